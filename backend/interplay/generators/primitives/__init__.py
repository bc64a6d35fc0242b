"""Motion primitives for what the captures lack, built per body part on a captured base
posture (issue 24): `postures` (standing, seated, kneeling, prone, supine, all fours, a walk,
all from real captured frames), builders (`contacts`, `legs`, `exercise`, `reach`, `gait`,
`head`), each a pure function (base joints (T, 22, 3), parameters) → joints (T, 22, 3) on the
base's bone lengths, and `registry` (a primitive found from its text by the MiniLM encoder).
"""
