"""A count the plan cannot hold is capped with a note, never a failed plan (issue 26, 5)."""

from __future__ import annotations

from interplay.cli.main import main
from interplay.planner.plan import embedded_plan
from interplay.planner.schema import MAX_REPEAT


def test_a_count_over_the_limit_is_capped_and_said():
    p = embedded_plan("a person claps 21 times", 1, None, None)
    assert p.segments[0].repeat == MAX_REPEAT
    assert f"{MAX_REPEAT} times" in p.segments[0].prompt and "21" not in p.segments[0].prompt
    assert any("21 times is more than one segment holds" in r for r in p.reasons)


def test_a_count_within_the_limit_is_kept():
    p = embedded_plan("a person jumps 12 times", 1, None, None)
    assert p.segments[0].repeat == 12 and not any("segment holds" in r for r in p.reasons)


def test_the_cli_plans_it_instead_of_failing(capsys):
    assert main(["plan", "--prompt", "a person jumps 500 times, then waves", "--seconds", "10"]) == 0
    out = capsys.readouterr().out
    assert "20 are planned" in out and "pydantic" not in out
