"""POST /api/motions/{id}/edit on real captures: a new stored motion with parent_id, the edited
part/frames changed and the rest kept; 4xx (never 500) for bad ids, parts, ranges, prompts,
two-person motions, and when the generator cannot edit."""

from __future__ import annotations

import numpy as np
import pytest
from fastapi.testclient import TestClient

from interplay.api.app import create_app
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.generators.router import with_spam
from interplay.generators.spam.runtime import DEFAULT_DIR
from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips
from interplay.text.encoder import get_encoder


@pytest.fixture(scope="module")
def captures():
    clips = default_clips()
    one = next(c for c in clips if len(c.people) == 1 and "soccer" in c.prompt and c.frames >= 100)
    two = next(c for c in clips if len(c.people) == 2)
    return one, two


@pytest.fixture(scope="module")
def spam_generator(captures):
    # A small retrieval index is enough: edits only use SPAM (the committed graphs, trained or not).
    return with_spam(RetrievalIndex(list(captures), get_encoder()), DEFAULT_DIR, allow_untrained=True)


@pytest.fixture
def client(settings, spam_generator):
    with TestClient(create_app(settings, generator=spam_generator)) as c:
        yield c


def _store(client, clip, frames=100) -> str:
    people = [p[:frames] for p in clip.people]
    return client.app.state.repo.create(prompt=clip.prompt, people=people, seconds=frames / 20,
                                        seed=1, plan={"generator": "retrieval"}).id


def test_part_edit_is_stored_as_a_child_motion(client, captures):
    one, _ = captures
    mid = _store(client, one)
    r = client.post(f"/api/motions/{mid}/edit", json={"part": "left_arm", "frames": [10, 60],
                                                      "prompt": "raises the left arm", "seed": 3})
    assert r.status_code == 201, r.text
    m = r.json()
    assert m["parent_id"] == mid and m["id"] != mid and m["persons"] == 1 and m["seed"] == 3
    edit = m["plan"]["edits"][-1]
    assert (edit["part"], edit["parts"], edit["frames"]) == ("left_arm", ["left_upper"], [10, 60])
    assert m["plan"]["generator"] == "retrieval"          # the parent's plan, plus the edit
    assert "foot_skating" in m["metrics"] and len(m["highlights"]["contacts"]) == 100
    new = np.asarray(m["people"][0]["joints"])
    old = np.asarray(client.get(f"/api/motions/{mid}").json()["people"][0]["joints"])
    assert new.shape == old.shape == (100, 22, 3)
    assert np.array_equal(new[:10], old[:10]) and np.array_equal(new[60:], old[60:])
    arm = [sk.JOINT_INDEX[j] for j in ("left_elbow", "left_wrist")]
    assert np.abs(new[10:60, arm] - old[10:60, arm]).max() > 0.01
    keep = [j for j in range(22) if j not in arm + [sk.JOINT_INDEX["left_shoulder"]]]
    assert np.abs(new[:, keep] - old[:, keep]).max() < 0.01
    assert client.get(f"/api/motions/{m['id']}").json()["parent_id"] == mid


def test_whole_body_inbetween_by_default(client, captures):
    mid = _store(client, captures[0])
    r = client.post(f"/api/motions/{mid}/edit", json={"prompt": "a person jumps",
                                                      "frames": [40, 80]})
    assert r.status_code == 201, r.text
    m = r.json()
    assert m["plan"]["edits"][-1]["parts"] == list(sk.PART_NAMES) and m["seed"] is not None
    again = client.post(f"/api/motions/{m['id']}/edit", json={"prompt": "a person waves",
                                                              "part": "right_upper"})
    assert again.status_code == 201 and again.json()["parent_id"] == m["id"]
    assert len(again.json()["plan"]["edits"]) == 2


@pytest.mark.parametrize("body, status, words", [
    ({"part": "tail", "prompt": "wags"}, 422, "unknown body part"),
    ({"part": "left_arm", "prompt": "  "}, 422, "prompt"),
    ({"prompt": "x", "frames": [50, 20]}, 422, "frames"),
    ({"prompt": "x", "frames": [0, 101]}, 422, "outside"),
    ({"prompt": "x", "frames": [-1, 5]}, 422, "frames"),
    ({"prompt": "x", "frames": [1, 2, 3]}, 422, "frames"),
    ({"prompt": "x", "seed": -4}, 422, "seed"),
])
def test_bad_edit_requests_are_422(client, captures, body, status, words):
    mid = _store(client, captures[0])
    r = client.post(f"/api/motions/{mid}/edit", json=body)
    assert r.status_code == status and words in r.json()["detail"], r.text


def test_unknown_ids_two_people_and_generators_that_cannot_edit(client, captures, settings,
                                                                 spam_generator, monkeypatch):
    r = client.post("/api/motions/nope/edit", json={"prompt": "x"})
    assert r.status_code == 404 and "no motion" in r.json()["detail"]
    pair = _store(client, captures[1], frames=60)
    r = client.post(f"/api/motions/{pair}/edit", json={"prompt": "x"})
    assert r.status_code == 422 and "one-person" in r.json()["detail"]

    def broken(*a, **k):
        raise RuntimeError("onnxruntime exploded")
    monkeypatch.setattr(spam_generator.spam, "edit", broken)
    r = client.post(f"/api/motions/{_store(client, captures[0])}/edit", json={"prompt": "x"})
    assert r.status_code == 503 and "exploded" in r.json()["detail"]


def test_retrieval_only_generator_answers_503(fake_client):
    mid = fake_client.app.state.repo.create(prompt="p", people=[np.zeros((20, 22, 3))],
                                            seconds=1.0).id
    r = fake_client.post(f"/api/motions/{mid}/edit", json={"part": "left_arm", "prompt": "x"})
    assert r.status_code == 503 and "edit" in r.json()["detail"]


def test_bad_input_gets_its_4xx_while_the_generator_is_unavailable(settings, monkeypatch):
    import interplay.api.app as app_module

    def no_generator(_settings):
        raise FileNotFoundError("no weights here")
    monkeypatch.setattr(app_module, "_load_generator", no_generator)
    with TestClient(create_app(settings)) as c:
        mid = c.app.state.repo.create(prompt="p", people=[np.zeros((20, 22, 3))], seconds=1.0).id
        assert c.post(f"/api/motions/{mid}/edit", json={"part": "tail", "prompt": "x"}
                      ).status_code == 422
        assert c.post("/api/motions/nope/edit", json={"prompt": "x"}).status_code == 404
        r = c.post(f"/api/motions/{mid}/edit", json={"prompt": "x"})
        assert r.status_code == 503 and "no weights here" in r.json()["detail"]
