"""The `interplay` command on real prompts with the real generator: generate → metrics →
export, bench through the real HTTP API, and exit code 2 with a message for bad input."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

from interplay.cli import main as cli
from interplay.motion import skeleton as sk
from interplay.motion.formats.bvh import read_bvh
from interplay.motion.metrics import clip_metrics
from interplay.motion.motion import Motion


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    """Two generated motion files: one person (walk then jump) and two people (salsa)."""
    out = tmp_path_factory.mktemp("cli")
    files = {}
    for persons, prompt in [(1, "a person walks forward, then jumps"), (2, "two people dance salsa")]:
        path = out / f"m{persons}.json"
        assert cli.main(["generate", "--prompt", prompt, "--persons", str(persons),
                         "--seconds", "4", "--seed", "5", "--out", str(path)]) == 0
        files[persons] = path
    return files


def test_generate_writes_a_motion_file(made):
    for persons, path in made.items():
        m = Motion.from_json(json.loads(path.read_text()))
        assert len(m.people) == persons and m.frames == 80 and m.seed == 5
        assert m.plan["segments"] and m.prompt
        assert "foot_skating" in m.metrics
        for p in m.people:   # real captures: standing on the floor, bones a human's length
            assert abs(p[..., 1].min()) < 0.1
            assert 0.3 < np.median(sk.bone_lengths(p)[:, 3]) < 0.5   # left shin


def test_generate_is_reproducible_by_seed(made, tmp_path):
    again = tmp_path / "again.json"
    assert cli.main(["generate", "--prompt", "two people dance salsa", "--persons", "2",
                     "--seconds", "4", "--seed", "5", "--out", str(again)]) == 0
    a, b = (json.loads(p.read_text()) for p in (made[2], again))
    assert a["people"] == b["people"]


def test_metrics_table_and_json_agree_with_clip_metrics(made, capsys):
    assert cli.main(["metrics", str(made[2]), "--json"]) == 0
    got = json.loads(capsys.readouterr().out)
    people = Motion.from_json(json.loads(made[2].read_text())).people
    want = clip_metrics([p.astype(np.float64) for p in people])
    assert set(got) == set(want) and "intersection_volume" in got
    assert all(got[k] == pytest.approx(want[k], rel=1e-6, abs=1e-9) for k in want)
    assert cli.main(["metrics", str(made[1])]) == 0
    table = capsys.readouterr().out
    assert "1 person(s), 80 frames" in table and "foot_skating" in table
    assert "intersection_volume" not in table


@pytest.mark.parametrize("person", [0, 1])
def test_export_bvh_reads_back_to_the_same_joints(made, tmp_path, person):
    out = tmp_path / "p.bvh"
    assert cli.main(["export", str(made[2]), "--format", "bvh", "--out", str(out),
                     "--person", str(person)]) == 0
    bvh = read_bvh(out.read_text())
    joints = Motion.from_json(json.loads(made[2].read_text())).people[person]
    pos = bvh.positions()[:, [bvh.names.index(n) for n in sk.JOINT_NAMES]]
    assert pos.shape == joints.shape and np.abs(pos - joints).max() < 2e-3


def test_export_json_round_trips(made, tmp_path):
    out = tmp_path / "copy.json"
    assert cli.main(["export", str(made[1]), "--format", "json", "--out", str(out)]) == 0
    a, b = (Motion.from_json(json.loads(p.read_text())) for p in (made[1], out))
    assert np.array_equal(a.people[0], b.people[0]) and a.plan == b.plan


@pytest.mark.parametrize("mesh", [True, False])
def test_export_glb_holds_everyone_with_or_without_the_mesh(made, tmp_path, mesh):
    import pygltflib
    out = tmp_path / "m.glb"
    assert cli.main(["export", str(made[2]), "--format", "glb", "--out", str(out),
                     *([] if mesh else ["--no-mesh"])]) == 0
    data = out.read_bytes()
    assert data[:4] == b"glTF"
    doc = pygltflib.GLTF2.load_from_bytes(data)
    assert len(doc.skins) == 2 and len(doc.meshes) == (2 if mesh else 0)
    assert doc.animations[0].name == Motion.from_json(json.loads(made[2].read_text())).prompt


def test_bad_files_and_arguments_exit_2_with_a_message(made, tmp_path, capsys):
    bad_json = tmp_path / "bad.json"
    bad_json.write_text("{nope")
    not_motion = tmp_path / "nm.json"
    not_motion.write_text(json.dumps({"people": [{"joints": [[1, 2, 3]]}]}))
    cases = [
        (["metrics", str(tmp_path / "missing.json")], "no such file"),
        (["metrics", str(bad_json)], "not valid JSON"),
        (["metrics", str(not_motion)], "not a motion file"),
        (["export", str(made[1]), "--format", "bvh", "--person", "1", "--out",
          str(tmp_path / "x.bvh")], "1 person"),
        (["export", str(made[1]), "--format", "json", "--out", str(tmp_path / "no" / "x.json")],
         "no such directory"),
        (["generate", "--prompt", " ", "--out", str(tmp_path / "x.json")], "prompt"),
        (["generate", "--prompt", "a person walks", "--seconds", "30", "--out",
          str(tmp_path / "x.json")], "seconds"),
        (["generate", "--prompt", "x" * 501, "--out", str(tmp_path / "x.json")], "500"),
        (["bench", "--runs", "0"], "runs"),
    ]
    for argv, msg in cases:
        assert cli.main(argv) == 2, argv
        err = capsys.readouterr().err
        assert "interplay: error:" in err and msg in err, (argv, err)
    for argv in (["generate", "--prompt", "walk", "--persons", "3", "--out", "x.json"],
                 ["export", str(made[1]), "--format", "fbx", "--out", "x"], ["nothing"]):
        with pytest.raises(SystemExit) as exc:
            cli.main(argv)
        assert exc.value.code == 2 and "error" in capsys.readouterr().err


def test_the_installed_entry_point_reports_errors(tmp_path):
    r = subprocess.run([sys.executable, "-m", "interplay.cli.main", "metrics",
                        str(tmp_path / "none.json")], capture_output=True, text=True)
    assert r.returncode == 2 and "no such file" in r.stderr


def test_data_build_passes_its_arguments_on(monkeypatch):
    import interplay.data.build as build
    seen = []
    monkeypatch.setattr(build, "main", lambda argv: seen.append(argv) or 0)
    assert cli.main(["data", "build", "--only", "hdm05", "--out", "/tmp/x"]) == 0
    assert seen == [["--only", "hdm05", "--out", "/tmp/x"]]


def test_bench_times_real_jobs_through_http_and_websocket(capsys):
    assert cli.main(["bench", "--json", "--runs", "2", "--seconds", "2", "--warmup", "0"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert [r["persons"] for r in report["results"]] == [1, 2]
    for r in report["results"]:
        assert r["frames"] == 40 and len(r["samples"]) == 2
        for s in r["samples"]:
            assert 0 < s["first_frame_s"] <= s["complete_s"] < 60
        assert r["first_frame_s"]["p50"] <= r["first_frame_s"]["p95"]
