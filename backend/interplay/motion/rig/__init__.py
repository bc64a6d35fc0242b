"""The one rotation solver behind every export (BVH, GLB, JSON) and the studio's skinned
character: joints (T, 22, 3) → a `Rig` of rest offsets, root positions and local joint
rotations (unit quaternions w, x, y, z) that reproduce the joints by forward kinematics.
numpy only.

    base.py    the Rig, reading it from Motion JSON, FK, slerp, continuous quaternions
    solve.py   solve_rig: the bones' rotations (hinges, propagated twist)
    leaves.py  the head, wrists and toes: derived, or explicit (`leaves=`), kept off the floor
"""

from interplay.motion.rig.base import (
    Rig,
    continuous,
    global_rotations,
    rig_from_json,
    rig_positions,
    slerp,
)
from interplay.motion.rig.leaves import (
    HAND_BEND,
    HAND_LAG,
    HAND_REACH,
    HAND_THICK,
    HEAD_SHARE,
    LEAVES,
    end_sites,
)
from interplay.motion.rig.solve import solve_rig

__all__ = ["HAND_BEND", "HAND_LAG", "HAND_REACH", "HAND_THICK", "HEAD_SHARE", "LEAVES", "Rig",
           "continuous", "end_sites", "global_rotations", "rig_from_json", "rig_positions",
           "slerp", "solve_rig"]
