"""`interplay react actor.json --out pair.json [--no-guidance]` on a held-out captured actor."""

from __future__ import annotations

import json

import numpy as np
import pytest

from interplay.cli.main import main
from interplay.motion.clip import default_clips
from interplay.motion.metrics import clip_metrics
from interplay.reaction.session import WEIGHTS_DIR

pytestmark = pytest.mark.skipif(not (WEIGHTS_DIR / "arflow.onnx").exists(),
                                reason="no ARFlow weights")


def test_react_writes_a_pair(tmp_path, capsys):
    clip = next(c for c in default_clips() if c.split == "test" and len(c.people) == 2
                and not c.synthetic)
    actor = np.asarray(clip.people[0][:30])
    src = tmp_path / "actor.json"
    src.write_text(json.dumps({"fps": 20, "skeleton": "smpl22",
                               "people": [{"joints": actor.round(4).tolist()}]}))
    outs = {}
    for flag in ([], ["--no-guidance"]):
        out = tmp_path / f"pair{len(flag)}.json"
        assert main(["react", str(src), "--out", str(out), "--seed", "2", *flag]) == 0
        d = json.loads(out.read_text())
        assert len(d["people"]) == 2 and d["plan"]["mode"] == "react"
        np.testing.assert_allclose(d["people"][0]["joints"], actor, atol=1e-4)
        outs[bool(flag)] = [np.asarray(p["joints"], dtype=np.float64) for p in d["people"]]
    assert "wrote" in capsys.readouterr().err
    guided, plain = (clip_metrics(outs[k])["intersection_volume"] for k in (False, True))
    assert guided <= plain


def test_react_bad_file(tmp_path, capsys):
    assert main(["react", str(tmp_path / "none.json"), "--out", str(tmp_path / "o.json")]) == 2
    assert "no such file" in capsys.readouterr().err


def test_eval_react_real_row_on_val(capsys):
    """`interplay eval-react --split val --rows real`: the pair evaluator's FID of the train
    windows against the val windows, per set, and IF per composed kind."""
    assert main(["eval-react", "--split", "val", "--rows", "real", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["split"] == "val" and set(report["sets"]) == {"real", "synthetic"}
    for rows in report["sets"].values():
        assert rows["real"]["fid"] >= 0 and rows["real"]["fid_stats"] >= 0
    kinds = report["sets"]["synthetic"]["real"]["per_kind"]
    assert {"hug", "handshake"} <= set(kinds) and kinds["hug"]["if"] > kinds["wave"]["if"]


@pytest.mark.parametrize("args", [["--rows", "bogus"], ["--sampling", "guidance"],
                                  ["--sampling", "colour=3"], ["--sampling", "steps=0"]])
def test_eval_react_bad_options(args, capsys):
    assert main(["eval-react", *args]) == 2
    assert "error" in capsys.readouterr().err.lower()
