"""The head as an editable part through POST /api/motions/{id}/edit and `interplay edit --part
head`: served by the head primitive (generators/primitives), never SPAM (these routers load no
SPAM at all); "look up" raises the head's pitch ≥ 25° over the stored motion on the edited
frames, every other joint stays within 2 cm (exactly, in fact); a nod is counted."""

from __future__ import annotations

import json

import numpy as np
import pytest
from fastapi.testclient import TestClient

from interplay.api.app import create_app
from interplay.cli import main as cli
from interplay.generators.primitives.head import pitch_yaw
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.generators.router import Router
from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips
from interplay.motion.motion import Motion
from interplay.motion.signals import runs
from interplay.text.encoder import get_encoder

OTHERS = [j for j in range(sk.NUM_JOINTS) if j != sk.HEAD]


@pytest.fixture(scope="module")
def walk():
    return next(c for c in default_clips() if len(c.people) == 1 and c.label == "walk"
                and c.frames >= 100)


@pytest.fixture(scope="module")
def router(walk):
    return Router(RetrievalIndex([walk], get_encoder()), spam=None, reason="no SPAM in this test")


@pytest.fixture
def client(settings, router):
    with TestClient(create_app(settings, generator=router)) as c:
        yield c


def test_head_edit_through_the_api(client, walk):
    people = [walk.people[0][:100]]
    mid = client.app.state.repo.create(prompt=walk.prompt, people=people, seconds=5.0, seed=1,
                                       plan={"generator": "retrieval"}).id
    r = client.post(f"/api/motions/{mid}/edit", json={"part": "head", "prompt": "look up",
                                                      "frames": [20, 80], "seed": 2})
    assert r.status_code == 201, r.text
    m = r.json()
    edit = m["plan"]["edits"][-1]
    assert (edit["generator"], edit["primitive"], edit["parts"]) == ("primitive", "look_up", ["head"])
    new = np.asarray(m["people"][0]["joints"], dtype=np.float64)
    old = np.asarray(people[0], dtype=np.float64)
    rise = pitch_yaw(new)[0] - pitch_yaw(old)[0]
    assert rise[30:70].min() >= 25.0
    assert np.linalg.norm(new[:, OTHERS] - old[:, OTHERS], axis=-1).max() <= 0.02
    assert np.abs(new[:20] - old[:20]).max() < 1e-4 and np.abs(new[80:] - old[80:]).max() < 1e-4
    r = client.post(f"/api/motions/{mid}/edit", json={"part": "head", "prompt": "nod twice"})
    assert r.status_code == 201, r.text
    new = np.asarray(r.json()["people"][0]["joints"], dtype=np.float64)
    assert len(runs(pitch_yaw(new)[0] - pitch_yaw(old)[0] < -12)) == 2
    r = client.post(f"/api/motions/{mid}/edit", json={"part": "head", "prompt": "kick with the right leg"})
    assert r.status_code == 422, r.text
    r = client.post(f"/api/motions/{mid}/edit", json={"part": "tail", "prompt": "look up"})
    assert r.status_code == 422 and "head" in r.text


def test_head_edit_through_the_cli(walk, tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("INTERPLAY_SPAM_DIR", str(tmp_path / "no-weights"))
    from interplay.settings import get_settings
    get_settings.cache_clear()
    src, out = tmp_path / "walk.json", tmp_path / "edited.json"
    src.write_text(json.dumps(Motion(people=[walk.people[0][:100]], prompt=walk.prompt, seed=1).to_json()))
    try:
        assert cli.main(["edit", str(src), "--part", "head", "--prompt", "shake your head three times",
                         "--frames", "10:90", "--out", str(out)]) == 0
    finally:
        get_settings.cache_clear()
    before = Motion.from_json(json.loads(src.read_text())).people[0].astype(np.float64)
    after = Motion.from_json(json.loads(out.read_text()))
    edit = after.plan["edits"][-1]
    assert (edit["primitive"], edit["count"], edit["frames"]) == ("shake_head", 3, [10, 90])
    j = after.people[0].astype(np.float64)
    assert np.abs(j[:, OTHERS] - before[:, OTHERS]).max() < 1e-5
    yaw = pitch_yaw(j)[1] - pitch_yaw(before)[1]
    assert len(runs(yaw > 15)) == 3 and len(runs(yaw < -15)) == 3
