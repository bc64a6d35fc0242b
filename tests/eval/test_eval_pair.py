"""`interplay eval-pair` on a tiny subset: the table's sets and columns, real vs retrieval,
rows without weights listed as skipped, the contact windows from the composed data, CLI."""

from __future__ import annotations

import json

import numpy as np

from interplay.cli.main import main
from interplay.eval.pair import SCORES, pair_set, window_scores
from interplay.eval.pair_report import contact_windows, format_table, run_eval_pair
from interplay.motion.clip import default_clips


def test_eval_pair_on_a_tiny_subset(tmp_path):
    report = run_eval_pair(("real", "retrieval", "coda"), repeats=2, limit=3, contact_seeds=1,
                           weights=tmp_path)                 # no CODA weights there
    assert report["skipped"] == {"coda": "no weights in models/weights/coda"}
    assert set(report["sets"]) == {"captured", "composed"}
    for res in report["sets"].values():
        assert res["windows"] == 3 and set(res["rows"]) == {"real", "retrieval"}
        for cells in res["rows"].values():
            assert set(cells) == {"fid", *SCORES}
            assert all(np.isfinite(v).all() and v[1] >= 0 for v in cells.values())
    # captured salsa windows: retrieval composes no bodies into each other more than they are
    real = report["sets"]["captured"]["rows"]["real"]
    assert real["bone_deviation"][0] < 0.005           # captured bones barely stretch
    kinds = report["contact"]["kinds"]
    assert {"handshake", "high_five", "hug"} <= set(kinds)
    assert all(k["shares"]["real"] == 1.0 for k in kinds.values())   # the check sees the touch
    table = format_table(report)
    assert "composed, SYNTHETIC" in table and "skipped coda" in table and "hug" in table


def test_contact_windows_cover_the_composed_touches():
    clips = default_clips()
    windows = contact_windows(clips)
    for _kind, info in windows.items():
        lo, hi = info["window"]
        for cid in info["clips"]:
            c = next(x for x in clips if x.id == cid)
            assert lo <= c.meta["contact"]["start"] and c.meta["contact"]["end"] <= hi


def test_window_scores_see_an_overlap():
    test = pair_set("test")
    w = test.windows[0].copy()
    apart, inside = w.copy(), w.copy()
    apart[1, ..., 0] += 5.0                               # 5 m apart: no touch, no overlap
    inside[1] = inside[0]                                 # one body inside the other
    s_apart, s_inside = window_scores(apart), window_scores(inside)
    assert s_apart[0] == 0 and s_apart[2] == 0 and s_apart[5] == 0
    assert s_inside[0] > 1000 and s_inside[1] == 1.0 and s_inside[5] > 5


def test_cli_eval_pair(capsys):
    assert main(["eval-pair", "--json", "--rows", "real", "--repeats", "2", "--limit", "2",
                 "--contact-seeds", "0"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert set(report["sets"]["composed"]["rows"]) == {"real"} and "contact" not in report
    assert main(["eval-pair", "--rows", "nope"]) == 2
    assert "unknown row" in capsys.readouterr().err


def test_coda_rows_raw_and_product_see_the_same_samples():
    from interplay.eval.pair import load_row
    from interplay.eval.pair_report import touches
    from interplay.generators.coda.files import DEFAULT_DIR, FILES
    if not all((DEFAULT_DIR / f).is_file() for f in FILES):
        import pytest
        pytest.skip("no CODA weights committed yet")
    raw, product = load_row("coda_raw", []), load_row("coda", [])
    prompt = "two people shake hands"
    a, b = raw(prompt, 80, 3), product(prompt, 80, 3)
    assert np.array_equal(a, raw(prompt, 80, 3))
    # the product holds the feet and makes the touch on the raw sample; the raw one has none
    assert not touches(a, [12, 62]) and touches(b, [12, 62])
    assert window_scores(b)[3] < window_scores(a)[3]                 # foot skating
    assert np.abs(b[:, :, 0] - a[:, :, 0]).max() < 0.2               # the same pair, feet held
