"""CODA at run time: two-person masked token generation, contact refinement and the finishing pass."""
