"""Each version keeps its review rounds (issue 26.3): a segment re-run, a part edit and a path
edit store the parent's review for the segments they left alone and, for the segments whose
frames they changed, the edit's own review (one round on the new frames, marked with what made
it); a path alone keeps every round of the parent."""

from __future__ import annotations

import pytest

from tests.helpers.api import run_job

PROMPT = "a person walks forward, then jumps, then sits down"


@pytest.mark.parametrize("settings", ["sqlite"], indirect=True)
def test_versions_keep_their_rounds_and_an_edit_gets_its_own_review(real_client):
    _, events = run_job(real_client, prompt=PROMPT, seconds=6, seed=1)
    parent = real_client.get(f"/api/motions/{events[-1]['motion_id']}").json()
    by_seg = {s["segment"]: s for s in parent["review"]["segments"]}
    assert set(by_seg) == {0, 1, 2}

    r = real_client.post(f"/api/motions/{parent['id']}/segments/1/rerun", json={"seed": 11})
    assert r.status_code == 201, r.text
    rerun = r.json()["review"]
    got = {s["segment"]: s for s in rerun["segments"]}
    assert got[0] == by_seg[0] and got[2] == by_seg[2]          # untouched: the parent's rounds
    assert got[1]["edit"] == {"kind": "rerun", "segment": 1, "seed": 11}
    assert [r["round"] for r in got[1]["reviews"]] == [0] and got[1]["corrections"] == []
    assert got[1]["reviews"][0]["verdict"] in ("ok", "correct", "failed", "not_covered")

    seg0 = parent["plan"]["segments"][0]
    frames = [seg0["start"] + 2, seg0["end"] - 2]
    r = real_client.post(f"/api/motions/{parent['id']}/edit",
                         json={"part": "left_arm", "prompt": "raises the left arm", "frames": frames,
                               "seed": 3})
    assert r.status_code == 201, r.text
    edited = {s["segment"]: s for s in r.json()["review"]["segments"]}
    assert edited[1] == by_seg[1] and edited[2] == by_seg[2]
    assert edited[0]["edit"] == {"kind": "edit", "part": "left_arm", "prompt": "raises the left arm",
                                 "frames": frames}
    review0 = edited[0]["reviews"][0]
    assert "left_arm" in review0["confirmed"]                   # the edit is judged as asked

    r = real_client.post(f"/api/motions/{parent['id']}/edit",
                         json={"trajectory": {"person": 0, "shape": "circle", "size_m": 2}})
    assert r.status_code == 201, r.text
    assert r.json()["review"]["segments"] == parent["review"]["segments"]
