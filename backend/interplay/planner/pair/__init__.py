"""Two people: who acts in a clause (`actors`) and exchanges with an action per person and its timing (`roles`)."""
