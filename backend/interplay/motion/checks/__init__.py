"""Checks of what a motion does, computed from the joints alone (never from a plan):
`measures` holds the per-frame quantities and events they are built on (flights, pelvis dips,
travel relative to facing, hand points, ground clearance …), `named` the named pass/fail
checks, the plausibility checks every output gets, and the registry (`CHECKS`) a prompt suite
names them by; `everyday` (hands meeting, at the face, pumping; lying face down / up; sit-ups;
an uneven gait), `heads` (nods, shakes, a part edit against its base) and `contact` (a hand on
the partner, hands meeting, moving apart, carried) hold the fresh split's checks, which
`named` registers. numpy only; `interplay eval-prompts` runs them on every generator's output.
"""
