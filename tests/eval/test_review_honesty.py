"""`interplay review-eval --honesty`'s bookkeeping: an output's verdict is the worst of its
segments' last ones, and the table counts bad outputs that end ok and good ones that end failed."""

from __future__ import annotations

from interplay.eval.review import format_honesty, honesty_table, output_verdict, why_failed


def _seg(*verdicts, kind="evaluator", failed=None):
    return {"reviews": [{"verdict": v, "score_kind": kind, "instructions": [],
                         "checks": {"failed": failed or {}}} for v in verdicts]}


def test_an_output_is_as_bad_as_its_worst_segment():
    assert output_verdict({"segments": [_seg("correct", "ok"), _seg("ok")]}) == "ok"
    assert output_verdict({"segments": [_seg("ok"), _seg("unconfirmed")]}) == "unconfirmed"
    assert output_verdict({"segments": [_seg("not_covered"), _seg("correct", "failed")]}) == "failed"
    assert output_verdict({"segments": [_seg("ok"), _seg("correct")]}) == "correct"
    # a pair's interaction still missing its checks after its tries is a failure
    assert output_verdict({"segments": [_seg("ok", "correct", kind="interaction_checks")]}) == "failed"
    rv = {"segments": [_seg("correct", "failed", failed={"words": "…"})]}
    assert why_failed(rv) == ["words"]


def test_the_table_counts_bad_ok_and_good_failed():
    rows = [{"persons": 1, "bad": True, "good": False, "verdict": "ok"},
            {"persons": 1, "bad": True, "good": False, "verdict": "failed"},
            {"persons": 1, "bad": False, "good": True, "verdict": "failed"},
            {"persons": 2, "bad": False, "good": True, "verdict": "ok"}]
    t = honesty_table(rows)
    assert t["one person"] | {"verdicts": None} == {"outputs": 3, "bad": 2, "bad_ok": 1, "good": 1,
                                                    "good_failed": 1, "verdicts": None}
    assert t["all"]["good"] == 2 and t["all"]["verdicts"]["failed"] == 2
    text = format_honesty({"outputs": 4, "seeds": 1, "elapsed_s": 1.0, "table": t})
    assert "1/2 = 50%" in text and "1/1 = 100%" in text
