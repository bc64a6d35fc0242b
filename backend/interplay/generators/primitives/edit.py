"""A user's edit of the head ("look up", "nod twice", "shake your head", "look left") made by
the `head` primitive over the edited frames of a stored motion, the way arm-pose edits are
made by IK (`retrieve_edit/part_edit.py`): the head primitive is found from the words by the
text encoder (`registry.find` over the head's primitives), its count from them
(`retrieval.intent.count_of`), a side named in them decides left from right
(`retrieve_edit.actions.side_of`), an angle written in degrees is used as said; every joint
but the head stays exactly where it was. The entry carries, under "leaves", the export's head
rotations (`head_leaf`): the head turns on the neck by the primitive's own angles.

    head_edit(joints, "nod twice", (20, 80), encoder) → (joints, plan entry)
"""

from __future__ import annotations

import numpy as np

from interplay.catalogue.grammar import DEGREES
from interplay.generators.primitives.body import axes
from interplay.generators.primitives.head import head_angles, head_turns, pitch_yaw
from interplay.generators.primitives.registry import PARTNER_AHEAD_M, PRIMITIVES, build, find
from interplay.generators.retrieval.intent import count_of
from interplay.generators.retrieve_edit.actions import side_of
from interplay.motion import skeleton as sk
from interplay.motion.rig import global_rotations, solve_rig
from interplay.motion.rotations import matrix_to_quat, quat_to_matrix
from interplay.text.encoder import Encoder

HEAD_PRIMITIVES = tuple(n for n, p in PRIMITIVES.items() if p.parts == ("head",))
MIN_SIMILARITY = 0.25      # below this the words are not about the head at all …
MARGIN = 0.05              # … nor when another part's primitive fits them this much better


def head_edit(joints: np.ndarray, prompt: str, frames: tuple[int, int] | None,
              encoder: Encoder) -> tuple[np.ndarray, dict]:
    """(edited joints (T, 22, 3), plan entry); ValueError when the words ask nothing of the
    head."""
    j = np.asarray(joints, dtype=np.float64)
    a, b = frames or (0, len(j))
    prim, sim = find(prompt, encoder, HEAD_PRIMITIVES)
    other, other_sim = find(prompt, encoder)
    if sim < MIN_SIMILARITY or other.name not in HEAD_PRIMITIVES and other_sim > sim + MARGIN:
        raise ValueError(f"{prompt!r} does not say what the head does (look up / down / left / "
                         "right, nod, shake)")
    side = side_of(prompt)
    if prim.name in ("look_left", "look_right") and side:
        prim = PRIMITIVES[f"look_{side}"]
    params: dict = {}
    count = count_of(prompt) if prim.counts else None
    if prim.counts:
        params["count"] = count or 1
    deg = DEGREES.search(prompt.lower())
    if deg:
        params["degrees"] = float(deg.group(1))
    sub = build(prim, params, base=j[a:b])
    out = j.copy()
    out[a:b] = sub
    moved = np.linalg.norm(out - j, axis=-1)
    others = np.ones(sk.NUM_JOINTS, bool)
    others[sk.HEAD] = False
    p0, y0 = pitch_yaw(j[a:b])
    p1, y1 = pitch_yaw(out[a:b])
    entry = {"generator": "primitive", "primitive": prim.name, "part": "head",
             "prompt": prompt.strip(), "frames": [int(a), int(b)],
             "similarity": round(sim, 4), **params,
             "pitch_change_deg": [round(float((p1 - p0).min()), 1), round(float((p1 - p0).max()), 1)],
             "untouched_change_cm": round(float(moved[:, others].max() * 100), 3),
             "edited_change_cm": round(float(moved[a:b, sk.HEAD].mean() * 100), 3)}
    action = prim.params["action"]
    point = j[a:b, sk.NECK] + PARTNER_AHEAD_M * axes(j[a:b])[2] if action == "look_at" else None
    pitch, yaw = head_angles(j[a:b], action, int(params.get("count", 1)), params.get("degrees"), point)
    entry["leaves"] = {"head": head_leaf(j, out, (a, b), pitch, yaw)}
    return out, entry


def head_leaf(base: np.ndarray, edited: np.ndarray, frames: tuple[int, int], pitch: np.ndarray,
              yaw: np.ndarray) -> np.ndarray:
    """The head's local rotations (T, 4), w x y z, for `rig.solve_rig(edited, leaves=…)`: on the
    edited frames the base's own head rotation turned on the neck by the primitive's turns
    (`head.head_turns` of pitch, yaw (b - a,) degrees, in the edited neck's frame), so the
    head channel turns by the primitive's angles (on top of the neck bone's own swing); the
    derived rotation elsewhere, so the frames around the edit export as before."""
    a, b = frames
    rig_base, rig_edit = solve_rig(base), solve_rig(edited)
    neck = global_rotations(rig_edit)[a:b, sk.NECK]
    turn = np.swapaxes(neck, -1, -2) @ head_turns(base[a:b], pitch, yaw) @ neck
    local = quat_to_matrix(rig_edit.rotations[:, sk.HEAD])
    local[a:b] = turn @ quat_to_matrix(rig_base.rotations[a:b, sk.HEAD])
    return matrix_to_quat(local)
