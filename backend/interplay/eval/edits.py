"""Part-edit fidelity: generate a base motion, re-generate one body part from a part prompt, and
ask the automatic captioner whether the edit shows, and how far the rest of the body moved.

Per case and seed:
  confirmed     share of frames where `posecodes.caption_clip` gives the edited part exactly
                the edit prompt (its captions are the texts such edits are trained with)
  code_share    share of frames where the case's pose code (`posecodes.frame_codes`) holds in
                the edited motion; base_code_share the same in the base motion (before)
  untouched_cm  mean displacement (cm) between base and edited motion of the joints that belong
                to no edited part (skeleton.PART_JOINTS; the torso belongs to both upper
                parts, so an arm edit may move it)
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.posecodes import caption_clip, frame_codes


@dataclass(frozen=True)
class EditCase:
    base: str           # prompt of the base motion
    part: str           # CoMA part that is edited
    prompt: str         # the part's new prompt (a caption the captioner can give)
    code: str           # frame code that shows the edit

    @property
    def text(self) -> str:
        return f"{self.base} + {self.part}: {self.prompt}"


CASES = (
    EditCase("a person walks forward", "left_upper", "the left arm is raised above the head",
             "left_hand_above_head"),
    EditCase("a person walks forward", "right_upper", "the right arm is raised above the head",
             "right_hand_above_head"),
    EditCase("a person walks forward", "left_upper", "the left hand is near the face",
             "left_hand_near_face"),
    EditCase("a person squats down and stands back up", "right_upper",
             "the right arm is stretched out to the side", "right_arm_sideways"),
)
# Other bases, parts and prompts, for choosing edit settings on `interplay eval --split val`.
VAL_CASES = (
    EditCase("a person jogs", "right_upper", "the right arm is raised above the head",
             "right_hand_above_head"),
    EditCase("a person kicks", "left_upper", "the left arm is stretched out to the side",
             "left_arm_sideways"),
    EditCase("a person jumps", "right_upper", "the right hand is near the face",
             "right_hand_near_face"),
    EditCase("a person walks backwards", "left_upper", "the left arm is raised above the head",
             "left_hand_above_head"),
)
FRAMES = 120             # 6 s


def untouched_cm(base: np.ndarray, edited: np.ndarray, parts: list[str]) -> float:
    """Mean distance (cm) over frames and the joints in none of `parts`."""
    touched: set[int] = set()
    for p in parts:
        touched.update(int(j) for j in sk.PART_JOINTS[sk.resolve_part(p)])
    keep = [j for j in range(sk.NUM_JOINTS) if j not in touched]
    return float(np.linalg.norm(edited[:, keep] - base[:, keep], axis=-1).mean() * 100)


def confirmed_share(joints: np.ndarray, part: str, prompt: str) -> float:
    """Share of frames whose caption for `part` is exactly `prompt`."""
    hit = np.zeros(len(joints), dtype=bool)
    for cap in caption_clip(joints):
        if cap.part == part and cap.text == prompt:
            hit[cap.start:cap.end] = True
    return float(hit.mean())


def measure(case: EditCase, base: np.ndarray, edited: np.ndarray) -> dict:
    """The fidelity numbers of one edit."""
    if base.shape != edited.shape:
        raise ValueError(f"edited motion {edited.shape} differs in shape from the base {base.shape}")
    return {"confirmed": confirmed_share(edited, case.part, case.prompt),
            "code_share": float(frame_codes(edited)[case.code].mean()),
            "base_code_share": float(frame_codes(base)[case.code].mean()),
            "untouched_cm": untouched_cm(base, edited, [case.part])}


def edit_fidelity(generate, edit, seeds: int = 3, cases=CASES, frames: int = FRAMES) -> list[dict]:
    """Per case: the numbers averaged over `seeds` seeds (generate(text, frames, seed) and
    edit(joints, parts, prompt, seed, context) as in eval.rows; the context is the base
    prompt, which the parts left alone keep)."""
    out = []
    for k, case in enumerate(cases):
        runs = []
        for s in range(seeds):
            base = generate(case.base, frames, 7919 * k + s)
            edited = edit(base, [case.part], case.prompt, 7919 * k + s + 1, case.base)
            runs.append(measure(case, base, edited))
        out.append({**asdict(case), "seeds": seeds,
                    **{key: float(np.mean([r[key] for r in runs])) for key in runs[0]}})
    return out
