"""persons: 2 jobs through the API: the router composes the interactions it knows from real
single-person clips (the plan says "compose" and what was composed), gives the rest to
retrieve-then-edit with the reason in the plan, and neither needs CODA's weights."""

from __future__ import annotations

from fastapi.testclient import TestClient

from interplay.api.app import create_app


def run_job(client: TestClient, **body) -> tuple[dict, list[dict]]:
    r = client.post("/api/jobs", json=body)
    assert r.status_code == 201, r.text
    events = []
    with client.websocket_connect(r.json()["stream"]) as ws:
        while not events or events[-1]["type"] not in ("done", "error"):
            events.append(ws.receive_json())
    return r.json(), events


def _plan(events) -> dict:
    return next(e for e in events if e["type"] == "plan")["plan"]


def test_two_person_job_is_composed(real_client):
    job, events = run_job(real_client, prompt="two people shake hands", persons=2, seconds=3,
                          seed=5)
    assert events[-1]["type"] == "done", events[-1]
    plan = _plan(events)
    assert plan["generator"] == "compose" and plan["composition"]["kind"] == "handshake"
    assert plan["sources"] and all(s["licence"] for s in plan["sources"])
    stored = real_client.get(f"/api/motions/{job['motion_id']}").json()
    assert len(stored["people"]) == 2 and len(stored["people"][0]["joints"]) == 60
    assert stored["metrics"]["contact_frames"] > 0
    assert len(stored["highlights"]["penetration"]) == 60


def test_what_composition_does_not_make_goes_to_retrieve_edit_without_coda(settings, tmp_path):
    empty = tmp_path / "no_coda"
    empty.mkdir()
    settings = settings.model_copy(update={"coda_dir": empty})
    with TestClient(create_app(settings)) as client:
        _, events = run_job(client, prompt="two people dance salsa", persons=2, seconds=2,
                            seed=1)
    assert events[-1]["type"] == "done", events[-1]
    plan = _plan(events)
    assert plan["generator"] == "retrieve_edit"
    assert "composition" in plan["generator_reason"]
