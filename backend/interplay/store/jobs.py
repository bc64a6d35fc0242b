"""Durable jobs: the `jobs` and `job_events` tables behind the API's job queue.

A job row holds the request (`spec`), its state (queued → running → done | failed |
cancelled) with the reason it ended, who admitted it (`owner`) and who runs it (`worker`),
and how many events it has streamed; every event is a `job_events` row, so a stream opened
on any process, or after a restart, replays the job from its first event.

Process names are `host:pid:token` (`process_name()`): a job whose worker's process is gone
(same host, pid not alive, or this very pid with another token: the process was restarted) or
whose heartbeat is older than the stale time is an orphan, found by `orphans()`: queued again
(`requeue()`, with a `restart` event) or, after its last attempt, ended (`end_with_event()`). On PostgreSQL every write that adds events or ends a job sends
`NOTIFY interplay_jobs, '<job id>'` in its transaction, so listeners wake as soon as it commits.
"""

from __future__ import annotations

import json
import os
import secrets
import socket
import threading
from dataclasses import dataclass
from datetime import datetime, timedelta, timezone
from typing import Any

from sqlalchemy import ColumnElement, Engine, delete, func, insert, literal, select, text, update
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session

from interplay.store.models import JobEventRow, JobRow
from interplay.store.repository import valid_id

ACTIVE = ("queued", "running")
TERMINAL = ("done", "failed", "cancelled")
CHANNEL = "interplay_jobs"
ADMIT_LOCK = 0x1A7E4D       # pg_advisory_xact_lock key serialising admissions

_HOST = socket.gethostname()
_TOKEN = secrets.token_hex(4)


def process_name() -> str:
    """This process's name as a job owner or worker: `host:pid:token` (the token tells a
    restarted process that reuses a pid from the one before it)."""
    return f"{_HOST}:{os.getpid()}:{_TOKEN}"


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    try:   # a killed child its parent has not reaped yet is a zombie: gone all the same
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rpartition(")")[2].split()[0] != "Z"
    except (OSError, IndexError):
        return True


def process_gone(name: str | None) -> bool:
    """Whether the process `name` certainly no longer runs (known only on this host)."""
    if not name:
        return False
    host, _, rest = name.partition(":")
    pid_text, _, token = rest.partition(":")
    if host != _HOST or not pid_text.isdigit():
        return False
    pid = int(pid_text)
    if pid == os.getpid():
        return token != _TOKEN
    return not _pid_alive(pid)


def _my_pid(name: str | None) -> bool:
    """Whether `name` has this process's host and pid (then it is this process, or the one
    before a restart that reused the pid)."""
    parts = (name or "").split(":")
    return len(parts) == 3 and parts[0] == _HOST and parts[1] == str(os.getpid())


def _now() -> datetime:
    return datetime.now(timezone.utc)


def _aware(dt: datetime | None) -> datetime | None:
    return None if dt is None else (dt if dt.tzinfo else dt.replace(tzinfo=timezone.utc))


@dataclass(frozen=True)
class JobRecord:
    id: str
    motion_id: str
    kind: str
    spec: dict
    state: str
    reason: str | None
    result: dict | None
    queue: str
    owner: str
    worker: str | None
    attempts: int
    cancel_requested: bool
    events: int
    events_pruned: bool
    created_at: datetime
    started_at: datetime | None
    finished_at: datetime | None
    heartbeat_at: datetime

    @property
    def finished(self) -> bool:
        return self.state in TERMINAL


def _record(row: JobRow) -> JobRecord:
    return JobRecord(id=row.id, motion_id=row.motion_id, kind=row.kind, spec=row.spec,
                     state=row.state, reason=row.reason, result=row.result, queue=row.queue,
                     owner=row.owner, worker=row.worker, attempts=row.attempts or 0,
                     cancel_requested=bool(row.cancel_requested), events=row.events or 0,
                     events_pruned=bool(row.events_pruned),
                     created_at=_aware(row.created_at) or _now(),
                     started_at=_aware(row.started_at), finished_at=_aware(row.finished_at),
                     heartbeat_at=_aware(row.heartbeat_at) or _now())


@dataclass
class Write:
    """One step of a batched write: events appended from `seq` on, and/or the job ended."""
    job_id: str
    seq: int = 0
    events: list[dict] | None = None
    state: str | None = None          # a terminal state: the job ends with this write
    reason: str | None = None
    result: dict | None = None


class JobStore:
    """Every query on the job tables. Methods are synchronous (call them from a thread)."""

    def __init__(self, engine: Engine):
        self.engine = engine
        self.postgres = engine.dialect.name == "postgresql"
        self._admit_lock = threading.Lock()

    # -- admission and lookups ----------------------------------------------------------------

    def admit(self, *, id: str, motion_id: str, kind: str, spec: dict, queue: str, owner: str,
              max_active: int) -> bool:
        """Insert a queued job unless `max_active` jobs are already queued or running (then
        False). Atomic across processes: one INSERT … SELECT … WHERE count < max (SQLite takes
        its write lock for the statement), under an advisory lock on PostgreSQL."""
        now = _now()
        values = {"id": id, "motion_id": motion_id, "kind": kind, "spec": spec,
                  "state": "queued", "queue": queue, "owner": owner, "attempts": 0,
                  "cancel_requested": False, "events": 0, "events_pruned": False,
                  "created_at": now, "heartbeat_at": now}
        cols = JobRow.__table__.c
        active = (select(func.count()).select_from(JobRow)
                  .where(JobRow.state.in_(ACTIVE)).scalar_subquery())
        source = select(*[literal(v, type_=cols[k].type) for k, v in values.items()]
                        ).where(active < max_active)
        stmt = insert(JobRow).from_select(list(values), source)
        with self._admit_lock, self.engine.begin() as conn:
            if self.postgres:
                conn.execute(text("SELECT pg_advisory_xact_lock(:k)"), {"k": ADMIT_LOCK})
            conn.execute(stmt)   # (rowcount of INSERT … SELECT is not reported by every driver)
            return conn.scalar(select(func.count()).select_from(JobRow)
                               .where(JobRow.id == id)) == 1

    def get(self, job_id: str) -> JobRecord | None:
        if not valid_id(job_id):
            return None
        with Session(self.engine) as session:
            row = session.get(JobRow, job_id)
            return _record(row) if row is not None else None

    def by_motion(self, motion_id: str) -> JobRecord | None:
        """The job that makes (or made) the motion `motion_id`."""
        if not valid_id(motion_id):
            return None
        with Session(self.engine) as session:
            row = session.scalars(select(JobRow).where(JobRow.motion_id == motion_id)).first()
            return _record(row) if row is not None else None

    def active_count(self) -> int:
        with Session(self.engine) as session:
            return session.scalar(select(func.count()).select_from(JobRow)
                                  .where(JobRow.state.in_(ACTIVE))) or 0

    def active(self) -> list[JobRecord]:
        """Every queued or running job (few: admission bounds them)."""
        with Session(self.engine) as session:
            return [_record(r) for r in session.scalars(
                select(JobRow).where(JobRow.state.in_(ACTIVE)).order_by(JobRow.created_at))]

    def for_client(self, client_id: str, limit: int = 20, scan: int = 500) -> list[JobRecord]:
        """The generate and react jobs `client_id` asked for that made no motion (yet): queued,
        running, failed or cancelled, newest first (among the newest `scan` such jobs)."""
        with Session(self.engine) as session:
            rows = session.scalars(
                select(JobRow).where(JobRow.state != "done", JobRow.kind.in_(("generate", "react")))
                .order_by(JobRow.created_at.desc()).limit(scan))
            out = [_record(r) for r in rows if (r.spec or {}).get("client_id") == client_id]
        return out[:limit]

    def recent_run_seconds(self, limit: int = 20) -> list[float]:
        """How long the last `limit` finished jobs ran (start to finish), newest first."""
        with Session(self.engine) as session:
            rows = session.execute(
                select(JobRow.started_at, JobRow.finished_at)
                .where(JobRow.state == "done", JobRow.started_at.is_not(None))
                .order_by(JobRow.finished_at.desc()).limit(limit)).all()
        out = []
        for started, finished in rows:
            s, f = _aware(started), _aware(finished)
            if s is not None and f is not None:
                out.append(max(0.0, (f - s).total_seconds()))
        return out

    # -- running --------------------------------------------------------------------------------

    def claim(self, job_id: str, worker: str) -> JobRecord | None:
        """queued → running for `worker` (attempts + 1); None when the job is not queued any
        more (cancelled, ended by a reaper, or claimed by someone else)."""
        now = _now()
        with Session(self.engine) as session:
            done = session.execute(
                update(JobRow).where(JobRow.id == job_id, JobRow.state == "queued")
                .values(state="running", worker=worker, attempts=JobRow.attempts + 1,
                        started_at=now, heartbeat_at=now))
            session.commit()
            if done.rowcount != 1:   # type: ignore[attr-defined]
                return None
            row = session.get(JobRow, job_id)
            return _record(row) if row is not None else None

    def heartbeat(self, job_ids: list[str]) -> None:
        if not job_ids:
            return
        with Session(self.engine) as session:
            session.execute(update(JobRow).where(JobRow.id.in_(job_ids),
                                                 JobRow.state.in_(ACTIVE))
                            .values(heartbeat_at=_now()))
            session.commit()

    def cancel_requested(self, job_ids: list[str]) -> set[str]:
        """Which of `job_ids` a client asked to cancel (through any process)."""
        if not job_ids:
            return set()
        with Session(self.engine) as session:
            return set(session.scalars(select(JobRow.id).where(JobRow.id.in_(job_ids),
                                                               JobRow.cancel_requested)))

    def write(self, writes: list[Write]) -> None:
        """Append events and end jobs, in order, in one transaction (NOTIFY on PostgreSQL).
        A job already ended by someone else (a reaper) keeps its end; if the batch collides
        with events a reaper appended, each job's writes are retried alone and the colliding
        ones dropped."""
        if not writes:
            return
        try:
            self._write(writes)
        except IntegrityError:
            for w in writes:
                try:
                    self._write([w])
                except IntegrityError:
                    pass

    def _write(self, writes: list[Write]) -> None:
        now = _now()
        touched: list[str] = []
        with self.engine.begin() as conn:
            for w in writes:
                if w.events:
                    conn.execute(insert(JobEventRow), [
                        {"job_id": w.job_id, "seq": w.seq + i,
                         "body": json.dumps(e, separators=(",", ":"), allow_nan=False)}
                        for i, e in enumerate(w.events)])
                    conn.execute(update(JobRow).where(JobRow.id == w.job_id)
                                 .values(events=w.seq + len(w.events), heartbeat_at=now))
                if w.state is not None:
                    conn.execute(update(JobRow).where(JobRow.id == w.job_id,
                                                      JobRow.state.in_(ACTIVE))
                                 .values(state=w.state, reason=w.reason, result=w.result,
                                         finished_at=now))
                if w.job_id not in touched:
                    touched.append(w.job_id)
            self._notify(conn, touched)

    def _notify(self, conn, job_ids: list[str]) -> None:
        if self.postgres:
            for job_id in job_ids:
                conn.execute(text("SELECT pg_notify(:c, :p)"), {"c": CHANNEL, "p": job_id})

    def events_after(self, job_id: str, seq: int) -> list[dict]:
        """The job's stored events from `seq` on, in order."""
        with Session(self.engine) as session:
            bodies = session.scalars(select(JobEventRow.body)
                                     .where(JobEventRow.job_id == job_id, JobEventRow.seq >= seq)
                                     .order_by(JobEventRow.seq))
            return [json.loads(b) for b in bodies]

    # -- ending jobs from outside ---------------------------------------------------------------

    def end_with_event(self, rec: JobRecord, *, from_states: tuple[str, ...], state: str,
                       reason: str, event: dict, result: dict | None = None) -> bool:
        """End `rec` (if it is still in one of `from_states`, with the `events` count it had)
        as `state`, its stream's last event `event`. False when something else changed it
        first."""
        return self._step(rec, JobRow.state.in_(from_states), event, state=state, reason=reason,
                          result=result, finished_at=_now())

    def requeue(self, rec: JobRecord, *, owner: str, event: dict) -> bool:
        """A running job whose process died, queued again (if it is still running with the
        `events` count it had) for `owner` to take, its stream's next event `event` (a
        `restart`). False when something else changed it first."""
        return self._step(rec, JobRow.state == "running", event, state="queued", worker=None,
                          owner=owner, heartbeat_at=_now(), started_at=None)

    def _step(self, rec: JobRecord, in_state: ColumnElement[bool], event: dict,
              **values: Any) -> bool:
        """One transaction: `rec`'s row, if it still matches `in_state` and has the `events`
        count it had, takes `values` and one more event, `event` is stored as that event and
        listeners are notified. False when something else changed the row first (no row
        matched, or another writer took the event's seq)."""
        cond = [JobRow.id == rec.id, in_state, JobRow.events == rec.events]
        try:
            with self.engine.begin() as conn:
                n = conn.execute(update(JobRow).where(*cond).values(
                    **values, events=rec.events + 1)).rowcount
                if n != 1:
                    return False
                conn.execute(insert(JobEventRow).values(
                    job_id=rec.id, seq=rec.events,
                    body=json.dumps(event, separators=(",", ":"))))
                self._notify(conn, [rec.id])
        except IntegrityError:
            return False
        return True

    def request_cancel(self, job_id: str, event: dict) -> JobRecord | None:
        """A client's cancel: a queued job ends `cancelled` at once (with `event`), a running
        one gets `cancel_requested` for its worker to see. None for unknown ids."""
        for _ in range(3):
            rec = self.get(job_id)
            if rec is None or rec.finished:
                return rec
            if rec.state == "queued":
                if self.end_with_event(rec, from_states=("queued",), state="cancelled",
                                       reason="cancelled", event=event):
                    return self.get(job_id)
                continue
            with Session(self.engine) as session:
                session.execute(update(JobRow).where(JobRow.id == job_id)
                                .values(cancel_requested=True))
                session.commit()
            return self.get(job_id)
        return self.get(job_id)

    def orphans(self, stale_s: float, grace_s: float) -> list[JobRecord]:
        """Active jobs whose process is gone: a running job's worker (or an embedded queued
        job's owner) is certainly dead and its heartbeat older than `grace_s`, or its heartbeat
        is older than `stale_s` (another host, or a hung process)."""
        now = _now()
        out = []
        for rec in self.active():
            holder = rec.worker if rec.state == "running" else rec.owner
            if rec.state == "queued" and rec.queue != "embedded":
                continue     # the queue engine holds it, whoever admitted it
            age = (now - rec.heartbeat_at).total_seconds()
            if age > stale_s or (process_gone(holder) and (_my_pid(holder) or age > grace_s)):
                out.append(rec)
        return out

    def adopt(self, rec: JobRecord, owner: str) -> bool:
        """Take over a queued embedded job whose owner is gone (it had not started)."""
        with Session(self.engine) as session:
            n = session.execute(update(JobRow).where(
                JobRow.id == rec.id, JobRow.state == "queued", JobRow.owner == rec.owner)
                .values(owner=owner, heartbeat_at=_now())).rowcount  # type: ignore[attr-defined]
            session.commit()
            return n == 1

    # -- housekeeping ---------------------------------------------------------------------------

    def prune_events(self, older_than_s: float) -> int:
        """Drop the events of jobs that ended more than `older_than_s` ago (the rows stay, so
        their state and reason are still known); how many jobs."""
        cutoff = _now() - timedelta(seconds=older_than_s)
        with self.engine.begin() as conn:
            ids = list(conn.scalars(select(JobRow.id).where(
                JobRow.state.in_(TERMINAL), JobRow.finished_at < cutoff,
                JobRow.events_pruned.is_(False))))
            for i in range(0, len(ids), 500):
                part = ids[i:i + 500]
                conn.execute(delete(JobEventRow).where(JobEventRow.job_id.in_(part)))
                conn.execute(update(JobRow).where(JobRow.id.in_(part)).values(events_pruned=True))
        return len(ids)

    def stats(self) -> dict[str, Any]:
        with Session(self.engine) as session:
            rows = session.execute(select(JobRow.state, func.count()).group_by(JobRow.state)).all()
        return {state: n for state, n in rows}
