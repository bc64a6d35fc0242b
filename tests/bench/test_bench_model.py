"""The model section of `interplay bench`: SpamRuntime timings per length and for an edit, on the
committed graphs, and the table; a missing weights dir is reported, not raised."""

from __future__ import annotations

from interplay.bench.model import format_model_table, run_model_bench
from interplay.generators.spam.runtime import DEFAULT_DIR


def test_model_bench_times_generation_and_an_edit(tmp_path):
    report = run_model_bench(DEFAULT_DIR, runs=2, warmup=0, seconds=(2.0, 6.0))
    assert [r["frames"] for r in report["generate"]] == [40, 120]
    for r in report["generate"] + [report["edit"]]:
        assert r["runs"] == 2 and 0 < r["p50_ms"] <= r["p95_ms"] and r["frames_per_s"] > 0
    assert report["edit"]["untouched_change_cm"] < 1.0
    table = format_model_table(report)
    assert "generate 6 s" in table and "edit 1 part" in table and "targets" in table
    missing = run_model_bench(tmp_path / "none", runs=1)
    assert "error" in missing and "did not load" in format_model_table(missing)


def test_pair_bench_times_generation_and_the_finished_product(tmp_path):
    from interplay.bench.pair import format_pair_table, run_pair_bench
    report = run_pair_bench(runs=1, warmup=0, seconds=(2.0,))
    assert [r["frames"] for r in report["generate"]] == [40]
    assert report["product"]["frames"] == 120 and report["product"]["p50_ms"] > 0
    table = format_pair_table(report)
    assert "generate 2 s" in table and "+ finish 6 s" in table and "target" in table
    assert "did not load" in format_pair_table(run_pair_bench(tmp_path / "none", runs=1))


def test_default_bench_times_the_router_and_its_ik_edit():
    from interplay.bench.model import format_default_table, run_default_bench
    report = run_default_bench(runs=2, warmup=0, seconds=(2.0,))
    assert [r["frames"] for r in report["generate"]] == [40]
    assert report["edit"]["generator"] == "ik_pose" and report["edit"]["runs"] == 2
    table = format_default_table(report)
    assert "generate 2 s" in table and "edit 1 part 6 s" in table
