"""words.toml validates, every list is read somewhere, and its phrases are found as whole words."""

from __future__ import annotations

from pathlib import Path

import pytest

from interplay.catalogue.words import Phrases, WordLists, lists, parse, words

PACKAGE = Path(__file__).resolve().parents[2] / "backend" / "interplay"


def test_every_list_is_read_by_the_code():
    code = "\n".join(p.read_text(encoding="utf-8") for p in PACKAGE.rglob("*.py"))
    unread = [name for name in lists() if f'"{name}"' not in code]
    assert not unread, f"lists no module reads: {unread}"


def test_a_bad_phrase_or_list_is_refused():
    with pytest.raises(ValueError, match="not closed"):
        parse("shak* (hand|hands")
    with pytest.raises(ValueError, match="bracket inside a word"):
        parse("high-(five|fives)")
    with pytest.raises(ValueError):
        WordLists.model_validate({"lists": {"empty": []}})


def test_phrases_are_whole_words_with_endings_options_and_gaps():
    p = Phrases(["shak* [each other|each other's] (hand|hands)", "high-five", "under ~2 (arm|arms)"])
    assert p.search("they shake hands").text == "shake hands"
    assert p.search("shaking each other's hands").text == "shaking each other's hands"
    assert p.search("a high five") and p.search("a high-five") and not p.search("a highfive")
    assert p.search("under her partner's arm") and not p.search("under the left raised arm")
    assert not p.search("handshakes hands") and not p.search("shake handsome")
    assert Phrases(["hug*"]).search("HUGS") is None and Phrases(["hug*"], ignore_case=True).search("HUGS")


def test_whole_starts_and_cut():
    assert words("pair_both").whole("the two friends") and not words("pair_both").whole("the two friends wave")
    assert words("pair_second").whole("person 2") and words("pair_first").whole("the first one")
    assert words("plural_subject").starts("they're waving") and not words("plural_subject").starts("and they")
    assert words("in_turn").cut("they bow, one after the other", ",") == "they bow"
    assert words("in_return").cut("waves back", "+") == "waves" and words("in_return").cut("back off", "+") == "back off"
    assert words("gesture_together", ignore_case=True).cut("jump together and clap in unison") == "jump and clap"


def test_intents_patterns_are_built_once_per_catalogue_in_use():
    from interplay.catalogue.load import use_catalogue
    from interplay.generators.retrieval import intent
    intent.speed_of("a person sprints")
    built = dict(intent._PATTERNS)
    assert built
    intent.speed_of("a person sprints")
    assert intent._PATTERNS == built                       # the same patterns, not built again
    use_catalogue(None)                                     # another catalogue: built anew
    assert not intent._PATTERNS


def test_a_phrase_that_may_not_go_on():
    sits = Phrases(["(sit|sits|sitting|sat) !(up*)"])
    assert sits.search("he sits down") and not sits.search("he sits up") and not sits.search("sits upright")
    with pytest.raises(ValueError, match="words after"):
        parse("sit !(up) down")


def test_words_said_any_number_of_times():
    arms = Phrases(["(arm|arms) on [the|his|her|both]* (hip|hips)"])
    assert arms.search("arms on hips") and arms.search("arms on both his hips") and not arms.search("arms on a hip")
