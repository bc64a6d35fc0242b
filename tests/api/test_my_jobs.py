"""GET /api/jobs?client=<id> (issue 26.2): a browser's generations that made no motion — queued,
running, failed, cancelled — newest first, each with the body to POST again (My motions'
Retry); done jobs, edits and other browsers' jobs are not listed; a malformed client id is 422."""

from __future__ import annotations

import time

import pytest

from interplay.api.events import ErrorEvent
from interplay.store import JobStore, make_engine

A, B = "a" * 22, "b" * 22


@pytest.mark.parametrize("settings", ["sqlite"], indirect=True)
def test_a_browser_lists_its_unfinished_jobs_with_the_request_to_retry(fake_client, settings):
    store = JobStore(make_engine(settings.db_url))

    def admit(n: int, client: str, state: str, kind: str = "generate", **spec) -> str:
        job = f"job{n}".ljust(22, "x")
        body = {"prompt": f"prompt {n}", "persons": 1, "seconds": 2.0, "seed": n, "mode": kind,
                "client_id": client, **spec}
        assert store.admit(id=job, motion_id=f"mot{n}".ljust(22, "x"), kind=kind, spec=body,
                           queue="embedded", owner="elsewhere:1:x", max_active=99)
        if state != "queued":
            rec = store.get(job)
            assert rec is not None
            store.end_with_event(rec, from_states=("queued",), state=state, reason=f"{state} here",
                                 event=ErrorEvent(message=state).dump())
        time.sleep(0.01)           # distinct creation times
        return job

    failed = admit(1, A, "failed", trajectory={"person": 0, "shape": "circle"})
    admit(2, A, "done")
    cancelled = admit(3, A, "cancelled")
    admit(4, B, "failed")
    admit(5, A, "failed", kind="edit", parent_id="p" * 22)
    react = admit(6, A, "failed", kind="react", actor_motion_id="m" * 22)
    queued = admit(7, A, "queued")
    r = fake_client.get("/api/jobs", params={"client": A})
    assert r.status_code == 200, r.text
    jobs = r.json()["jobs"]
    assert [j["job_id"] for j in jobs] == [queued, react, cancelled, failed]
    assert [j["status"] for j in jobs] == ["queued", "failed", "cancelled", "failed"]
    assert jobs[3]["reason"] == "failed here" and jobs[3]["prompt"] == "prompt 1"
    assert jobs[3]["request"] == {"prompt": "prompt 1", "persons": 1, "seconds": 2.0, "seed": 1,
                                  "trajectory": {"person": 0, "shape": "circle"}}
    assert jobs[1]["request"] == {"mode": "react", "actor_motion_id": "m" * 22,
                                  "prompt": "prompt 6", "seed": 6}
    assert fake_client.get("/api/jobs", params={"client": A, "limit": 2}).json()["jobs"][1]["job_id"] == react
    assert fake_client.get("/api/jobs", params={"client": "c" * 22}).json() == {"jobs": []}
    assert fake_client.get("/api/jobs", params={"client": "short"}).status_code == 422
    assert fake_client.get("/api/jobs").status_code == 422
