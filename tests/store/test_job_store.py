"""The job tables on SQLite and on a real PostgreSQL: admission is capped atomically, a job is
claimed once, events replay in order from any seq, a client's cancel ends a queued job at once
and flags a running one, a job whose process died is found (by pid on this host, by heartbeat
elsewhere) and ended once with its reason, old jobs' events are dropped but their rows stay,
and the retention policy deletes the oldest motions (not those a job still reads)."""

from __future__ import annotations

import subprocess
import sys
import threading
from datetime import datetime, timedelta, timezone

import numpy as np
import pytest
from sqlalchemy import update

from interplay.motion.skeleton import rest_joints
from interplay.settings import Settings
from interplay.store import JobStore, MotionRepository, Retention, make_engine, new_id
from interplay.store.jobs import Write, process_gone, process_name
from interplay.store.models import JobRow, MotionRow
from tests.helpers.postgres import reset


@pytest.fixture(params=["sqlite", "postgres"])
def engine(request, tmp_path):
    url = f"sqlite:///{tmp_path / 'jobs.db'}"
    if request.param == "postgres":
        url = Settings(database_url=request.getfixturevalue("pg_url")).db_url
    eng = make_engine(url)
    yield eng
    eng.dispose()


def _admit(store: JobStore, owner: str | None = None, max_active: int = 100, **spec) -> str | None:
    job_id = new_id()
    ok = store.admit(id=job_id, motion_id=new_id(), kind="generate", spec=spec or {"p": 1},
                     queue="embedded", owner=owner or process_name(), max_active=max_active)
    return job_id if ok else None


def test_admission_is_capped_even_when_requests_race(engine):
    store = JobStore(engine)
    results: list[str | None] = []
    lock = threading.Lock()

    def one():
        got = _admit(store, max_active=5)
        with lock:
            results.append(got)
    threads = [threading.Thread(target=one) for _ in range(12)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert sum(r is not None for r in results) == 5 and store.active_count() == 5
    rec = store.get(next(r for r in results if r))
    assert rec.state == "queued" and rec.attempts == 0 and rec.spec == {"p": 1}


def test_a_job_is_claimed_once_and_its_events_replay_in_order(engine):
    store = JobStore(engine)
    job = _admit(store)
    assert store.claim(job, "w1").attempts == 1
    assert store.claim(job, "w2") is None
    events = [{"type": "plan", "plan": {}}, {"type": "frames", "start": 0, "total": 2,
                                             "people": [[[[0.1, 0.2, 0.3]] * 22] * 2]}]
    store.write([Write(job, 0, events[:1]), Write(job, 1, events[1:])])
    store.write([Write(job, 2, [{"type": "done", "motion_id": "m", "frames": 2}], state="done")])
    assert store.events_after(job, 0)[:2] == events
    assert [e["type"] for e in store.events_after(job, 1)] == ["frames", "done"]
    rec = store.get(job)
    assert (rec.state, rec.events, rec.worker) == ("done", 3, "w1")
    # A finished job's end is not overwritten by a late write.
    store.write([Write(job, 3, None, state="failed", reason="late")])
    assert store.get(job).state == "done"


def test_cancel_ends_a_queued_job_at_once_and_flags_a_running_one(engine):
    store = JobStore(engine)
    event = {"type": "error", "message": "cancelled", "cancelled": True}
    queued, running = _admit(store), _admit(store)
    store.claim(running, "w")
    assert store.request_cancel(queued, event).state == "cancelled"
    assert store.events_after(queued, 0) == [event]
    assert store.claim(queued, "w") is None
    rec = store.request_cancel(running, event)
    assert rec.state == "running" and rec.cancel_requested
    assert store.cancel_requested([running, queued]) == {running}
    assert store.request_cancel("unknownjobidunknownjob", event) is None


def test_a_requeued_job_is_queued_again_once_with_its_restart_event(engine):
    store = JobStore(engine)
    job = _admit(store)
    store.claim(job, "w1")
    store.write([Write(job, 0, [{"type": "plan", "plan": {}}])])
    rec = store.get(job)
    event = {"type": "restart", "attempt": 2}
    assert store.requeue(rec, owner="o2", event=event)
    assert not store.requeue(rec, owner="o3", event=event)      # it changed since `rec`
    again = store.get(job)
    assert (again.state, again.worker, again.owner, again.events, again.started_at) == (
        "queued", None, "o2", 2, None)
    assert store.events_after(job, 0)[-1] == event
    assert not store.requeue(again, owner="o3", event=event)    # queued, not running


def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_a_dead_workers_job_is_found_and_failed_once_with_its_reason(engine):
    store = JobStore(engine)
    host = process_name().split(":")[0]
    dead = f"{host}:{_dead_pid()}:abcd"
    job, alive = _admit(store), _admit(store)
    store.claim(job, dead)
    store.claim(alive, process_name())
    store.write([Write(job, 0, [{"type": "plan", "plan": {}}])])
    assert process_gone(dead) and not process_gone(process_name())
    assert store.orphans(stale_s=30, grace_s=3) == []          # its heartbeat is still fresh
    old = datetime.now(timezone.utc) - timedelta(seconds=10)
    with engine.begin() as conn:
        conn.execute(update(JobRow).values(heartbeat_at=old))
    found = store.orphans(stale_s=30, grace_s=3)
    assert [r.id for r in found] == [job]                       # not the one this process runs
    event = {"type": "error", "stage": "worker", "message": "generation failed: it died"}
    assert store.end_with_event(found[0], from_states=("running",), state="failed",
                                reason="it died", event=event)
    assert not store.end_with_event(found[0], from_states=("running",), state="failed",
                                    reason="twice", event=event)
    rec = store.get(job)
    assert (rec.state, rec.reason, rec.events) == ("failed", "it died", 2)
    assert store.events_after(job, 0)[-1] == event
    # Silent for longer than the stale time: an orphan whatever its host says.
    with engine.begin() as conn:
        conn.execute(update(JobRow).values(heartbeat_at=old - timedelta(seconds=60)))
    assert [r.id for r in store.orphans(stale_s=30, grace_s=3)] == [alive]


def test_a_queued_embedded_job_of_a_dead_owner_is_taken_over_once(engine):
    store = JobStore(engine)
    host = process_name().split(":")[0]
    job = _admit(store, owner=f"{host}:{_dead_pid()}:abcd")
    with engine.begin() as conn:
        conn.execute(update(JobRow).values(
            heartbeat_at=datetime.now(timezone.utc) - timedelta(seconds=10)))
    (rec,) = store.orphans(stale_s=30, grace_s=3)
    assert store.adopt(rec, "me") and not store.adopt(rec, "someone else")
    assert store.get(job).owner == "me" and store.orphans(stale_s=30, grace_s=3) == []


def test_old_events_are_dropped_but_the_job_row_stays(engine):
    store = JobStore(engine)
    job = _admit(store)
    store.claim(job, "w")
    store.write([Write(job, 0, [{"type": "error", "message": "x"}], state="failed", reason="x")])
    assert store.prune_events(older_than_s=3600) == 0
    assert store.prune_events(older_than_s=0) == 1
    rec = store.get(job)
    assert rec.events_pruned and rec.state == "failed" and store.events_after(job, 0) == []


def _joints(n: int = 5) -> list[np.ndarray]:
    return [np.repeat(rest_joints()[None], n, axis=0).astype(np.float32)]


def test_retention_keeps_the_newest_motions_and_those_a_job_reads(engine):
    repo = MotionRepository(engine, Retention(max_motions=3))
    ids = [repo.create(prompt=f"m{i}", people=_joints(), seconds=0.25).id for i in range(3)]
    store = JobStore(engine)
    _admit(store, parent_id=ids[0])                 # an edit of the oldest is queued
    newer = [repo.create(prompt=f"n{i}", people=_joints(), seconds=0.25).id for i in range(2)]
    left = {m.id for m in repo.list(limit=10)}
    assert left == {ids[0], *newer}                  # 3 kept: the newest two and the one in use
    # One more: the oldest not in use goes, even as the parent of the new one (which stays).
    edit = repo.create(prompt="edit", people=_joints(), seconds=0.25, parent_id=newer[0])
    assert {m.id for m in repo.list(limit=10)} == {ids[0], newer[1], edit.id}
    assert repo.get(edit.id).parent_id is None
    # Off by default: nothing is deleted.
    plain = MotionRepository(engine)
    for _ in range(3):
        plain.create(prompt="x", people=_joints(), seconds=0.25)
    assert plain.enforce_retention() == 0 and len(plain.list(limit=50)) == 6


def test_retention_by_age_deletes_old_motions_and_old_jobs(engine):
    repo = MotionRepository(engine, Retention(max_age_s=3600))
    old = repo.create(prompt="old", people=_joints(), seconds=0.25)
    child = repo.create(prompt="child", people=_joints(), seconds=0.25, parent_id=old.id)
    store = JobStore(engine)
    job = _admit(store)
    store.claim(job, "w")
    store.write([Write(job, 0, [{"type": "done", "motion_id": "m", "frames": 1}], state="done")])
    long_ago = datetime.now(timezone.utc) - timedelta(days=2)
    with engine.begin() as conn:
        conn.execute(update(MotionRow).where(MotionRow.id == old.id).values(created_at=long_ago))
        conn.execute(update(JobRow).values(created_at=long_ago))
    assert repo.enforce_retention() == 1
    assert repo.get(old.id) is None and store.get(job) is None
    assert repo.get(child.id).parent_id is None      # the edit stays, without its parent



@pytest.mark.parametrize("backend", ["sqlite", "postgres"])
def test_processes_starting_together_make_the_tables_once(request, tmp_path, backend):
    """`serve --workers N` and workers start on one database at once: none fails to start."""
    code = "import sys; from interplay.store import make_engine; make_engine(sys.argv[1])"
    for i in range(3):
        url = f"sqlite:///{tmp_path / f'race{i}.db'}"
        if backend == "postgres":
            url = request.getfixturevalue("pg_url")
            reset(url)
            url = Settings(database_url=url).db_url
        procs = [subprocess.Popen([sys.executable, "-c", code, url], stderr=subprocess.PIPE,
                                  text=True) for _ in range(4)]
        errors = [p.communicate(timeout=120)[1] for p in procs]
        assert [p.returncode for p in procs] == [0] * 4, errors
