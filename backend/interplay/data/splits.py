"""What the main build and the staged build share: the split by trial (stable hash per family)
and the automatic part captions."""

from __future__ import annotations

import hashlib

from interplay.motion.clip import Caption, Clip

SPLIT_SHARES = {"test": 0.15, "val": 0.10}


def _stable_rank(key: str) -> str:
    return hashlib.sha1(key.encode()).hexdigest()


def stratified_split(ids_by_family: dict[str, list[str]], min_test: int = 1) -> dict[str, str]:
    """Trial id → split. Within each family, trials are ordered by a stable hash; the first
    15% (at least one when the family has ≥ 3 trials) go to test, the next 10% to val."""
    out = {}
    for ids in ids_by_family.values():
        ranked = sorted(ids, key=_stable_rank)
        n = len(ranked)
        n_test = max(min_test if n >= 3 else 0, round(n * SPLIT_SHARES["test"]))
        n_val = max(1 if n >= 6 else 0, round(n * SPLIT_SHARES["val"]))
        for i, trial in enumerate(ranked):
            out[trial] = "test" if i < n_test else "val" if i < n_test + n_val else "train"
    return out


def add_captions(clips: list[Clip]) -> None:
    from interplay.motion.posecodes import caption_clip

    for c in clips:
        caps: list[Caption] = []
        for person, joints in enumerate(c.people):
            for cap in caption_clip(joints):
                if len(c.people) > 1:
                    cap = Caption(cap.start, cap.end, cap.part, f"person {person + 1}: {cap.text}")
                caps.append(cap)
        c.captions = caps


__all__ = ["SPLIT_SHARES", "add_captions", "stratified_split"]
