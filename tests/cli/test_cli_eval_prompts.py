"""`interplay eval-prompts` end to end on one prompt with the retrieval row, and its errors."""

from __future__ import annotations

import json

from interplay.cli.main import main


def test_eval_prompts_writes_its_table_results_and_motions(tmp_path, capsys):
    out = tmp_path / "run"
    assert main(["eval-prompts", "--rows", "retrieval", "--ids", "counts-02", "--seeds", "2",
                 "--out", str(out), "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["split"] == "test" and report["prompts"] == 1 and report["seeds"] == 2
    cell = report["table"]["retrieval"]["counts"]
    assert cell["outputs"] == 2 and 0.0 <= cell["checks"] <= 1.0
    assert report["table"]["retrieval"]["two_person"] is None
    lines = (out / "results.jsonl").read_text().splitlines()
    assert len(lines) == 2
    first = json.loads(lines[0])
    assert (out / first["motion"]).is_file() and first["plausibility"]


def test_eval_prompts_rejects_bad_arguments(capsys):
    assert main(["eval-prompts", "--rows", "nope"]) == 2
    assert main(["eval-prompts", "--seeds", "0"]) == 2
    assert main(["eval-prompts", "--ids", "no-such-id"]) == 2
    assert "error" in capsys.readouterr().err
