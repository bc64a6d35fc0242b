"""SQLAlchemy 2.0 tables. One row per generated motion; joints stored compactly as float32
bytes of shape (persons, frames, 22, 3), C order. One row per job (its spec, state and who runs
it) and one per streamed event of a job, which a stream replays from."""

from __future__ import annotations

import secrets
from datetime import datetime, timezone

from sqlalchemy import (
    JSON,
    Boolean,
    DateTime,
    Float,
    ForeignKey,
    Integer,
    LargeBinary,
    String,
    Text,
)
from sqlalchemy.orm import DeclarativeBase, Mapped, mapped_column

# secrets.token_urlsafe(16): 16 random bytes = 128 bits, 22 URL-safe characters.
ID_BYTES = 16
ID_PATTERN = r"^[A-Za-z0-9_-]{22,64}$"


def new_id() -> str:
    """An unguessable, URL-safe id (128 bits of entropy)."""
    return secrets.token_urlsafe(ID_BYTES)


def _now() -> datetime:
    return datetime.now(timezone.utc)


class Base(DeclarativeBase):
    pass


class MotionRow(Base):
    __tablename__ = "motions"

    id: Mapped[str] = mapped_column(String(64), primary_key=True, default=new_id)
    prompt: Mapped[str] = mapped_column(Text)
    persons: Mapped[int] = mapped_column(Integer)
    seconds: Mapped[float] = mapped_column(Float)
    seed: Mapped[int | None] = mapped_column(Integer, nullable=True)
    fps: Mapped[int] = mapped_column(Integer, default=20)
    frames: Mapped[int] = mapped_column(Integer)
    joints: Mapped[bytes] = mapped_column(LargeBinary)       # float32 (persons, frames, 22, 3)
    plan: Mapped[dict | None] = mapped_column(JSON, nullable=True)
    metrics: Mapped[dict | None] = mapped_column(JSON, nullable=True)
    highlights: Mapped[dict | None] = mapped_column(JSON, nullable=True)
    # The reviewer's rounds per segment (generated motions) and what made an edited version
    # ({part, prompt, frames, trajectory}; None for a generated motion).
    review: Mapped[dict | None] = mapped_column(JSON, nullable=True)
    edit: Mapped[dict | None] = mapped_column(JSON, nullable=True)
    # A later version of a motion (an edit) points at the motion it came from.
    parent_id: Mapped[str | None] = mapped_column(
        String(64), ForeignKey("motions.id", ondelete="SET NULL"), nullable=True, index=True)
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True), default=_now, index=True)
    # The browser that made it (the studio's random per-browser id, `X-Interplay-Client`), for
    # its "My motions" list; None for motions made without one (CLI, API, older rows). Never
    # sent back with a motion: it is what lists a browser's motions.
    client_id: Mapped[str | None] = mapped_column(String(64), nullable=True, index=True)


class JobRow(Base):
    """A generation, reaction or edit job: queued → running → done | failed | cancelled.

    `owner` is the process that admitted it, `worker` the one that runs it (process names
    `host:pid:token`); a running job's worker refreshes `heartbeat_at`, so a job whose worker
    died is found and failed with a reason. `events` counts its stored events (the next seq)."""
    __tablename__ = "jobs"

    id: Mapped[str] = mapped_column(String(64), primary_key=True)
    motion_id: Mapped[str] = mapped_column(String(64), unique=True, index=True)
    kind: Mapped[str] = mapped_column(String(16))                 # generate | react | edit
    spec: Mapped[dict] = mapped_column(JSON)
    state: Mapped[str] = mapped_column(String(16), index=True)
    reason: Mapped[str | None] = mapped_column(Text, nullable=True)
    result: Mapped[dict | None] = mapped_column(JSON, nullable=True)   # e.g. {"http_status": 422}
    queue: Mapped[str] = mapped_column(String(16))                # embedded | procrastinate
    owner: Mapped[str] = mapped_column(String(160))
    worker: Mapped[str | None] = mapped_column(String(160), nullable=True)
    attempts: Mapped[int] = mapped_column(Integer, default=0)
    cancel_requested: Mapped[bool] = mapped_column(Boolean, default=False)
    events: Mapped[int] = mapped_column(Integer, default=0)
    events_pruned: Mapped[bool] = mapped_column(Boolean, default=False)
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True), default=_now, index=True)
    started_at: Mapped[datetime | None] = mapped_column(DateTime(timezone=True), nullable=True)
    finished_at: Mapped[datetime | None] = mapped_column(DateTime(timezone=True), nullable=True,
                                                         index=True)
    heartbeat_at: Mapped[datetime] = mapped_column(DateTime(timezone=True), default=_now)


class JobEventRow(Base):
    """One streamed event of a job (the dict an `api.events` model dumps, as JSON text)."""
    __tablename__ = "job_events"

    job_id: Mapped[str] = mapped_column(String(64), ForeignKey("jobs.id", ondelete="CASCADE"),
                                        primary_key=True)
    seq: Mapped[int] = mapped_column(Integer, primary_key=True)
    body: Mapped[str] = mapped_column(Text)
