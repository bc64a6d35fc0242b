"""Keeping a segment on the spot when its words ask for it ("hop on the spot", "march in
place", "jog on the spot", "without moving from the spot": `intent.in_place`, the words of the
catalogue's "on the spot" entry).

`verify.pick` prefers draws that stay within IN_PLACE_M, but the captures of many actions
travel in every draw (a captured hop goes 4–7 m in 6 s, a captured march walks on). When the
frames chosen for such a segment still go further than the bound, the horizontal drift of the
whole body is taken out:

1. the pelvis velocity on the floor, low-passed over LOW_PASS frames (a step's sway and a
   hop's bounce averaged out), is what the body drifts by each frame; summed from the
   segment's first frame (weighted by an ease that rises over EASE frames at the start and
   falls over EASE frames at the end) it is the drift path, subtracted from every joint, so
   the segment starts where it was and its neighbours join it with no jump in position or
   speed (`drift`);
2. planted feet would then slide backwards at the speed the body travelled: during each
   stance of the captured frames the foot is put back where it was at the stance's middle and
   moves from there as it did in the capture, by the legs' IK of `motion.footlock` (the
   trajectory editor's pinning, with no turn), the correction faded to nothing over
   FOOT_EDGE frames at the segment's ends;
3. the generator moves everything after the segment by the drift it removed (`stay`'s
   second result), so the next segment continues from where this one now ends.

A way of travelling asked on the spot ("marches in place") is drawn by its words without the
on-the-spot ones (`travelling`): with them the nearest captures are of other actions that
stay put (a kick, a dance); the march drawn is then kept on the spot as above.

    on_the_spot.asks(seg)            # the segment's words ask to stay on the spot
    frames, moved = stay(frames)     # (n, 22, 3) → (n, 22, 3), (3,) added to the frames after
"""

from __future__ import annotations

import numpy as np

from interplay.generators.plan import GenerationSegment
from interplay.generators.retrieval.intent import Intent, _entry, intent
from interplay.generators.retrieval.verify import IN_PLACE_M
from interplay.motion import skeleton as sk
from interplay.motion.checks.measures import frame_of
from interplay.motion.checks.named import CHECKS
from interplay.motion.footlock import apply_foot_corrections, foot_targets
from interplay.motion.signals import smooth

LOW_PASS = 20      # frames (1 s at 20 fps): two steps of a walk, two hops
EASE = 6           # frames over which the removal eases in and out at the segment's ends
FOOT_EDGE = 4      # frames over which the feet's correction fades at the segment's ends


def asks(seg: GenerationSegment) -> bool:
    """Do one person's segment words ask to stay on the spot?"""
    return intent(seg.prompt, seg.repeat, seg.travel).in_place


def travelling(text: str, it: Intent) -> str:
    """The text a way of travelling done on the spot is drawn by: without its on-the-spot
    words ("a person marches in place" → "a person marches"), which pull the text match
    towards captures of other actions that stay put (a kick, a dance). Other texts as they are."""
    if not it.in_place or it.action is not None or it.still or it.hold is not None:
        return text
    return " ".join(_entry("on the spot").sub(" ", text).split())


def travels(joints: np.ndarray, max_m: float = IN_PLACE_M) -> bool:
    """Does the pelvis go further than `max_m` from where it starts (the benchmark's
    stays_in_place measure, on frames (T, 22, 3))?"""
    return len(joints) >= 2 and not CHECKS["stays_in_place"].fn(frame_of(joints), max_m=max_m)[0]


def _ease(n: int) -> np.ndarray:
    """(n,) weights: 0 → 1 over EASE steps at the start, 1 → 0 over EASE at the end
    (smoothstep), 1 between; a segment shorter than 2·EASE never reaches 1."""
    i = np.arange(n)
    x = np.clip(np.minimum(i + 1, n - i) / (EASE + 1), 0.0, 1.0)
    return x * x * (3 - 2 * x)


def drift(joints: np.ndarray) -> np.ndarray:
    """The low-passed path (T, 2) (x, z) the pelvis travels, relative to the first frame
    (0 there), eased in and out at the ends (module doc, step 1)."""
    xz = joints[:, sk.PELVIS][:, [0, 2]].astype(np.float64)
    step = smooth(np.diff(xz, axis=0), LOW_PASS)            # (T-1, 2) m per frame
    step *= _ease(len(step))[:, None]
    return np.concatenate([np.zeros((1, 2)), np.cumsum(step, axis=0)])


def stay(joints: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(frames, moved): one person's segment frames (T, 22, 3) kept on the spot when they go
    further than IN_PLACE_M (else unchanged), and the shift (3,) (x, 0, z) that every later
    frame of the motion needs to continue from the new end."""
    if not travels(joints):
        return joints, np.zeros(3)
    d = drift(joints)
    out = joints.astype(np.float64).copy()
    out[..., [0, 2]] -= d[:, None]
    # feet planted in the capture stay planted where the body now is (module doc, step 2)
    corr = foot_targets(joints.astype(np.float64), out, np.zeros(len(out)))   # (T, 2, 3)
    t = np.arange(len(out))
    ramp = np.minimum(1.0, np.minimum(t, t[::-1]) / FOOT_EDGE)
    out = apply_foot_corrections(out, corr * ramp[:, None, None])
    return out.astype(joints.dtype), np.array([-d[-1, 0], 0.0, -d[-1, 1]])
