"""What retrieval reads from a segment's words beyond the action: the speed band, the turn,
staying on the spot, stopping (each then checked on the draws with the benchmark's checks)."""

import pytest

from interplay.generators.retrieval.intent import intent, speed_of, turn_of


@pytest.mark.parametrize("text,band", [
    ("a person sprints as fast as they can", "sprint"), ("a person jogs", "jog"),
    ("a person runs slowly", "jog"), ("a person runs", "run"), ("a person walks slowly", "slow"),
    ("a person shuffles along like a tired old man", "slow"), ("a person walks", None),
    # slowing down is a change of speed, not a slow walk
    ("a person slows down to a walk", None), ("a person slowed down and stopped", None),
])
def test_speed_bands(text, band):
    assert speed_of(text) == band


@pytest.mark.parametrize("text,turn", [
    ("a person turns around", (180, "any")), ("a person spins around twice", (720, "any")),
    ("a person turns to the left", (90, "left")), ("a person walks forward", None),
])
def test_turns(text, turn):
    assert turn_of(text) == turn


def test_on_the_spot_and_stopping():
    assert intent("a person hops on the spot").in_place
    assert intent("a person dances on the spot").in_place           # kept put (on_the_spot.py)
    assert not intent("a person dances").in_place
    assert intent("a person stops walking and stands still").still
    assert not intent("a person walks, then stops").still
