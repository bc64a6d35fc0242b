"""`interplay edit --trajectory` (a preset shape or a drawn-points file, no model needed) and
`interplay review-eval` (the reviewer's before/after table)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from interplay.cli import main as cli
from interplay.motion.clip import default_clips
from interplay.motion.motion import Motion


@pytest.fixture(scope="module")
def walk_file(tmp_path_factory):
    clip = next(c for c in default_clips() if c.label == "walk" and c.frames >= 100)
    path = tmp_path_factory.mktemp("walk") / "walk.json"
    path.write_text(json.dumps(Motion(people=[clip.people[0][:100]], prompt=clip.prompt,
                                      seed=1).to_json()))
    return path


def _pelvis(path) -> np.ndarray:
    return Motion.from_json(json.loads(path.read_text())).people[0][:, 0]


def test_edit_follows_a_preset_shape(walk_file, tmp_path, capsys):
    out = tmp_path / "circle.json"
    assert cli.main(["edit", str(walk_file), "--trajectory", "circle", "--out", str(out)]) == 0
    assert "follows circle" in capsys.readouterr().err
    before, after = _pelvis(walk_file), _pelvis(out)
    assert after.shape == before.shape
    edit = Motion.from_json(json.loads(out.read_text())).plan["edits"][-1]
    assert edit == {"trajectory": {"person": 0, "shape": "circle"}}
    # A circle turns the walk: the heading of the path sweeps far more than a straight walk's.
    def sweep(p):
        d = np.diff(p[::10][:, [0, 2]], axis=0)
        return np.abs(np.diff(np.unwrap(np.arctan2(d[:, 0], d[:, 1])))).sum()
    assert sweep(after) > sweep(before) + np.pi / 2


def test_edit_follows_drawn_points(walk_file, tmp_path):
    pts = [[0.0, 0.0], [0.0, 1.5], [1.5, 3.0]]
    (tmp_path / "path.json").write_text(json.dumps(pts))
    out = tmp_path / "drawn.json"
    assert cli.main(["edit", str(walk_file), "--trajectory", str(tmp_path / "path.json"),
                     "--out", str(out)]) == 0
    p = _pelvis(out)
    assert np.linalg.norm(p[0, [0, 2]] - pts[0]) < 0.3      # starts where the drawing starts


@pytest.mark.parametrize("argv,msg", [
    (["--trajectory", "pentagon"], "shape"),
    (["--trajectory", "missing.json"], "missing.json"),
    (["--trajectory", "circle", "--person", "1"], "person 1"),
    ([], "--prompt, --trajectory"),
])
def test_edit_trajectory_errors_exit_2(walk_file, tmp_path, capsys, argv, msg):
    out = str(tmp_path / "x.json")
    assert cli.main(["edit", str(walk_file), *argv, "--out", out]) == 2
    err = capsys.readouterr().err
    assert "interplay: error:" in err and msg in err, err


def test_review_eval_prints_the_before_after_table(capsys):
    assert cli.main(["review-eval", "--limit", "1", "--seconds", "4", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["prompts"] == 1 and report["rounds"] == 2
    t = report["table"]
    for side in ("before", "after"):
        assert {"score", "confirmed_share", "foot_skating", "ground_penetration",
                "com_lean"} <= set(t[side])
    assert t["after"]["score"] >= t["before"]["score"]       # a correction never lowers it
    assert report["rows"][0]["prompt"].startswith("Thierry Henry")
