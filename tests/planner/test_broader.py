"""Verbs the catalogue lacks, read as the broader verb it knows through WordNet's verb hierarchy
(planner/broader.py, catalogue/wordnet.py, catalogue/senses.toml)."""

from __future__ import annotations

import pytest

from interplay.catalogue import wordnet
from interplay.catalogue.load import catalogue
from interplay.planner.broader import broadened, broader
from interplay.planner.plan import embedded_plan
from interplay.planner.verbs import VERBS


@pytest.mark.parametrize("word, known, said", [
    ("heft", "lift", "lift"),            # a kind of lifting
    ("hefted", "lift", "lifted"),        # the said form kept
    ("lobs", "throw", "throws"),
    ("toss", "throw", "throw"),          # not "flip": the catalogue's flip is a somersault
    ("perch", "sit", "sit"),
    ("mosey", "walk", "walk"),
])
def test_a_rare_verb_is_read_as_the_known_verb_it_is_a_kind_of(word, known, said):
    hit = broader(word)
    assert hit is not None and hit.known == known and hit.word == said, hit
    assert "WordNet" in hit.reason() and word in hit.reason()


@pytest.mark.parametrize("word", [
    "walk", "jumps", "hands",            # known already (a verb, a word of the hand-over's words)
    "off", "out",                        # particles WordNet also lists as verbs
    "think", "argue",                    # no motion sense among their first
    "grapple",                           # only as broad as "move": says nothing
    "qwzx",                              # not a word
])
def test_known_words_particles_and_non_motions_are_not_read(word):
    assert broader(word) is None


def test_only_the_head_verb_is_read_not_a_noun_after_it():
    assert broadened("two people duel")[0] == "two people fight"
    assert broadened("a person runs in a zigzag pattern") == ("a person runs in a zigzag pattern", ())
    assert broadened("heft a bride into the cottage")[0] == "lift a bride into the cottage"


def test_the_plan_says_what_it_read_and_makes_the_known_motion():
    plan = embedded_plan("heft a bride into the cottage", 1, 4.0, None)
    assert plan.segments[0].prompt.startswith("a person lifts a bride")
    assert plan.segments[0].coverage.how != "nearest"
    assert any("'heft' read as 'lift'" in r for r in plan.reasons)
    # a clause the catalogue knows is never re-read
    known = embedded_plan("a person walks forward", 1, 4.0, None)
    assert not any("WordNet" in r for r in known.reasons)


def test_the_senses_table_names_catalogue_verbs_and_real_senses():
    names = {a.name for a in catalogue().action}
    for verb in ("lift", "throw", "sit", "walk"):
        assert wordnet.meant(verb)
    table = wordnet._meant()
    assert len(table) >= 90
    for verb, ids in table.items():
        assert verb in names and verb in VERBS, verb
        assert ids and all(i in wordnet.senses(verb) for i in ids), verb
    assert wordnet.meant("flip") is None                 # the somersault is no WordNet sense


def test_the_wordnet_data_says_where_it_came_from():
    src = wordnet.source()
    assert src["repository"].endswith("globalwordnet/english-wordnet")
    assert len(src["commit"]) == 40 and "CC BY 4.0" in src["licence"]
    assert wordnet.lemmas("lobbed") == ["lob"] and wordnet.senses("lob")


def test_the_two_person_reader_weighs_the_broader_reading():
    from interplay.generators.interaction.reading import read
    from interplay.text.encoder import get_encoder
    script = read("a detective tails a suspect", None, get_encoder())
    assert script is not None and script.kind == "chase" and script.guessed is None
    assert any("'tails' read as 'chases'" in r for r in script.reasons)
    # a prompt the encoder reads nearer than 0.7 keeps its reading ("arm wrestle" is no fight)
    wrestle = read("two men arm wrestle", None, get_encoder())
    assert wrestle is not None and wrestle.kind != "spar"


def test_words_a_primitive_makes_are_left_to_it():
    """"bang on a drum" is the drumming activity, not a hit: the broader verb is read only where
    no primitive is as near as the generator takes one (the bound is the generator's own)."""
    from interplay.generators.retrieve_edit.primitive_steps import PRIMITIVE_SIM
    from interplay.planner.broader import PRIMITIVE_NEAR, primitive_near
    from interplay.planner.vocabulary import load_vocabulary
    assert PRIMITIVE_NEAR == PRIMITIVE_SIM
    encode = load_vocabulary(None).encode
    assert broader("bang") is not None and primitive_near("bang on a drum", encode)
    assert not primitive_near("heft a bride into the cottage", encode)
    plan = embedded_plan("bang on a drum", 1, 4.0, lambda: load_vocabulary(None))
    assert not any("WordNet" in r for r in plan.reasons)
    plan = embedded_plan("heft a bride into the cottage", 1, 4.0, lambda: load_vocabulary(None))
    assert plan.segments[0].prompt.startswith("a person lifts")


def test_a_verb_of_a_limb_or_thing_needs_an_object():
    """"a person levitates and spins in the air" stays not covered: WordNet's levitate is a kind
    of raising something, and the catalogue's raise moves a limb; with nothing raised it is no
    raise. "heft a bride" has its object."""
    assert broader("levitates", "and") is None and broader("levitates", None) is None
    assert broader("heft", "a") is not None and broader("mosey", None) is not None    # walk: no object
    assert broadened("a person levitates and spins in the air")[1] == ()
