"""Re-running one planned segment of a stored motion with a new seed, in place: the shared step
of `POST /api/motions/{id}/segments/{index}/rerun`.

The segment's prompt is generated again (the generator's own plan for it: SPAM, CODA or
retrieval, as for a job) at the segment's length, then spliced into the stored motion:

1. moved as one rigid ground-plane move (yaw about Y + XZ shift, the same for both people)
   so that its first frame stands where the old segment's first frame stood;
2. bent, one rigid move per frame growing linearly to the end, so that its last frame stands
   where the old segment's last frame stood (the next segment, kept, continues from there);
3. cross-faded over `FADE` frames at each border that has a neighbour, from the old segment's
   own frames there (pelvis path and root-relative pose blended separately);
4. re-posed by IK → FK on the person's own bones (`kinematics.fit_to_skeleton`).

Every frame outside the segment is the stored float32 value, bit for bit; the length stays.

Errors: ValueError for a bad request (no such segment, a motion without segments; 422), the
generator's own exceptions otherwise (503)."""

from __future__ import annotations

import numpy as np

from interplay.generators.base import Generator, Request
from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_angle, fit_offsets, fit_to_skeleton
from interplay.motion.metrics import clip_metrics
from interplay.motion.rotations import yaw_matrix
from interplay.pipeline.highlights import highlight_lists
from interplay.pipeline.motion_json import plain
from interplay.store import MotionRepository, StoredMotion

FADE = 8          # frames cross-faded at each border (0.4 s), at most a quarter of the segment
MIN_FRAMES = 4    # a shorter segment is not worth re-running (and too short to blend)


def segment_span(plan: dict | None, index: int, frames: int) -> tuple[int, int, str]:
    """(start, end, prompt) of plan segment `index` of a motion of `frames` frames."""
    segments = (plan or {}).get("segments") or []
    if not segments:
        raise ValueError("this motion has no planned segments to re-run")
    if not 0 <= index < len(segments):
        raise ValueError(f"segment {index} does not exist: this motion has {len(segments)} "
                         f"segment(s), numbered from 0")
    seg = segments[index]
    a, b = int(seg.get("start", 0)), min(int(seg.get("end", 0)), frames)
    prompt = str(seg.get("prompt") or seg.get("base") or (plan or {}).get("prompt") or "")
    if b - a < MIN_FRAMES:
        raise ValueError(f"segment {index} covers frames {a}–{b} of this motion's {frames}: "
                         f"too short to re-run")
    if not prompt.strip():
        raise ValueError(f"segment {index} has no prompt to re-run")
    return a, b, prompt


def _ground(v: np.ndarray) -> np.ndarray:
    return np.asarray(v, dtype=np.float64) * np.array([1.0, 0.0, 1.0])


def _turn(src: np.ndarray, dst: np.ndarray) -> float:
    """The yaw (radians, wrapped to ±π) that turns pose src (22, 3) to face as dst does."""
    d = float(facing_angle(dst[None])[0] - facing_angle(src[None])[0])
    return (d + np.pi) % (2 * np.pi) - np.pi


def _moved(joints: np.ndarray, yaw: np.ndarray, pivot: np.ndarray, shift: np.ndarray
           ) -> np.ndarray:
    """Joints (n, 22, 3) turned per frame by yaw (n,) about the vertical through pivot, then
    shifted per frame by shift (n, 3) on the ground."""
    rot = yaw_matrix(yaw)                                             # (n, 3, 3)
    return np.einsum("tij,tkj->tki", rot, joints - pivot) + pivot + shift[:, None, :]


def _blend(frm: np.ndarray, to: np.ndarray, w: np.ndarray) -> np.ndarray:
    """(1 − w)·frm + w·to per frame (w (n,)), the pelvis path and the pose about it apart."""
    w = w[:, None, None]
    root = (1 - w) * frm[:, sk.PELVIS:sk.PELVIS + 1] + w * to[:, sk.PELVIS:sk.PELVIS + 1]
    rel = (1 - w) * (frm - frm[:, sk.PELVIS:sk.PELVIS + 1]) \
        + w * (to - to[:, sk.PELVIS:sk.PELVIS + 1])
    return root + rel


def splice_segment(old: list[np.ndarray], new: list[np.ndarray], a: int, b: int,
                   fade: int = FADE) -> list[np.ndarray]:
    """`old` (one (T, 22, 3) array per person) with frames [a, b) replaced by `new` (one
    (b − a, 22, 3) array per person), placed, bent and blended as the module says. Returns
    float32 arrays; frames outside [a, b) are old's values exactly."""
    n = b - a
    olds = [np.asarray(o, dtype=np.float64) for o in old]
    news = [np.asarray(x, dtype=np.float64)[:n] for x in new]
    if any(len(x) != n for x in news) or len(news) != len(olds):
        raise ValueError(f"the new segment has shapes {[x.shape for x in news]}, expected "
                         f"{len(olds)} × ({n}, 22, 3)")
    total = len(olds[0])
    ref_old, ref_new = olds[0], news[0]           # person 0 places both (one world frame)
    ones = np.ones(n)
    # 1. start where the old segment started
    yaw0 = _turn(ref_new[0], ref_old[a])
    pivot0 = _ground(ref_new[0, sk.PELVIS])
    shift0 = _ground(ref_old[a, sk.PELVIS]) - pivot0
    news = [_moved(x, yaw0 * ones, pivot0, np.tile(shift0, (n, 1))) for x in news]
    # 2. end where the old segment ended (when a kept segment follows), growing linearly
    if b < total and n > 1:
        share = np.arange(n) / (n - 1)
        ref = news[0]
        yaw1 = _turn(ref[-1], ref_old[b - 1])
        pivot1 = _ground(ref[-1, sk.PELVIS])
        shift1 = _ground(ref_old[b - 1, sk.PELVIS]) - pivot1
        news = [_moved(x, share * yaw1, pivot1, share[:, None] * shift1) for x in news]
    # 3. cross-fade from / into the old segment's own frames at the borders
    k = max(1, min(fade, n // 4))
    ramp = np.arange(1, k + 1) / (k + 1)
    up = ramp * ramp * (3 - 2 * ramp)                                  # smoothstep
    out: list[np.ndarray] = []
    for o, x in zip(olds, news):
        x = x.copy()
        if a > 0:
            x[:k] = _blend(o[a:a + k], x[:k], up)
        if b < total:
            x[n - k:] = _blend(x[n - k:], o[b - k:b], up)
        # 4. the person's own bones
        fitted, _ = fit_to_skeleton(x, fit_offsets(o))
        person = np.asarray(old[len(out)], dtype=np.float32).copy()
        person[a:b] = fitted.astype(np.float32)
        out.append(person)
    return out


def generate_segment(generator: Generator, prompt: str, persons: int, frames: int,
                     seed: int) -> tuple[list[np.ndarray], dict]:
    """`frames` frames per person of `prompt` by the generator (its plan, then its stream),
    and the plan's JSON; a stream that ends early is held on its last frame."""
    req = Request(prompt=prompt, persons=persons, seconds=frames / sk.FPS, seed=seed)
    plan = generator.plan(req)
    chunks: list[list[np.ndarray]] = [[] for _ in range(persons)]
    got = 0
    for _, people in generator.stream(req, plan):
        for p in range(persons):
            chunks[p].append(np.asarray(people[p], dtype=np.float64))
        got += len(people[0])
        if got >= frames:
            break
    if got == 0:
        raise RuntimeError("the generator produced no frames for the segment")
    out: list[np.ndarray] = []
    for p in range(persons):
        x = np.concatenate(chunks[p])[:frames]
        if len(x) < frames:
            x = np.concatenate([x, np.repeat(x[-1:], frames - len(x), axis=0)])
        out.append(x)
    return out, plan.to_json()


def rerun_stored(repo: MotionRepository, generator: Generator, parent: StoredMotion,
                 index: int, seed: int, client_id: str | None = None,
                 id: str | None = None) -> StoredMotion:
    """Re-run segment `index` of `parent` with `seed` and store the result as a new version
    (parent_id = parent). Its plan is the parent's with `{"kind": "rerun_segment", …}`
    appended to `edits`; its review the parent's without that segment (whose rounds no longer
    apply); `edit` says {mode: "rerun", segment, prompt, frames, seed}."""
    a, b, prompt = segment_span(parent.plan, index, parent.frames)
    new, seg_plan = generate_segment(generator, prompt, parent.persons, b - a, seed)
    people = splice_segment(parent.people, new, a, b)
    entry = {"kind": "rerun_segment", "segment": index, "prompt": prompt, "frames": [a, b],
             "seed": seed, "generator": seg_plan.get("generator"),
             "generator_reason": seg_plan.get("generator_reason"),
             "fade": max(1, min(FADE, (b - a) // 4))}
    plan = dict(parent.plan or {})
    plan["edits"] = list(plan.get("edits") or []) + [entry]
    review = parent.review
    if isinstance(review, dict) and isinstance(review.get("segments"), list):
        review = {**review, "segments": [s for s in review["segments"]
                                         if not (isinstance(s, dict) and s.get("segment") == index)]}
    metrics = plain(clip_metrics([p.astype(np.float64) for p in people]))
    highlights = highlight_lists(people, 0, len(people))
    edit = {"mode": "rerun", "segment": index, "part": None, "prompt": prompt,
            "frames": [a, b], "trajectory": None, "seed": seed}
    return repo.create(id=id, prompt=parent.prompt, people=people, seconds=parent.seconds, seed=seed,
                       plan=plain(plan), metrics=metrics, highlights=highlights,
                       parent_id=parent.id, review=plain(review), edit=plain(edit),
                       client_id=client_id)
