"""`interplay edit` on a real capture: a part edit over a frame range writes a motion file that
keeps everything else; bad parts, ranges, files and missing SPAM weights exit with code 2."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest

from interplay.cli import main as cli
from interplay.generators.spam.runtime import DEFAULT_DIR
from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips
from interplay.motion.motion import Motion
from interplay.settings import get_settings


@pytest.fixture
def spam_dir(tmp_path, monkeypatch):
    """The committed graphs without their model card, so the CLI serves them even while they
    are the untrained placeholder."""
    d = tmp_path / "spam"
    shutil.copytree(DEFAULT_DIR, d, ignore=shutil.ignore_patterns("MODEL_CARD.md"))
    monkeypatch.setenv("INTERPLAY_SPAM_DIR", str(d))
    get_settings.cache_clear()
    yield d
    get_settings.cache_clear()


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    clips = default_clips()
    out = tmp_path_factory.mktemp("edit")
    one = next(c for c in clips if len(c.people) == 1 and "soccer" in c.prompt and c.frames >= 100)
    two = next(c for c in clips if len(c.people) == 2)
    paths = {}
    for name, clip in (("one", one), ("two", two)):
        m = Motion(people=[p[:100] for p in clip.people], prompt=clip.prompt, seed=1)
        paths[name] = out / f"{name}.json"
        paths[name].write_text(json.dumps(m.to_json()))
    return paths


def test_edit_writes_the_edited_motion(spam_dir, files, tmp_path, capsys):
    out = tmp_path / "edited.json"
    assert cli.main(["edit", str(files["one"]), "--part", "left_arm", "--prompt",
                     "raises the left arm", "--frames", "10:60", "--seed", "3",
                     "--out", str(out)]) == 0
    assert "untouched joints moved" in capsys.readouterr().err
    before = Motion.from_json(json.loads(files["one"].read_text())).people[0]
    after = Motion.from_json(json.loads(out.read_text()))
    edit = after.plan["edits"][-1]
    assert (edit["parts"], edit["frames"], edit["seed"]) == (["left_upper"], [10, 60], 3)
    assert after.seed == 3 and after.prompt and "foot_skating" in after.metrics
    j = after.people[0]
    assert j.shape == before.shape
    assert np.array_equal(j[:10], before[:10]) and np.array_equal(j[60:], before[60:])
    lower = list(sk.PART_JOINTS["left_lower"]) + list(sk.PART_JOINTS["right_lower"])
    assert np.abs(j[:, lower] - before[:, lower]).max() < 0.01


def test_edit_errors_exit_2(spam_dir, files, tmp_path, capsys, monkeypatch):
    out = str(tmp_path / "x.json")
    cases = [
        (["edit", str(files["one"]), "--part", "tail", "--prompt", "x", "--out", out], "body part"),
        (["edit", str(files["one"]), "--prompt", "x", "--frames", "10:500", "--out", out], "outside"),
        (["edit", str(files["two"]), "--prompt", "x", "--out", out], "one-person"),
        (["edit", str(tmp_path / "none.json"), "--prompt", "x", "--out", out], "no such file"),
        (["edit", str(files["one"]), "--prompt", " ", "--out", out], "prompt"),
    ]
    for argv, msg in cases:
        assert cli.main(argv) == 2, argv
        err = capsys.readouterr().err
        assert "interplay: error:" in err and msg in err, (argv, err)
    with pytest.raises(SystemExit) as exc:
        cli.main(["edit", str(files["one"]), "--prompt", "x", "--frames", "9", "--out", out])
    assert exc.value.code == 2
    monkeypatch.setenv("INTERPLAY_SPAM_DIR", str(tmp_path / "no-weights"))
    get_settings.cache_clear()
    assert cli.main(["edit", str(files["one"]), "--prompt", "x", "--out", out]) == 2
    assert "needs the SPAM model" in capsys.readouterr().err
