"""Two people named by role (a waiter and a guest, two coworkers, a dad and his daughter): the
planner reads them as "one person" / "the other person" / "two people" (`pair.named`), so each
person's part is found, and a clause of one doing something to the other gives that one the
action and the other a stand-by; people it knows by name are planned as before."""

from __future__ import annotations

from interplay.planner.plan import embedded_plan, plan
from interplay.planner.vocabulary import load_vocabulary
from interplay.text.encoder import get_encoder


def _roles(prompt: str) -> list[tuple[str, dict]]:
    return [(s.prompt, s.roles) for s in plan(prompt, 2, 6.0).segments]


def test_role_nouns_leave_the_segment_text():
    for prompt, said in (("two coworkers argue loudly", "two people argue loudly"),
                         ("two toddlers build a sandcastle", "two people build a sandcastle")):
        p = plan(prompt, 2, 6.0)
        assert [s.prompt for s in p.segments] == [said]
        assert any(r.startswith("people:") for r in p.reasons)


def test_one_does_it_to_the_other_who_stands_by():
    for prompt in ("a waiter hands a menu to a guest", "a young waiter serves an old lady a cup of tea"):
        (text, roles), = _roles(prompt)
        assert text.startswith("one person ") and "the other person" in roles["0"], (text, roles)
        assert roles["1"] == "a person stands still"


def test_an_exchange_with_role_nouns_is_read_as_one():
    segs = _roles("the boxer punches his opponent, who falls down")
    assert len(segs) == 2
    assert segs[0][1]["0"].startswith("a person punches") and segs[1][1]["1"] == "a person falls down"


def test_people_the_planner_knows_are_planned_as_before():
    for prompt in ("the man and the woman shake hands", "one person pushes the other, who stumbles backwards",
                   "give each other a high five", "they greet each other with a handshake",
                   # instructions: their nouns are things, not people ("iron a shirt", "do a squat")
                   "iron a shirt", "do a squat", "step sideways to the left", "tiptoe past the sleeping baby"):
        assert not any(r.startswith("people:") for r in plan(prompt, 2, 6.0).reasons)


def test_one_person_named_by_role_is_a_person():
    """"a toddler wobbles across the rug": the words after the toddler are their motion (they
    were kept with the noun, "a person toddler wobbles …"); a bare first word is no person."""
    from interplay.planner.pair.named import plain_person
    enc = get_encoder()
    assert plain_person("a toddler wobbles across the rug", enc)[0] == "a person wobbles across the rug"
    assert plain_person("a tired hiker climbs a steep hill", enc)[0] == "a person climbs a steep hill"
    for kept in ("pick apples from the high branches of a tree", "a man jumps", "a waiter hands a menu to a guest"):
        assert plain_person(kept, enc)[0] == kept
    plan = embedded_plan("a toddler wobbles across the rug", 1, 5.0, lambda: load_vocabulary(None))
    assert plan.segments[0].prompt == "a person wobbles across the rug"
