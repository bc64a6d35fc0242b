"""The scenes two people are composed into, one builder per kind (`generator.BUILDERS`): gestures
(a handshake, a high five, a wave, a bow, face to face), contacts (a hug, a push, a touch,
helping up, handing over), contests (sparring), partners (mirroring, together), travel (side by
side, following, walking up to each other, leading by the hand), a piggyback ride, and what
they do after (`after`: one walks away)."""
