"""SPAM's edits (CoMA §4.2.3) on an existing motion: body part, in-between, blend. Each encodes
the input to its own tokens, re-masks some of them, lets the runtime decode them again, and
splices the result into the input (`motion_splice`) so that what was not edited stays put.

Called through `SpamRuntime.edit / edit_parts / inbetween / blend`."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.generators.spam.splice import (
    compose,
    edited_joints,
    joint_weights,
    ramp_move,
    seam_corrected,
    time_weights,
    yaw_between,
)
from interplay.motion import features as F
from interplay.motion import skeleton as sk
from interplay.motion.kinematics import fit_offsets
from interplay.motion.rotations import yaw_matrix

PARTS = sk.PART_NAMES
BLEND_CONTEXT = 10       # tokens of each neighbour a transition sees (2 s)
MIN_EDIT_STEPS = 4       # masked-decoding steps of an edit at least (see `edit`)
# How a part edit decodes (see `edit`). "regenerate" is the default because on validation edit
# cases (other bases and parts than `interplay eval`'s) the captioner confirmed the edited part
# in 36% of frames against 0–3% for "inpaint" (docs/eval.md): the shipped transformers follow
# a part prompt when the whole body is conditioned on it, but keep the part in step with the
# other parts' tokens when those stay (spatial attention outweighs the part's text).
EDIT_MODES = ("regenerate", "inpaint")
DEFAULT_EDIT_MODE = "regenerate"
# A regenerated window decodes in 4 masked-decoding steps (validation: confirmed share 33%
# with 5 steps vs 36% with 10; on 10 seeds of the four validation cases 0.50 with 4 steps vs
# 0.42 with 5, docs/eval.md) and keeps the guidance scale generation had before it moved to
# 2.5 (edits measured 33% at 2.5, 36% at 4 and 6).
REGENERATE_STEPS = 4
REGENERATE_CFG = 4.0
# ... and its residual layers decode without guidance (the conditional pass alone): on the
# validation edit cases the captioner confirmed the edited part more often than with
# generation's residual scale 5 (0.33/0.33/0.00/0.89 → 0.44/0.56/0.00/1.00, 3 seeds each,
# `interplay eval --split val --rows spam --sampling cfg_residual=1`), and a residual layer
# then costs one transformer pass instead of two (docs/bench.md).
REGENERATE_CFG_RESIDUAL = 1.0


@dataclass(frozen=True)
class Edit:
    """An edit's result: joints (T, 22, 3) plus what changed and by how much."""
    joints: np.ndarray
    parts: tuple[str, ...]
    frames: tuple[int, int]
    masked_tokens: int            # base tokens re-masked (edited parts + random context ones)
    steps: int                    # masked-decoding steps used
    untouched_change_cm: float    # mean displacement (cm) of the joint-frames left alone
    untouched_pose_change_cm: float  # the same in each frame's body frame (pelvis at the
                                     # origin, hips facing +Z): the pose, not where it went
    model_untouched_change_cm: float  # the same for the model's own decode, against its decode
                                      # of the unedited codes (what splicing takes away)


def untouched_change_cm(a: np.ndarray, b: np.ndarray, parts: list[str],
                        frames: tuple[int, int] | None = None) -> float:
    """Mean distance (cm) between a and b (T, 22, 3) over the joint-frames an edit of `parts`
    over `frames` [lo, hi) leaves alone: the joints of the unedited parts (`edited_joints`),
    and every joint outside the frames (0 when nothing is left alone)."""
    lo, hi = frames or (0, len(a))
    edited = np.zeros((len(a), sk.NUM_JOINTS), bool)
    edited[lo:hi] = edited_joints(parts)
    if edited.all():
        return 0.0
    return float(np.linalg.norm(a - b, axis=-1)[~edited].mean() * 100)


def body_frame(joints: np.ndarray) -> np.ndarray:
    """Joints (T, 22, 3) relative to each frame's pelvis, turned so the hips face +Z (hips
    only: the shoulders may belong to an edited part)."""
    across = joints[:, sk.LEFT_HIP] - joints[:, sk.RIGHT_HIP]          # towards the left, +X
    yaw = np.arctan2(-across[:, 2], across[:, 0])                      # forward = across × up
    back = np.swapaxes(yaw_matrix(yaw), -1, -2)
    return np.einsum("tij,tkj->tki", back, joints - joints[:, sk.PELVIS:sk.PELVIS + 1])


def edit(rt, joints: np.ndarray, parts: list[str] | None, prompt: str, seed: int,
         frames: tuple[int, int] | None = None, context: str | None = None,
         keep_noise: float = 0.1, mode: str = DEFAULT_EDIT_MODE, **sampling) -> Edit:
    """Re-generate `parts` (default: the whole body) over `frames` [a, b) (default: all) from
    `prompt`. mode "inpaint" (CoMA 4.2.3): the other parts keep `context` (the motion's own
    prompt; default the edit prompt) and a `keep_noise` share of their tokens is re-masked at
    random, so they can meet the edited ones. mode "regenerate": every token of the window is
    re-masked and every part conditioned on `prompt` (context and keep_noise unused); the
    splice below still keeps the unedited parts' joints, so only the edited parts change. Only the edited parts' residual tokens (and those under a changed
    base token) are predicted again. Decoding takes the configured steps scaled by the share of
    the edited window's tokens that are masked (≥ MIN_EDIT_STEPS): a one-part edit masks about
    a third of them, so ~4 steps commit as many tokens per step as generation's 10 do.
    The output keeps the input's bone lengths, the joints of
    the unedited parts, every frame outside [a, b), and the root path unless a lower part is
    edited (then the new path is bent back onto the input's at b)."""
    joints = np.asarray(joints, dtype=np.float64)
    if joints.ndim != 3 or joints.shape[1:] != (sk.NUM_JOINTS, 3) or len(joints) < 2:
        raise ValueError(f"joints must be (T ≥ 2, 22, 3), got {joints.shape}")
    t = len(joints)
    parts = list(PARTS) if not parts else list(dict.fromkeys(sk.resolve_part(p) for p in parts))
    lo, hi = (0, t) if frames is None else (int(frames[0]), int(frames[1]))
    if not 0 <= lo < hi <= t:
        raise ValueError(f"frames {lo}:{hi} are not a range inside 0:{t}")
    if not 0 <= keep_noise <= 1:
        raise ValueError(f"keep_noise must be in [0, 1], got {keep_noise}")
    if mode not in EDIT_MODES:
        raise ValueError(f"edit mode must be one of {EDIT_MODES}, got {mode!r}")
    if mode == "regenerate":
        keep_noise, context = 1.0, None
        if sampling.get("steps") is None:
            sampling["steps"] = min(REGENERATE_STEPS, rt.config.steps)
        if sampling.get("cfg") is None:
            sampling["cfg"] = REGENERATE_CFG
        if sampling.get("cfg_residual") is None:
            sampling["cfg_residual"] = REGENERATE_CFG_RESIDUAL
    rng = np.random.default_rng(seed)
    offsets = fit_offsets(joints)
    feats = F.encode(joints, offsets)
    codes = rt.encode_codes(feats)
    ds = rt.config.downsample
    rows = np.array([p in parts for p in PARTS])
    cols = np.zeros(codes.shape[-1], bool)
    cols[lo // ds:-(-hi // ds)] = True
    force = rows[:, None] & cols[None, :]
    editable = force | ((~rows[:, None]) & cols[None, :] & (rng.random(force.shape) < keep_noise))
    if sampling.get("steps") is None:
        share = editable.sum() / max(1, editable[:, cols].size)
        sampling["steps"] = max(MIN_EDIT_STEPS, int(np.ceil(rt.config.steps * share)))
    texts = {p: prompt for p in parts}
    texts["global"] = context or prompt
    new = rt.fill(codes, editable, rt.text_embedding(texts), rng, force=force, **sampling)
    new_feats = rt.decode_codes(new)[:t]
    tw = time_weights(t, lo, hi)
    lower = any(p.endswith("_lower") for p in parts)
    composed = compose(feats, new_feats, joint_weights(parts, tw), tw if lower else 0 * tw)
    start = F.start_of(joints)
    out = F.decode(composed, offsets, start)
    if lower and hi < t:   # bend the new root path back onto the input's after the edit
        out = ramp_move(out, lo, hi, *yaw_between(out[hi], joints[hi]))
    keep = np.ones(t, bool)
    keep[lo:hi] = False
    out[keep] = joints[keep]
    model_only = F.decode(new_feats, offsets, start)
    recon = F.decode(rt.decode_codes(codes)[:t], offsets, start)
    return Edit(joints=out, parts=tuple(parts), frames=(lo, hi), masked_tokens=int(editable.sum()),
                steps=int(sampling["steps"]),
                untouched_change_cm=untouched_change_cm(out, joints, parts, (lo, hi)),
                untouched_pose_change_cm=untouched_change_cm(body_frame(out), body_frame(joints),
                                                             parts, (lo, hi)),
                model_untouched_change_cm=untouched_change_cm(model_only, recon, parts, (lo, hi)))


def blend(rt, a_joints: np.ndarray, b_joints: np.ndarray, transition_frames: int, prompt: str,
          seed: int, **sampling) -> np.ndarray:
    """a, then `transition_frames` new frames (a multiple of 4) decoded from the end of a and
    the start of b (MMM/CoMA), then b: (len a + transition + len b, 22, 3). a is kept as is;
    b's poses are kept and its path continues from the transition (moved on the ground); all
    on a's bone lengths."""
    ds, max_tokens = rt.config.downsample, rt.config.max_tokens
    if transition_frames < ds or transition_frames % ds:
        raise ValueError(f"transition_frames must be a positive multiple of {ds}, "
                         f"got {transition_frames}")
    tokens = transition_frames // ds
    if tokens > max_tokens - 2:
        raise ValueError(f"a transition is at most {(max_tokens - 2) * ds} frames")
    a, b = (np.asarray(x, dtype=np.float64) for x in (a_joints, b_joints))
    offsets = fit_offsets(a)
    fa, fb = F.encode(a, offsets), F.encode(b, fit_offsets(b))
    ctx = min(BLEND_CONTEXT, (max_tokens - tokens) // 2) * ds
    # Context windows aligned to a's end and b's start (short motions: edge frames repeat).
    tail = fa[-ctx:] if len(fa) >= ctx else np.concatenate([np.repeat(fa[:1], ctx - len(fa), 0), fa])
    head = fb[:ctx] if len(fb) >= ctx else np.concatenate([fb, np.repeat(fb[-1:], ctx - len(fb), 0)])
    window, ca = transition_codes(rt, rt.encode_codes(tail), rt.encode_codes(head), tokens,
                                  prompt, np.random.default_rng(seed), **sampling)
    w = rt.decode_codes(window)
    lo, hi = ca * ds, ca * ds + transition_frames
    mid = seam_corrected(w[lo:hi], fa[-1] - w[lo - 1], fb[0] - w[hi])
    out = F.decode(np.concatenate([fa, mid, fb]), offsets, F.start_of(a))
    out[:len(a)] = a
    return out


def transition_codes(rt, left: np.ndarray, right: np.ndarray, tokens: int, texts,
                     rng: np.random.Generator, **sampling) -> tuple[np.ndarray, int]:
    """(codes (4, Q, ca + tokens + cb), ca): the last ca tokens of `left` (4, Q, ·), `tokens`
    new ones decoded from both sides, the first cb tokens of `right`."""
    room = max(0, (rt.config.max_tokens - tokens) // 2)
    ca, cb = min(left.shape[-1], BLEND_CONTEXT, room), min(right.shape[-1], BLEND_CONTEXT, room)
    window = np.concatenate([left[..., left.shape[-1] - ca:],
                             np.zeros((len(PARTS), rt.config.Q, tokens), np.int64),
                             right[..., :cb]], -1)
    editable = np.zeros((len(PARTS), window.shape[-1]), bool)
    editable[:, ca:ca + tokens] = True
    return rt.fill(window, editable, rt.text_embedding(texts), rng, **sampling), ca
