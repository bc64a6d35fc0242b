"""eval-pair's penetration bounds (issue 15) on the eval-prompts suite's two-person test prompts:
the product default keeps every output within IF ≤ 0.10 (no contact asked) and 3 cm of
penetration (contact asked); one captured person standing inside a copy of itself breaks
both, so the table can fail."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.eval.pair import load_row
from interplay.eval.pair_bounds import bounds_check, format_bounds
from interplay.motion.clip import default_clips


@pytest.fixture(scope="module")
def clips():
    return default_clips()


def test_the_product_default_stays_within_the_bounds(clips):
    out = bounds_check({"default": load_row("default", clips)}, "test", seeds=1)
    assert out["prompts"]["contact"] > 0 and out["prompts"]["none"] > 0
    row = out["rows"]["default"]
    assert row["if"]["over"] == 0.0 and row["if"]["worst"] <= 0.10, row
    assert row["penetration_cm"]["over"] == 0.0 and row["penetration_cm"]["worst"] <= 3.0, row
    assert "default" in format_bounds(out)


def test_two_bodies_in_one_place_break_both_bounds(clips):
    walk = next(c for c in clips if c.split == "test" and len(c.people) == 1
                and "walk" in c.prompt)
    one = np.asarray(walk.people[0], np.float64)

    def inside(prompt: str, frames: int, seed: int) -> np.ndarray:
        idx = np.arange(frames) % len(one)
        return np.stack([one[idx], one[idx]])

    row = bounds_check({"inside": inside}, "test", seeds=1)["rows"]["inside"]
    assert row["if"]["over"] == 1.0 and row["penetration_cm"]["over"] == 1.0
