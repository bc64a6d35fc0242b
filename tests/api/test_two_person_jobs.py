"""persons: 2 jobs through the API: CODA generates them when its weights load (the plan says
"coda"), and retrieval serves them with the reason in the plan when the weights dir is empty."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from interplay.api.app import create_app
from interplay.generators.coda.files import DEFAULT_DIR, FILES
from interplay.generators.weights import placeholder_reason

HAVE_CODA = all((DEFAULT_DIR / f).is_file() for f in FILES) and placeholder_reason(DEFAULT_DIR, "CODA") is None


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


@pytest.mark.skipif(not HAVE_CODA, reason="no trained CODA weights committed yet")
def test_two_person_job_is_generated_by_coda(real_client):
    job, events = run_job(real_client, prompt="two people shake hands", persons=2, seconds=3,
                          seed=5)
    assert events[-1]["type"] == "done", events[-1]
    plan = _plan(events)
    assert plan["generator"] == "coda" and plan["model"]["name"] == "coda"
    stored = real_client.get(f"/api/motions/{job['motion_id']}").json()
    assert len(stored["people"]) == 2 and len(stored["people"][0]["joints"]) == 60
    assert {"intersection_volume", "contact_frames"} <= set(stored["metrics"])
    assert len(stored["highlights"]["penetration"]) == 60


def test_two_person_job_falls_back_to_retrieval_with_a_reason(settings, tmp_path):
    empty = tmp_path / "no_coda"
    empty.mkdir()
    settings = settings.model_copy(update={"coda_dir": empty})
    with TestClient(create_app(settings)) as client:
        _, events = run_job(client, prompt="two people dance salsa", persons=2, seconds=2,
                            seed=1)
    assert events[-1]["type"] == "done", events[-1]
    plan = _plan(events)
    assert plan["generator"] == "retrieval"
    assert "CODA" in plan["generator_reason"] and str(empty) in plan["generator_reason"]
