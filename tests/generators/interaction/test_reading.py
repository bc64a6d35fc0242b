"""A two-person prompt read as written and with its people named neutrally
(`interaction.reading.read`): role nouns no longer keep a prompt from the kind it describes,
the words still beat the encoder, "together" yields to a near description of another kind, and
a prompt left to another generator (a couple's dance) stays with it."""

from __future__ import annotations

import pytest

from interplay.generators.interaction.kinds import fallback, read_script
from interplay.generators.interaction.reading import read
from interplay.text.encoder import get_encoder


@pytest.mark.parametrize("prompt, was, kind", [
    ("a waiter hands a menu to a guest", "face_to_face", "hand_over"),
    ("a father lifts his daughter onto his shoulders", "face_to_face", "carry"),
    ("a nurse helps an old man walk down the hall", "face_to_face", "lead"),
    ("two friends clink their glasses together", "together", "high_five"),
])
def test_role_nouns_and_together_no_longer_hide_the_kind(prompt, was, kind):
    enc = get_encoder()
    before = read_script(prompt, None, enc) or fallback(prompt, enc)
    assert before is not None and before.kind == was          # what the words alone read
    script = read(prompt, None, enc)
    assert script is not None and script.kind == kind, script
    assert any("neutrally" in r or "nearer than" in r for r in script.reasons)


def test_the_words_still_decide_where_they_name_a_kind():
    enc = get_encoder()
    for prompt, kind in (("one person pushes the other, who stumbles backwards", "push"),
                         ("the teacher pats the student on the shoulder", "touch"),
                         ("a kid runs away and his dad chases him", "chase")):
        script = read(prompt, None, enc)
        assert script is not None and script.kind == kind and script.guessed is None


def test_a_dance_stays_with_the_generator_it_was_left_to():
    enc = get_encoder()
    for prompt in ("the leader spins the follower", "a salsa couple, the lead turns his partner under his arm"):
        assert read(prompt, None, enc) is None


@pytest.mark.parametrize("prompt", ["two people grab each other's hands", "a man holds a woman's hand",
                                    "lovers stroll hand in hand on the beach", "they walk with their hands joined"])
def test_hands_held_said_many_ways_are_held(prompt):
    """Not a touch ('grab*', 'hand on the beach') nor a hand-over: the two walk holding hands."""
    script = read(prompt, None, get_encoder())
    assert script is not None and script.kind == "side_by_side" and script.held, script


@pytest.mark.parametrize("prompt, kind, approach", [
    ("two old friends spot each other, walk over and hug", "hug", True),
    ("he runs over to his friend and gives him a high five", "high_five", True),
    ("they walk over the bridge together", "together", False),      # over a thing: no approach
])
def test_walking_over_to_someone_is_an_approach(prompt, kind, approach):
    script = read(prompt, None, get_encoder())
    assert script is not None and script.kind == kind and script.approach is approach
