"""The reaction stage: an ARFlow reactor generated frame by frame for a given actor, with penetration guidance."""
