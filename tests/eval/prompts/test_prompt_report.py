"""`interplay eval-prompts`' runner and table with stand-in rows that return real captures."""

from __future__ import annotations

import json

import numpy as np

from interplay.eval.prompts.report import build_report, format_table, run, t975, write
from interplay.eval.prompts.rows import Row
from interplay.eval.prompts.suite import Prompt
from interplay.motion.clip import default_clips
from interplay.motion.motion import Motion


def _clip(label):
    return next(c for c in default_clips() if c.label == label).people[0].astype(np.float32)


PROMPTS = [
    Prompt("counts-01", "test", "counts", "squat once", 1, 2.0, ({"check": "squat_count", "count": 1},)),
    Prompt("counts-02", "test", "counts", "jump once", 1, 2.0, ({"check": "jump_count", "count": 1},)),
    Prompt("two_person-01", "test", "two_person", "dance", 2, 4.0, ({"check": "close_together"},),
           contact=True, kind="dancing"),
]


def squat_row(fail_seed: int | None = None) -> Row:
    """A one-person row that answers every prompt with a captured squat (raising on one seed)."""
    def make(req):
        if req.seed == fail_seed:
            raise RuntimeError("boom")
        return [_clip("squat1Reps")], {"generator": "stub"}
    return Row("squats", (1,), make, "a captured squat for everything")


def salsa_row() -> Row:
    salsa = next(c for c in default_clips() if c.source == "cmu-salsa")
    return Row("salsa", (2,), lambda req: ([p[200:360] for p in salsa.people], {"generator": "stub"}),
               "a captured salsa pair")


def test_rates_count_checks_per_seed_with_n_a_where_a_row_cannot_serve(tmp_path):
    rows = [squat_row(), salsa_row()]
    results = run(rows, PROMPTS, seeds=2, out=tmp_path)
    assert len(results) == 2 * 2 + 1 * 2
    report = build_report(rows, {"coda": "no weights"}, PROMPTS, results, "test", 2, 1.0)
    t = report["table"]
    assert t["squats"]["counts"]["checks"] == 0.5           # the squat counts 1 squat, 0 jumps
    assert t["squats"]["counts"]["checks_ci"] == 0.0        # the same on both seeds
    assert t["squats"]["two_person"] is None and t["salsa"]["counts"] is None
    assert t["salsa"]["two_person"]["checks"] == 1.0
    text = format_table(report)
    assert "n/a" in text and "coda: skipped (no weights)" in text
    write(tmp_path, report, results)
    assert json.loads((tmp_path / "report.json").read_text())["table"]["squats"]["all"]["outputs"] == 4
    rec = json.loads((tmp_path / "results.jsonl").read_text().splitlines()[0])
    motion = Motion.from_json(json.loads((tmp_path / rec["motion"]).read_text()))
    assert motion.frames == len(_clip("squat1Reps")) and motion.seed == 0
    md = (tmp_path / "table.md").read_text()
    assert "| category | prompts | squats | salsa |" in md and "| counts | 2 | 0.50±0.00 | n/a |" in md


def test_a_raising_generator_fails_its_checks_and_is_counted(tmp_path):
    rows = [squat_row(fail_seed=1)]
    results = run(rows, PROMPTS[:1], seeds=3, out=tmp_path)
    bad = [r for r in results if "error" in r]
    assert len(bad) == 1 and not bad[0]["all_passed"] and "boom" in bad[0]["error"]
    report = build_report(rows, {}, PROMPTS[:1], results, "test", 3, 1.0)
    cell = report["table"]["squats"]["counts"]
    assert abs(cell["checks"] - 2 / 3) < 1e-9
    # Student's t over 3 seeds: 4.303 · sd / √3 with sd of (1, 0, 1).
    assert abs(cell["checks_ci"] - 4.303 * np.std([1, 0, 1], ddof=1) / np.sqrt(3)) < 1e-9
    assert report["table"]["squats"]["errors"] == 1


def test_t_quantiles():
    assert t975(2) == 4.303 and t975(11) == 2.228 and t975(100) == 1.96 and np.isnan(t975(0))
