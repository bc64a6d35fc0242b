"""A prompt nothing in the library covers ends `not_covered` with the nearest shown — in the
API's plan and review events and in the CLI's output — never a silent `ok` (issue 24, 1)."""

from __future__ import annotations

from interplay.cli.main import main
from tests.helpers.api import run_job

PROMPT = "a person levitates and spins in the air"


def test_the_api_says_not_covered_with_what_was_shown(real_client):
    job, events = run_job(real_client, prompt=PROMPT, seconds=5, seed=3)
    assert events[-1]["type"] == "done"
    plan = next(e["plan"] for e in events if e["type"] == "plan")
    cov = plan["segments"][0]["coverage"]
    assert cov["how"] == "nearest" and cov["shown"]
    assert any("not in the library — showing the nearest" in r for r in plan["reasons"])
    verdicts = [e.get("verdict") for e in events if e["type"] == "review" and e.get("segment") == 0]
    assert verdicts and set(verdicts) == {"not_covered"}
    assert plan["segments"][1]["coverage"]["how"] == "capture"        # the spin is covered


def test_the_cli_says_so(tmp_path, capsys):
    assert main(["generate", "--prompt", PROMPT, "--seconds", "5", "--seed", "3",
                 "--out", str(tmp_path / "m.json")]) == 0
    err = capsys.readouterr().err
    assert "segment 0 'a person levitates': not in the library — showing the nearest:" in err
