"""The data build on the committed raw fixtures (the same folder layout as ../shared/data),
and invariants of the processed set the app ships."""

from pathlib import Path

import numpy as np
import pytest

from interplay.data import build
from interplay.data.licences import is_noncommercial, licences_of
from interplay.motion import skeleton as sk
from interplay.motion.clip import DATA_DIR, default_clips, load_clips

RAW = Path(__file__).resolve().parents[1] / "fixtures" / "raw"


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    out = tmp_path_factory.mktemp("data")
    build.SKIPPED.clear()
    assert build.main(["--source", str(RAW), "--out", str(out), "--composed", "2"]) == 0
    return out, load_clips(out)


def test_build_reads_every_source_and_leaves_out_broken_trials(built):
    out, clips = built
    assert {c.source for c in clips} - {"composed"} == {"cmu-bvh", "cmu-salsa", "hdm05", "cmu-8action",
                                                       "bandai-namco", "cmu-iclone", "cmu-asfamc",
                                                       "deepmimic"}
    assert "cmu:07_12" not in {c.id for c in clips}  # broken root track
    assert any("07_12" in f for f, _ in build.SKIPPED)
    # One capture once: CC_Base's 02_01 is cmu-bvh's 02_01.
    assert "cmu-iclone:02_01" not in {c.id for c in clips}
    assert any(f.endswith("002_01.bvh") and "cmu-bvh/02/02_01.bvh" in r[0] for f, r in build.SKIPPED)
    salsa = [c for c in clips if c.source == "cmu-salsa"]
    assert salsa and all(len(c.people) == 2 for c in salsa)
    card = (out / "README.md").read_text()
    assert "07_12" in card and "CC BY-SA 3.0" in card
    assert f"| **all** | | {len(clips)} |" in card
    # HDM05-derived data stays in its own file.
    assert {c.licence for c in clips if c.source == "hdm05"} == {"CC BY-SA 3.0 (HDM05)"}
    assert (out / "hdm05.npz").exists()
    # Bandai Namco is non-commercial, in its own file, and never a composed clip's base.
    assert {c.licence for c in clips if c.source == "bandai-namco"} == {"CC BY-NC 4.0 (Bandai Namco)"}
    assert (out / "bandai-namco.npz").exists() and (out / "deepmimic.npz").exists()
    assert not any(is_noncommercial(c.licence) for c in clips if c.source == "composed")
    assert "CC BY-NC 4.0" in card and "MIT" in card and "Hours per action family" in card


def test_build_newer_sources_labels_and_evidence(built):
    _, clips = built
    by_id = {c.id: c for c in clips}
    wave = by_id["bandai:dataset-2_wave-right-hand_normal_001"]
    assert wave.prompt == "a person waves with the right hand" and wave.meta["content"] == "wave-right-hand"
    assert by_id["cmu-iclone:06_08"].prompt == "a person dribbles a basketball sideways"
    assert by_id["cmu-asfamc:11_01"].prompt == "a person kicks a soccer ball"
    assert by_id["deepmimic:backflip"].prompt == "a person does a backflip"
    for c in (wave, by_id["cmu-iclone:06_08"], by_id["cmu-asfamc:11_01"], by_id["deepmimic:jump"]):
        assert c.meta["fps_evidence"] and c.meta["contact_check"] and c.meta["defects"] == [], c.id
        assert c.meta["source_fps"] == {"bandai-namco": 30, "cmu-iclone": 60, "cmu-asfamc": 120,
                                        "deepmimic": 60}[c.source]

def test_build_labels_and_captions(built):
    _, clips = built
    by_id = {c.id: c for c in clips}
    assert by_id["cmu:02_01"].prompt == "a person walks forward"
    assert by_id["salsa:01"].prompt == "two people dance salsa"
    assert all(c.prompt and c.captions for c in clips)
    assert all(cap.part in ("body",) + sk.PART_NAMES for c in clips for cap in c.captions)


def test_build_composes_synthetic_pairs_from_bases_of_the_same_split(built):
    out, clips = built
    real = {c.id: c for c in clips if not c.synthetic}
    composed = [c for c in clips if c.source == "composed"]
    # The fixtures' train split has quiet standing and walks; val/test may have none (skipped).
    assert {c.meta["kind"] for c in composed if c.split == "train"} >= {"handshake", "walk_side_by_side"}
    for c in composed:
        assert c.synthetic and len(c.people) == 2 and c.frames == 80 and c.captions
        assert all(real[b["clip"]].split == c.split for b in c.meta["bases"])
    card = (out / "README.md").read_text()
    assert "Composed two-person clips" in card and f"{len(composed)} synthetic clips" in card


def test_stratified_split_is_by_trial_and_stable():
    ids = {"walk": [f"w{i}" for i in range(20)], "jump": ["j1", "j2", "j3"], "solo": ["s1"]}
    a, b = build.stratified_split(ids), build.stratified_split(ids)
    assert a == b
    walk = [a[i] for i in ids["walk"]]
    assert walk.count("test") == 3 and walk.count("val") == 2
    assert [a[i] for i in ids["jump"]].count("test") == 1
    assert a["s1"] == "train"


def test_processed_set_invariants():
    clips = default_clips()
    assert len(clips) > 1000
    # Every source in its own file, every licence known; ≥ 1.2 h of real single-person capture.
    assert {c.source for c in clips} == {p.stem for p in DATA_DIR.glob("*.npz")}
    assert all(licences_of(c.licence) for c in clips)
    single = sum(c.frames for c in clips if not c.synthetic and len(c.people) == 1)
    assert single / sk.FPS / 3600 >= 1.2
    assert not any(is_noncommercial(c.licence) for c in clips if c.source == "composed")
    # Bandai Namco's takes: every content with ≥ 3 takes has unseen takes in test.
    takes: dict = {}
    for c in clips:
        if c.source == "bandai-namco":
            takes.setdefault((c.meta["dataset"], c.meta["content"]), []).append(c.split)
    assert all("test" in s for s in takes.values() if len(s) >= 3)
    splits = {c.split for c in clips}
    assert splits == {"train", "val", "test"}
    hdm_test = {c.meta["actor"] for c in clips if c.source == "hdm05" and c.split == "test"}
    assert hdm_test == {build.HDM05_TEST_ACTOR}
    for c in clips:
        for joints, offsets in zip(c.people, c.offsets):
            assert joints.shape[1:] == (sk.NUM_JOINTS, 3) and np.isfinite(joints).all()
            lengths = sk.bone_lengths(joints)
            # float16 storage: bones stay within a few millimetres of the person's offsets.
            want = np.linalg.norm(offsets[1:], axis=-1)
            assert np.abs(lengths - want).max() < 0.01, c.id
        # Canonical frame: floor at 0 (lowest 2% of frames), first person starts at the origin.
        lowest = np.concatenate([p[:, :, 1].min(axis=1) for p in c.people])
        assert abs(np.percentile(lowest, 2)) < 0.01, c.id
        assert np.abs(c.people[0][0, sk.PELVIS, [0, 2]]).max() < 0.01, c.id
