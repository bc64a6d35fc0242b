"""SPAM behind the studio's router: its plans stream through the router in order and add up
exactly; the router's own plans (retrieve-then-edit) do not need it, and when its weights are
missing, broken or an untrained placeholder the router says why and refuses the edits only SPAM
can make; SPAM's edits through the router."""

from __future__ import annotations

import shutil

import numpy as np
import pytest

from interplay.generators.base import EditUnavailable, Request, generate_motion
from interplay.generators.retrieval.generator import CHUNK
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.generators.router import with_spam
from interplay.generators.spam.generator import SpamGenerator, resolve_edit_part, segment_texts
from interplay.generators.spam.runtime import DEFAULT_DIR, part_texts
from interplay.generators.weights import placeholder_reason
from interplay.motion import skeleton as sk
from interplay.planner.schema import Segment
from tests.helpers.spam_stub import StubEncoder
from tests.helpers.synthetic_motion import fk_motion, stand_in_clips


@pytest.fixture(scope="module")
def index():
    return RetrievalIndex(stand_in_clips(), StubEncoder())


@pytest.fixture(scope="module")
def spam_gen(index):
    return with_spam(index, DEFAULT_DIR, allow_untrained=True)


def _weights(tmp_path, card: str | None) -> str:
    d = tmp_path / "spam"
    shutil.copytree(DEFAULT_DIR, d)
    (d / "MODEL_CARD.md").unlink(missing_ok=True)
    if card is not None:
        (d / "MODEL_CARD.md").write_text(card)
    return d


def test_one_person_uses_spam_and_streams_exact_frames(spam_gen):
    assert spam_gen.spam is not None
    req = Request("a person walks forward, then jumps", persons=1, seconds=13.3, seed=4)
    spam = SpamGenerator(spam_gen.spam)
    plan = spam.plan(req)
    assert plan.generator == "spam" and plan.seed == 4 and len(plan.segments) == 2
    chunks = list(spam_gen.stream(req, plan))
    starts = [s for s, _ in chunks]
    sizes = [len(c[0]) for _, c in chunks]
    assert starts == list(np.cumsum([0] + sizes[:-1])) and sum(sizes) == 266
    assert max(sizes) <= CHUNK and all(len(c) == 1 for _, c in chunks)
    motion = generate_motion(spam, req)
    assert motion.frames == 266 and motion.plan["generator"] == "spam"
    assert np.array_equal(motion.people[0], np.concatenate([c[0] for _, c in chunks]))


@pytest.mark.parametrize("persons", [1, 2])
def test_the_router_plans_with_retrieve_edit_and_says_why(spam_gen, persons):
    # two people: a dance is no interaction the composition makes, so retrieve-then-edit does
    plan = spam_gen.plan(Request("a person walks forward" if persons == 1 else "two people dance salsa",
                                 persons=persons, seconds=4, seed=1))
    assert plan.generator == "retrieve_edit" and "real captured clips" in plan.generator_reason
    if persons == 2:
        assert plan.generator_reason.startswith("composition: no interaction it composes")


@pytest.mark.parametrize("case", ["missing", "broken", "placeholder"])
def test_bad_weights_fall_back_to_retrieval(case, index, tmp_path):
    if case == "missing":
        d = tmp_path / "nothing"
    elif case == "broken":
        d = _weights(tmp_path, "# SPAM\n")
        (d / "vq_decode.onnx").write_bytes(b"\x00" * 64)
    else:
        d = _weights(tmp_path, "# SPAM — placeholder\n\nUNTRAINED graphs\n")
    gen = with_spam(index, d)
    assert gen.spam is None and str(d) in gen.reason
    req = Request("a person walks forward", persons=1, seconds=3, seed=2)
    assert gen.plan(req).generator == "retrieve_edit"
    assert gen.generate(req).frames == 60
    walk = fk_motion(40, "walk")[0]
    _, entry = gen.edit(walk, "left_arm", "waves", seed=0)        # an arm pose: IK, no model
    assert entry["generator"] == "ik_pose"
    with pytest.raises(EditUnavailable, match="SPAM"):
        gen.edit(walk, "left_leg", "kicks high", seed=0)


def test_trained_card_is_served(tmp_path):
    d = _weights(tmp_path, "# SPAM — model card\n\nTrained on …\n")
    assert placeholder_reason(d, "SPAM") is None
    assert placeholder_reason(_weights(tmp_path / "x", "# SPAM — placeholder\n"), "SPAM") is not None


def test_edit_through_the_generator(spam_gen):
    joints = fk_motion(80, "walk")[0].astype(np.float64)
    edit, entry = spam_gen.edit(joints, "right_arm", "swings the right arm", frames=(8, 60), seed=3)
    assert entry["generator"] == "spam"
    assert edit.parts == ("right_upper",) and entry["frames"] == [8, 60] and entry["seed"] == 3
    assert np.array_equal(edit.joints[:8], joints[:8]) and np.array_equal(edit.joints[60:], joints[60:])
    assert entry["untouched_change_cm"] < 0.5
    assert resolve_edit_part("whole_body") == list(sk.PART_NAMES)
    assert resolve_edit_part("Left Leg") == ["left_lower"]
    with pytest.raises(ValueError, match="left_arm"):
        resolve_edit_part("tail")
    with pytest.raises(ValueError):
        spam_gen.edit(joints, "left_arm", "   ", seed=0)


def test_planned_part_edits_become_part_prompts():
    timing = {"index": 0, "seconds": 1.0, "start": 0, "end": 20, "persons": [0]}
    seg = Segment.model_validate({
        "prompt": "a person walks while waving", "base": "a person walks", **timing,
        "edits": {"left_arm": None, "right_arm": "waves the right hand", "left_leg": "",
                  "right_leg": None}})
    assert part_texts(segment_texts(seg)) == ["a person walks", "waves the right hand",
                                              "a person walks", "a person walks"]
    jump = Segment.model_validate({"prompt": "a person jumps", "base": "a person jumps", **timing})
    assert segment_texts(jump) == "a person jumps"
