"""Contact refinement (`agents.contact_refine`) on CODA's own samples of the committed weights:
the kind from the prompt, a touch made in the window on fixed bones, frames outside the eased
window untouched, no deeper overlap, far-apart pairs moved closer or skipped (never stretched),
and the product's generator reporting it per segment."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.eval.pair_report import CONTACT_PROMPTS
from interplay.generators.base import Request
from interplay.generators.coda.contact_kinds import candidates, contact_kind
from interplay.generators.coda.contact_refine import pair_numbers, reach_gaps, refine_contact
from interplay.generators.coda.files import DEFAULT_DIR, FILES
from interplay.generators.coda.generator import CodaGenerator
from interplay.generators.coda.runtime import CodaRuntime
from interplay.motion import skeleton as sk
from interplay.motion.pair.compose import HELD_PROMPT, PROMPTS
from interplay.review.checks import CONTACT_VERBS

HAVE_CODA = all((DEFAULT_DIR / f).is_file() for f in FILES)
needs_coda = pytest.mark.skipif(not HAVE_CODA, reason="no CODA weights committed yet")
ARMS = [sk.JOINT_INDEX[f"{s}_{j}"] for s in ("left", "right") for j in ("elbow", "wrist")]


@pytest.fixture(scope="module")
def rt():
    return CodaRuntime.load(DEFAULT_DIR)


def sample(rt, prompt: str, seed: int) -> np.ndarray:
    return rt.generate(prompt, 4.0, seed)                       # (2, 80, 22, 3)


def test_the_kind_comes_from_the_composers_and_evals_words():
    for kind in ("handshake", "high_five", "hug", "push"):
        assert all(contact_kind(p) == kind for p in PROMPTS[kind]), kind
    assert contact_kind(HELD_PROMPT) == "walk_side_by_side"
    assert all(contact_kind(p) is None for p in PROMPTS["wave"] + PROMPTS["walk_side_by_side"])
    assert all(contact_kind(p) == k for k, p in CONTACT_PROMPTS.items())
    assert contact_kind("a person does push-ups") is None
    assert contact_kind("two people walk hand in hand") == "walk_side_by_side"
    for p in [*PROMPTS["handshake"], *PROMPTS["hug"], *PROMPTS["push"], HELD_PROMPT]:
        assert CONTACT_VERBS.search(p), p                      # the reviewer agrees it is a touch


@needs_coda
def test_a_refined_handshake_touches_on_fixed_bones_and_leaves_the_rest(rt):
    pair = sample(rt, "two people shake hands", 1)
    a, b, rep = refine_contact(pair[0], pair[1], "handshake")
    assert rep["applied"], rep["reason"]
    s, e = rep["window"]
    r_in, r_out = rep["ramps"]
    rs = candidates("handshake", pair[0], pair[1], slice(s, e))[0]
    assert rep["hands"] == [[0, "right_wrist"], [1, "right_wrist"]]
    assert reach_gaps(pair[0], pair[1], rs)[s:e].min() > 0.03          # no touch before
    assert reach_gaps(a, b, rs)[s:e].max() <= 0.03                     # right hands touch
    for new, old in ((a, pair[0]), (b, pair[1])):
        assert np.abs(sk.bone_lengths(new) - sk.bone_lengths(old)).max() < 1e-6
        outside = np.r_[0:s - r_in, e + r_out:len(old)]
        assert np.array_equal(new[outside], old[outside])            # bit for bit
        others = [j for j in range(sk.NUM_JOINTS) if j not in ARMS]
        if rep["approach_m"] == 0:
            assert np.array_equal(new[:, others], old[:, others])    # only the arms moved
        # eased: no pop of the wrists (a jump would be a one-frame step of many cm)
        for w in (sk.LEFT_HAND, sk.RIGHT_HAND):
            acc = np.linalg.norm(np.diff(new[:, w], 2, axis=0), axis=1)
            ref = np.linalg.norm(np.diff(old[:, w], 2, axis=0), axis=1)
            assert acc.max() <= ref.max() + 0.02
    before, after = pair_numbers(*pair), pair_numbers(a, b)
    assert after["penetration_cm"] <= before["penetration_cm"] + 0.01
    assert after["iv_cm3"] <= before["iv_cm3"] + 0.5
    assert rep["after"] == after


@needs_coda
@pytest.mark.parametrize("kind", ["high_five", "push"])
def test_high_five_and_push_touch_without_deeper_overlap(rt, kind):
    for seed in (1, 2):
        pair = sample(rt, CONTACT_PROMPTS[kind], seed)
        a, b, rep = refine_contact(pair[0], pair[1], kind)
        assert rep["applied"], rep["reason"]
        s, e = rep["window"]
        assert rep["gap_cm"] <= 3.0
        assert pair_numbers(a, b)["penetration_cm"] <= pair_numbers(*pair)["penetration_cm"] + 0.01
        for new, old in ((a, pair[0]), (b, pair[1])):
            assert np.abs(sk.bone_lengths(new) - sk.bone_lengths(old)).max() < 1e-6


def _apart(pair: np.ndarray, metres: float) -> np.ndarray:
    """b moved `metres` further from a along the line between their pelvises (frame 0)."""
    u = (pair[1, 0, sk.PELVIS] - pair[0, 0, sk.PELVIS]) * np.array([1.0, 0.0, 1.0])
    out = pair.copy()
    out[1] += metres * u / np.linalg.norm(u)
    return out


@needs_coda
def test_far_apart_people_are_moved_closer_or_skipped_never_stretched(rt):
    pair = _apart(sample(rt, "two people shake hands", 1), 0.4)
    a, b, rep = refine_contact(pair[0], pair[1], "handshake")
    assert rep["applied"] and rep["approach_m"] > 0.1, rep
    s, e = rep["window"]
    assert rep["gap_cm"] <= 3.0
    gap = lambda x, y: np.linalg.norm((y[s:e, sk.PELVIS] - x[s:e, sk.PELVIS])[:, [0, 2]], axis=1)
    assert gap(a, b).mean() < gap(pair[0], pair[1]).mean() - 0.1
    for new, old in ((a, pair[0]), (b, pair[1])):
        assert np.abs(sk.bone_lengths(new) - sk.bone_lengths(old)).max() < 1e-6
    # not the last segment: everything eases back out, so the next one joins the model's frames
    a2, b2, rep2 = refine_contact(pair[0], pair[1], "handshake", free_end=False)
    assert rep2["applied"] and np.array_equal(a2[-1], pair[0, -1]) and np.array_equal(b2[-1], pair[1, -1])

    far = _apart(sample(rt, "two people shake hands", 1), 2.0)
    a, b, rep = refine_contact(far[0], far[1], "handshake")
    assert not rep["applied"] and "out of reach" in rep["reason"]
    assert np.array_equal(a, far[0]) and np.array_equal(b, far[1])


def test_no_contact_kind_returns_the_motion():
    j = np.repeat(sk.rest_joints()[None], 10, axis=0)
    a, b, rep = refine_contact(j, j + [1.0, 0.0, 0.0], None)
    assert not rep["applied"] and np.array_equal(a, j)
    with pytest.raises(ValueError):
        refine_contact(j, j, "tango")


@needs_coda
def test_the_product_refines_contact_segments_and_reports_them(rt):
    gen = CodaGenerator(rt)
    req = Request("two people shake hands, then they wave at each other", persons=2, seconds=8, seed=1)
    plan = gen.plan(req)
    chunks = list(gen.stream(req, plan))
    frames = sum(c[0].shape[0] for _, c in chunks)
    assert frames == plan.segments[-1].end
    assert [s for s, _ in chunks] == sorted(s for s, _ in chunks)
    shake, wave = plan.to_json()["segments"]
    assert shake["contact"]["kind"] == "handshake" and shake["contact"]["applied"], shake["contact"]
    assert "contact" not in wave
    people = np.concatenate([np.stack(c) for _, c in chunks], axis=1)
    s, e = shake["contact"]["window"]
    rs = candidates("handshake", people[0], people[1], slice(s, e))
    assert min(reach_gaps(people[0], people[1], r)[s:e].max() for r in rs) <= 0.03
