"""The product's finishing pass on a generated two-person stretch (CODA's output), shared by the
studio (`coda_generator`) and `interplay eval-pair`'s `coda` row:

1. feet: each person's planted feet are held where they are at the middle of each stance
   (`footlock.lock_feet`, as SPAM's output; the decoder's joints slide 0.2–1 m/s), the
   correction fading out at the stretch's edges so consecutive stretches still meet;
2. contact: when the prompt asks for a touch, `contact_refine` makes it. It runs after the
   feet so that the hands end exactly where it puts them (holding the feet may move a body by
   a few cm, which would carry a hand off its contact).

Shapes: pair (2, T, 22, 3) metres, world frame.
"""

from __future__ import annotations

import numpy as np

from interplay.generators.coda.contact_kinds import contact_kind
from interplay.generators.coda.contact_refine import refine_contact
from interplay.motion.footlock import lock_feet


def hold_feet(pair: np.ndarray) -> np.ndarray:
    """(2, T, 22, 3) with each person's planted feet held (T ≥ 3; shorter stretches as given)."""
    pair = np.asarray(pair, np.float64)
    if pair.shape[1] < 3:
        return pair.copy()
    return np.stack([lock_feet(p) for p in pair])


def finish_pair(pair: np.ndarray, prompt: str, free_start: bool = True, free_end: bool = True
                ) -> tuple[np.ndarray, dict | None]:
    """(pair, contact report or None when the prompt asks for no touch); see the module doc."""
    held = hold_feet(pair)
    kind = contact_kind(prompt)
    if kind is None:
        return held, None
    a, b, report = refine_contact(held[0], held[1], kind, free_start, free_end)
    return np.stack([a, b]), report
