"""The head as an editable part (generators/primitives/head.py, edit.py): "look up" raises the
head's pitch ≥ 25° over the base on the edited frames while every other joint stays (≤ 2 cm;
in fact exactly), nods and shakes counted exactly, and the words found by the encoder."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.generators.primitives.edit import head_edit
from interplay.generators.primitives.head import head, pitch_yaw
from interplay.generators.primitives.postures import posture
from interplay.motion import skeleton as sk
from interplay.motion.signals import runs
from interplay.text.encoder import get_encoder

OTHERS = [j for j in range(sk.NUM_JOINTS) if j != sk.HEAD]


@pytest.fixture(scope="module")
def bases():
    return {n: posture(n, 5.0) for n in ("standing", "walk", "seated")}


@pytest.mark.parametrize("name", ["standing", "walk", "seated"])
def test_look_up_raises_the_head_only(bases, name):
    base = bases[name]
    out = head(base, "look_up", start=20, end=80)
    p0, _ = pitch_yaw(base)
    p1, _ = pitch_yaw(out)
    held = slice(30, 70)                                   # past the ease in / out
    assert (p1 - p0)[held].min() >= 25.0
    assert np.linalg.norm(out[:, OTHERS] - base[:, OTHERS], axis=-1).max() <= 0.02
    assert np.array_equal(out[:20], base[:20]) and np.array_equal(out[80:], base[80:])
    assert np.allclose(sk.bone_lengths(out), sk.bone_lengths(base))


def test_look_down_left_right(bases):
    base = bases["standing"]
    p0, y0 = pitch_yaw(base)
    down = pitch_yaw(head(base, "look_down"))[0] - p0
    left = pitch_yaw(head(base, "look_left"))[1] - y0
    right = pitch_yaw(head(base, "look_right"))[1] - y0
    assert down[50] <= -25 and left[50] >= 40 and right[50] <= -40


@pytest.mark.parametrize("n", [1, 2, 4])
def test_nods_and_shakes_are_counted(bases, n):
    base = bases["walk"]
    p0, y0 = pitch_yaw(base)
    nod = pitch_yaw(head(base, "nod", count=n))[0] - p0
    assert len(runs(nod < -12)) == n and nod.max() < 3
    shake = pitch_yaw(head(base, "shake", count=n))[1] - y0
    assert len(runs(shake > 15)) == n and len(runs(shake < -15)) == n


@pytest.mark.parametrize("words,primitive,count", [
    ("look up", "look_up", None), ("nod twice", "nod", 2), ("shake your head", "shake_head", 1),
    ("look left", "look_left", None), ("look right", "look_right", None),
    ("nod three times", "nod", 3), ("lower your head", "look_down", None)])
def test_head_edit_from_words(bases, words, primitive, count):
    base = bases["walk"]
    out, entry = head_edit(base, words, (10, 90), get_encoder())
    assert entry["primitive"] == primitive and entry["part"] == "head"
    assert entry.get("count") == count
    assert entry["untouched_change_cm"] == 0.0
    assert np.array_equal(out[:, OTHERS], base[:, OTHERS])
    if primitive == "nod":
        p = pitch_yaw(out)[0] - pitch_yaw(base)[0]
        assert len(runs(p < -12)) == count


def test_head_edit_refuses_other_parts_words(bases):
    with pytest.raises(ValueError, match="head"):
        head_edit(bases["standing"], "kick with the right leg", None, get_encoder())


def test_look_at_the_partner_turns_towards_them(bases):
    from interplay.generators.primitives.registry import PRIMITIVES, build
    base = bases["standing"]
    for sign in (1.0, -1.0):                      # a partner ahead on the left, then the right
        partner = base.copy()
        partner[..., 0] += sign * 1.5
        partner[..., 2] += 1.5
        out = build(PRIMITIVES["look_at_partner"], {"partner": partner}, base=base)
        moved = out[:, sk.HEAD, 0] - base[:, sk.HEAD, 0]          # +X is the person's left
        assert sign * moved[20:80].min() > 0.02
        assert np.array_equal(out[:, OTHERS], base[:, OTHERS])
