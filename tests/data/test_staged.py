"""Staged sources read from repository snapshots (`interplay data build --staged`), the
provenance manifest, the clear failure when a snapshot is absent, and the contact windows
measured on real two-person captures."""

import json
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from interplay.data import build, staged
from interplay.data.hunt import SOURCES_CONSIDERED
from interplay.data.licences import is_noncommercial
from interplay.data.mirror import Snapshot, SnapshotMissing
from interplay.data.pairs import contact_windows
from interplay.motion import skeleton as sk
from interplay.motion.clip import DATA_DIR, load_clips

RAW = Path(__file__).resolve().parents[1] / "fixtures" / "raw"


def _git(*args, cwd):
    subprocess.run(["git", *args], cwd=cwd, check=True, capture_output=True,
                   env={"GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@t", "GIT_COMMITTER_NAME": "t",
                        "GIT_COMMITTER_EMAIL": "t@t", "PATH": "/usr/bin:/bin"})


@pytest.fixture(scope="module")
def mirror(tmp_path_factory):
    """A mirror root holding a one-clip snapshot laid out like Bandai Namco's repository; the
    staged build is pointed at its commit."""
    root = tmp_path_factory.mktemp("mirror")
    work = tmp_path_factory.mktemp("work")
    shutil.copytree(RAW / "bandai-namco" / "dataset-2", work / staged.BANDAI.path)
    _git("init", "-q", cwd=work)
    _git("add", ".", cwd=work)
    _git("commit", "-q", "-m", "snapshot", cwd=work)
    commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=work, check=True, capture_output=True,
                            text=True).stdout.strip()
    dest = root / staged.BANDAI.repo.replace("/", "+") / "repo"
    subprocess.run(["git", "clone", "-q", "--bare", str(work), str(dest)], check=True)
    return root, Snapshot(staged.BANDAI.repo, commit, staged.BANDAI.path, staged.BANDAI.licence)


def test_an_absent_snapshot_fails_with_the_fetch_step(tmp_path, capsys):
    with pytest.raises(SnapshotMissing, match="fetch github:BandaiNamcoResearchInc"):
        staged.BANDAI.require(tmp_path)
    empty = tmp_path / "shared"
    empty.mkdir()
    assert build.main(["--staged", "--mirror", str(tmp_path), "--source", str(empty),
                       "--out", str(tmp_path / "out")]) == 2
    assert "not found" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_a_snapshot_lacking_the_commit_is_refused(mirror):
    root, snap = mirror
    with pytest.raises(SnapshotMissing, match="lacks commit"):
        Snapshot(snap.repo, "0" * 40, snap.path, snap.licence).require(root)


def test_staged_build_reads_the_snapshot_and_writes_its_own_index(mirror, tmp_path, monkeypatch):
    root, snap = mirror
    monkeypatch.setattr(staged, "BANDAI", snap)
    monkeypatch.setitem(staged.SNAPSHOTS, "bandai-namco-2", snap)
    empty = tmp_path / "shared"
    empty.mkdir()
    out = tmp_path / "staged"
    only = ["--only", "bandai-namco-2"]
    assert build.main(["--staged", "--mirror", str(root), "--source", str(empty), "--out", str(out), *only]) == 0
    clips = load_clips(out)
    assert [c.source for c in clips] == ["bandai-namco-2"]
    c = clips[0]
    assert c.id == "bandai2:dataset-2_wave-right-hand_normal_001" and is_noncommercial(c.licence)
    assert c.meta["repository"] == snap.repo and c.meta["commit"] == snap.commit
    assert c.meta["file"].startswith(snap.path + "/data/")
    assert c.people[0].shape[1:] == (sk.NUM_JOINTS, 3) and c.captions
    card = (out / "README.md").read_text()
    assert snap.commit in card and "not loaded by the app" in card and "CC BY-NC 4.0" in card
    # Clips ../shared/data already holds are the main build's, not staged again.
    assert build.main(["--staged", "--mirror", str(root), "--source", str(RAW), "--out", str(out), *only]) == 0
    assert json.loads((out / "index.json").read_text())["clips"] == []


def test_the_app_does_not_load_staged_sources():
    index = json.loads((DATA_DIR / "index.json").read_text())
    assert not any(m["file"].startswith("staged") or m["source"] in staged.SNAPSHOTS for m in index["clips"])
    card = (DATA_DIR / "README.md").read_text()
    assert SOURCES_CONSIDERED.splitlines()[0] in card and "LAFAN1" in card


def test_contact_windows_find_a_hand_on_the_other_persons_chest():
    rest = sk.rest_joints()
    t = 40
    a = np.repeat(rest[None], t, axis=0).copy()
    b = a.copy()
    b[..., 2] += 0.9                                    # b stands 0.9 m in front of a
    b[..., 0] += 0.0
    chest = b[0, sk.JOINT_INDEX["spine3"]]
    hand = sk.JOINT_INDEX["right_wrist"]
    # a's right wrist reaches b's chest for frames 10-29, and stays at its side otherwise.
    a[10:30, hand] = chest + np.array([0.0, 0.0, -0.12])
    windows = contact_windows(a, b)
    mine = [w for w in windows if w.person == 0]
    assert len(mine) == 1
    w = mine[0]
    assert (w.hand, w.start, w.end) == ("right", 10, 30) and w.part.endswith("upper")
    far = b.copy()
    far[..., 2] += 2.0
    assert contact_windows(a, far) == []
