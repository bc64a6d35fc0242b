"""Clauses joined by ", then" whose verbs the catalogue does not know stay separate segments, in
their order, each shown as the nearest captures of its own words (not one segment with the
whole prompt)."""

from __future__ import annotations

import pytest

from interplay.planner.plan import embedded_plan

COFFEE = ["a person hammers a nail into the wall, then sips a hot coffee",
          "hammer a nail into the wall, then sip a hot coffee",          # an order: base forms
          "Hammer a nail into the wall, then sip a hot coffee."]


@pytest.mark.parametrize("prompt", COFFEE)
@pytest.mark.parametrize("persons", [1, 2])
def test_two_unknown_clauses_are_two_segments(prompt, persons):
    plan = embedded_plan(prompt, persons, None, None)
    assert len(plan.segments) == 2
    first, second = plan.segments
    assert "hammer" in first.base and "nail" in first.base and "coffee" not in first.base
    assert "sip" in second.base and "coffee" in second.base and "nail" not in second.base
    assert first.end <= second.start
    assert all(s.coverage is not None and s.coverage.how == "nearest" for s in plan.segments)


def test_one_unknown_clause_is_still_the_prompt_as_written():
    plan = embedded_plan("hammer a nail into the wall", 1, None, None)
    assert [s.base for s in plan.segments] == ["a person hammer a nail into the wall"]


def test_a_subject_noun_with_its_object_is_a_verb():
    """"fan yourself": "fan" (a supporter, when it is the subject) is the verb here."""
    said = embedded_plan("fan yourself with a newspaper", 1, 6.0).segments[0].prompt
    assert "fan themselves" in said
    assert embedded_plan("a fan cheers in the stands", 1, 6.0).segments[0].prompt == "a person cheers in the stands"


def test_a_bare_unknown_verb_after_a_known_one_is_kept_not_dropped():
    """"wave, then sip a hot coffee": the instruction's bare verb is not in the catalogue, and
    the clause is shown as the nearest captures instead of vanishing."""
    for prompt, said in (("wave, then sip a hot coffee", "a person sip a hot coffee"),
                         ("jump twice and then juggle three balls", "a person juggle three balls"),
                         ("two people argue and then one of them storms off", "a person storms off")):
        p = embedded_plan(prompt, 1, 8.0)
        assert len(p.segments) == 2, [s.prompt for s in p.segments]
        assert p.segments[1].prompt == said and p.segments[1].coverage.how == "nearest"
    states = embedded_plan("run, then feel happy", 1, 6.0)       # a state is still no motion
    assert [s.prompt for s in states.segments] == ["a person runs"]
