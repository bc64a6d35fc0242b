"""Training data of the evaluator: per-person feature tracks of the train split (and their
left/right mirror images), texts, and random windows of 2–10 s in padded batches.

Texts: a window is paired with its clip's prompt (made single-person, `person_prompt`) or with
the automatic body caption overlapping it most. A mirrored track gets mirrored texts ("left" ↔
"right"), so "kicks with the left foot" mirrors into "kicks with the right foot".
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from interplay.eval.testset import person_prompt
from interplay.motion import skeleton as sk
from interplay.motion.features import encode

# Joint index of each joint's mirror image (left_* ↔ right_*).
MIRROR_JOINTS = np.array([
    sk.JOINT_INDEX[n.replace("left_", "§").replace("right_", "left_").replace("§", "right_")]
    for n in sk.JOINT_NAMES])


def mirror_joints(joints: np.ndarray) -> np.ndarray:
    """(..., 22, 3) reflected through the YZ plane (x → -x) with left and right joints swapped."""
    out = np.array(joints[..., MIRROR_JOINTS, :], dtype=np.float64)
    out[..., 0] *= -1.0
    return out


def mirror_text(text: str) -> str:
    """Swap the words left and right (any case)."""
    swap = {"left": "right", "right": "left"}

    def sub(m: re.Match) -> str:
        w = m.group(0)
        r = swap[w.lower()]
        return r.capitalize() if w[0].isupper() else r
    return re.sub(r"\b(left|right)\b", sub, text, flags=re.IGNORECASE)


class TextTable:
    """Distinct strings with stable integer ids."""

    def __init__(self):
        self.texts: list[str] = []
        self.ids: dict[str, int] = {}

    def id(self, text: str) -> int:
        if text not in self.ids:
            self.ids[text] = len(self.texts)
            self.texts.append(text)
        return self.ids[text]


@dataclass(frozen=True, eq=False)
class Track:
    features: np.ndarray             # (T, 239) float32, not normalised
    prompt: int                      # text id of the prompt
    captions: np.ndarray             # (C, 3) int: start, end, text id of each body caption


def build_tracks(clips, table: TextTable, split: str = "train", mirror: bool = True) -> list[Track]:
    """One track per person of each clip in `split` (synthetic pairs left out), plus its mirror."""
    tracks = []
    for c in clips:
        if c.split != split or c.synthetic:
            continue
        prompt = person_prompt(c)
        for i, (joints, offsets) in enumerate(zip(c.people, c.offsets)):
            body = person_captions(c, i)
            variants = [(joints, offsets, lambda s: s)]
            if mirror:
                variants.append((mirror_joints(joints), mirror_joints(offsets[None])[0], mirror_text))
            for j, off, say in variants:
                caps = np.array([(a, b, table.id(say(t))) for a, b, t in body], dtype=np.int64)
                tracks.append(Track(encode(j, off), table.id(say(prompt)),
                                    caps.reshape(-1, 3)))
    if not tracks:
        raise ValueError(f"no {split!r} clips to train on")
    return tracks


def person_captions(clip, person: int) -> list[tuple[int, int, str]]:
    """(start, end, text) of the body captions of one person. Two-person clips caption each
    person as "person N: …" (N from 1); those prefixes are matched and stripped."""
    body = [cap for cap in clip.captions if cap.part == "body"]
    if len(clip.people) == 1:
        return [(c.start, c.end, c.text) for c in body]
    tag = f"person {person + 1}: "
    return [(c.start, c.end, c.text[len(tag):]) for c in body if c.text.startswith(tag)]


def window_text(track: Track, start: int, end: int, rng: np.random.Generator,
                prompt_share: float) -> int:
    """The prompt (with probability prompt_share, or when no caption overlaps) or the body
    caption overlapping [start, end) the most."""
    caps = track.captions
    if len(caps) and rng.random() >= prompt_share:
        overlap = np.minimum(caps[:, 1], end) - np.maximum(caps[:, 0], start)
        if overlap.max() > 0:
            return int(caps[int(np.argmax(overlap)), 2])
    return track.prompt


def sample_batch(tracks: list[Track], weights: np.ndarray, batch: int, min_frames: int,
                 max_frames: int, rng: np.random.Generator,
                 prompt_share: float) -> tuple[list[np.ndarray], np.ndarray]:
    """`batch` random windows (2–10 s, whole track if shorter) and their text ids (B,)."""
    picks = rng.choice(len(tracks), size=batch, p=weights)
    windows, texts = [], np.empty(batch, dtype=np.int64)
    for i, k in enumerate(picks):
        tr = tracks[k]
        t = len(tr.features)
        length = min(t, int(rng.integers(min_frames, max_frames + 1)))
        start = int(rng.integers(0, t - length + 1))
        windows.append(tr.features[start:start + length])
        texts[i] = window_text(tr, start, start + length, rng, prompt_share)
    return windows, texts


def pad(windows: list[np.ndarray], multiple: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Padded (B, T, F) float32 and mask (B, T) bool (True = real frame), T the longest
    window rounded up to a multiple of `multiple` (the encoder's patch)."""
    t = -(-max(len(w) for w in windows) // multiple) * multiple
    out = np.zeros((len(windows), t, windows[0].shape[1]), dtype=np.float32)
    mask = np.zeros((len(windows), t), dtype=bool)
    for i, w in enumerate(windows):
        out[i, :len(w)] = w
        mask[i, :len(w)] = True
    return out, mask


def track_weights(tracks: list[Track]) -> np.ndarray:
    """Sampling weight per track ∝ sqrt(frames): long salsa takes do not drown the many short
    HDM05 clips, nor do those drown them."""
    w = np.sqrt([len(t.features) for t in tracks])
    return w / w.sum()
