"""Two people: an action per person with its timing (issue 15, item 1) — who starts, who
answers and when — on the eval-prompts suite's dev prompts and the issue's own examples, and
the composed retrieval branch drawing each person's captures by their own role."""

import numpy as np
import pytest

from interplay.generators.retrieval.generator import RetrievalGenerator
from interplay.planner.pair.roles import exchange
from interplay.planner.plan import embedded_plan
from interplay.planner.schema import validate_plan
from interplay.planner.vocabulary import load_vocabulary
from tests.planner.suite import plan_of


def _plan(prompt, seconds=6.0):
    return embedded_plan(prompt, 2, seconds, load_vocabulary)


def _timing(seg):
    return seg.timing.model_dump() if seg.timing else None


def test_push_then_the_other_stumbles_back_from_the_contact():
    p = plan_of("two_person-13")                  # "one pushes the other, who stumbles backwards"
    push, stumble = p.segments
    assert push.persons == [0] and "pushes" in push.roles["0"] and "stands" in push.roles["1"]
    assert stumble.persons == [1] and "stumbles backwards" in stumble.roles["1"]
    assert _timing(push) == {"lead": 0, "response": "contact", "phase": "lead"}
    assert _timing(stumble) == {"lead": 0, "response": "contact", "phase": "response"}
    assert stumble.start == push.end and stumble.travel == "backward"
    assert stumble.trajectory is None              # moves back facing the pusher, no path
    assert push.edits.left_arm and push.edits.right_arm          # a two-handed push
    assert min(s.seconds for s in p.segments) >= 1.0             # time for contact and steps
    assert validate_plan(p.to_json()) == p


def test_a_wave_answered_after_it_ends():
    # the example with named people ("one waves at the other, who waves back")
    p = _plan("a man waves at a woman, who waves back", 5.0)
    first, answer = p.segments
    assert "waves" in first.roles["0"] and "stands" in first.roles["1"]
    assert answer.roles["1"] == "a person waves" and "stands" in answer.roles["0"]
    assert _timing(answer) == {"lead": 0, "response": "after", "phase": "response"}
    again = _plan("one waves, and the other waves back", 5.0)
    assert [s.persons for s in again.segments] == [[0], [1]]
    assert _timing(again.segments[1])["response"] == "after"


def test_the_leader_spins_the_follower_in_one_segment():
    (seg,) = _plan("the leader spins the follower", 4.0).segments
    assert seg.persons == [0, 1] and "raises the right arm" in seg.roles["0"]
    assert seg.roles["1"].startswith("a person spins around")
    assert _timing(seg) == {"lead": 0, "response": "with", "phase": "both"}
    assert "stand still" not in seg.prompt and "stands still" not in " ".join(seg.roles.values())


def test_the_one_followed_leads_and_a_mirror_copies():
    (follow,) = plan_of("two_person-15").segments  # "one person follows the other around the room"
    assert follow.persons == [0, 1] and _timing(follow)["lead"] == 1
    assert "around the room" in follow.roles["1"] and "following" in follow.roles["0"]
    (mirror,) = plan_of("two_person-21").segments  # "one copies the other's arm movements …"
    assert _timing(mirror) == {"lead": 1, "response": "with", "phase": "both"}
    assert "arms" in mirror.roles["1"] and "copies" in mirror.roles["0"]


def test_one_stops_while_the_other_walks_on():
    walk, stop = plan_of("two_person-17").segments   # "two people walk side by side, then one stops"
    assert walk.persons == [0, 1] and stop.persons == [0, 1]
    assert stop.roles["1"] == "a person stops walking and stands still"
    assert stop.roles["0"] == walk.roles["0"]        # the other keeps walking
    assert stop.seconds >= 2.5                       # slowing down, then seen standing (2 s)


def test_in_turn_and_together():
    bow = _plan("they bow in turn", 5.0)
    assert [s.persons for s in bow.segments] == [[0], [1]]
    assert [s.timing.phase for s in bow.segments] == ["lead", "response"]
    (jump,) = _plan("two people jump together", 3.0).segments
    assert jump.persons == [0, 1] and jump.timing is None and jump.roles["0"] == jump.roles["1"]


@pytest.mark.parametrize("text", ["two people walk side by side", "one walks away in a circle",
                                  "a man and a woman wave at each other", "they dance together"])
def test_plain_clauses_are_no_exchange(text):
    assert exchange(text, {}) is None


def test_plans_without_the_new_fields_read_and_write_as_before():
    old = _plan("two people shake hands", 3.0).to_json()
    assert "timing" not in old["segments"][0] and "travel" not in old["segments"][0]
    assert validate_plan(old).to_json() == old
    with pytest.raises(ValueError, match="with"):
        validate_plan({**old, "segments": [{**old["segments"][0], "timing": {
            "lead": 0, "response": "with", "phase": "lead"}}]})


class _Clip:
    def __init__(self, name):
        self.people = [np.zeros((400, 22, 3), np.float32)]
        self.licence, self.label = "test", name


class _Index:
    """Retrieval's index, recording which text each track was drawn by."""

    def __init__(self):
        self.texts = []

    def use_pair(self, text):
        return False

    def track(self, text, frames, rng, pair=False, exclude=frozenset(), after=None):
        self.texts.append(text)
        return [{"clip": text, "people": [0], "start": 0, "end": frames, "score": 1.0}]

    def clip(self, clip_id):
        return _Clip(clip_id)


def test_composed_retrieval_draws_each_person_by_their_role():
    p = plan_of("two_person-13")
    index = _Index()
    gen = RetrievalGenerator(index)
    for seg in p.segments:
        choice = gen.retrieve(seg.prompt, seg.end - seg.start, 2, np.random.default_rng(0),
                              None, seg.roles)
        assert choice.mode == "composed" and [t[0].clip for t in choice.tracks] == \
            [seg.roles["0"], seg.roles["1"]]
    assert "a person stumbles backwards" in index.texts
    index.texts.clear()
    gen.retrieve("two people shake hands", 40, 2, np.random.default_rng(0))
    assert index.texts == ["two people shake hands"] * 2    # no roles: the prompt for both


@pytest.mark.parametrize("prompt,parts", [("two people shake hands", {"right_arm"}),
                                          ("two friends shake hands with their left hands", {"left_arm"})])
def test_a_handshake_is_one_hand_each(prompt, parts):
    plan = embedded_plan(prompt, 2, 6.0, load_vocabulary)
    assert {k for k, v in plan.segments[0].edits.named().items() if v} == parts


def test_a_dance_follower_is_not_someone_who_follows():
    from interplay.generators.interaction.kinds import keyword_kind
    assert keyword_kind("the leader spins the follower")[0] is None
    assert keyword_kind("one person follows the other")[0] == "follow"


def test_one_shows_and_the_other_copies_is_an_exchange():
    """"… demonstrates a front kick and the student copies it": the copier's words are their own
    role, with whatever verb the first one's words have; "helps the other stand up" is no copy."""
    vocab = load_vocabulary(None)
    plan = embedded_plan("a karate teacher demonstrates a front kick and the student copies it", 2, 7.0,
                         lambda: vocab)
    roles = plan.segments[0].roles
    assert roles["0"] == "a person kicks" and roles["1"] == "a person copies it"
    helped = embedded_plan("one friend helps the other stand up from the ground", 2, 6.0, lambda: vocab)
    assert "copies" not in str(helped.segments[0].roles)
