"""Two-person interactions composed from real single-person clips (issue 15): `generator`
(InteractionGenerator, the "compose" generator), `kinds` (prompt → interaction), `timing`,
`library` (the clips), `moves` (standing, walking, stepping), `contacts` (touches by IK),
`scene` and the scenes: `touches`, `gestures`, `travel`."""
