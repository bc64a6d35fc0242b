"""`interplay plan`: the planner's JSON (what the API streams as the plan) and a readable table."""

import json

from interplay.cli import main as cli
from interplay.planner.plan import plan_json
from interplay.planner.schema import validate_plan

PROMPT = "two people shake hands, then one walks away in a circle"


def test_plan_json_is_the_planners_plan(capsys, monkeypatch):
    for var in ("INTERPLAY_LLM_BASE_URL", "INTERPLAY_LLM_MODEL"):
        monkeypatch.delenv(var, raising=False)
    assert cli.main(["plan", "--prompt", PROMPT, "--persons", "2", "--seconds", "8", "--json"]) == 0
    got = json.loads(capsys.readouterr().out)
    assert got == plan_json(PROMPT, 2, 8.0)
    p = validate_plan(got)
    assert p.planner == "embedded" and p.seconds == 8.0 and [s.persons for s in p.segments] == [[0, 1], [1]]


def test_plan_table_and_bad_input(capsys):
    assert cli.main(["plan", "--prompt", "a person walks in a circle while raising the left arm"]) == 0
    out = capsys.readouterr().out
    assert "planner: embedded · 1 segment(s)" in out
    assert "left_arm: raises the left arm" in out and "'shape': 'circle'" in out
    assert cli.main(["plan", "--prompt", "  "]) == 2
    assert "the prompt is empty" in capsys.readouterr().err
    assert cli.main(["plan", "--prompt", "a person jumps", "--seconds", "90"]) == 2
