"""Create, get and list stored motions. Rows become plain `StoredMotion` values (numpy joints),
so callers never hold a session or a detached ORM object. With a retention policy
(`store.retention`) every create also deletes what the policy no longer keeps."""

from __future__ import annotations

import string
from dataclasses import dataclass, field
from datetime import datetime, timezone

import numpy as np
from sqlalchemy import Engine, func, select
from sqlalchemy.orm import Session, load_only

from interplay.motion.skeleton import FPS, NUM_JOINTS
from interplay.store.models import MotionRow, new_id
from interplay.store.retention import Retention, enforce

# the characters and lengths of `models.ID_PATTERN`
_ID_CHARS = frozenset(string.ascii_letters + string.digits + "_-")


def valid_id(value: str) -> bool:
    """Whether `value` has the shape of an id this store hands out (cheap check before a query)."""
    return 22 <= len(value) <= 64 and _ID_CHARS.issuperset(value)


@dataclass(frozen=True)
class StoredMotion:
    id: str
    prompt: str
    persons: int
    seconds: float
    seed: int | None
    people: list[np.ndarray]          # one float32 (T, 22, 3) array per person
    plan: dict | None = None
    metrics: dict | None = None
    highlights: dict | None = None
    parent_id: str | None = None
    created_at: datetime | None = None
    fps: int = FPS
    review: dict | None = None        # the reviewer's rounds (generated motions)
    edit: dict | None = None          # what made this version: {part, prompt, frames, trajectory}

    @property
    def frames(self) -> int:
        return int(self.people[0].shape[0])


@dataclass(frozen=True)
class MotionSummary:
    id: str
    prompt: str
    persons: int
    seconds: float
    frames: int
    parent_id: str | None
    created_at: datetime
    metrics: dict | None = field(default=None)
    edit: dict | None = field(default=None)
    first_frame: list[np.ndarray] | None = field(default=None)   # (22, 3) per person


def _pack(people: list[np.ndarray]) -> tuple[bytes, int]:
    if not people:
        raise ValueError("a motion needs at least one person")
    arrays = [np.asarray(p, dtype=np.float32) for p in people]
    shape = arrays[0].shape
    if len(shape) != 3 or shape[1:] != (NUM_JOINTS, 3) or shape[0] < 1:
        raise ValueError(f"joints must be (T, {NUM_JOINTS}, 3) with T >= 1, got {shape}")
    if any(a.shape != shape for a in arrays):
        raise ValueError(f"every person needs the same shape, got {[a.shape for a in arrays]}")
    if not all(np.isfinite(a).all() for a in arrays):
        raise ValueError("joints contain NaN or infinite values")
    return np.ascontiguousarray(np.stack(arrays)).tobytes(), shape[0]


def _unpack(blob: bytes, persons: int, frames: int) -> list[np.ndarray]:
    arr = np.frombuffer(blob, dtype=np.float32).reshape(persons, frames, NUM_JOINTS, 3)
    return [arr[i].copy() for i in range(persons)]


def _first_frame(blob: bytes, persons: int, frames: int) -> list[np.ndarray]:
    arr = np.frombuffer(blob, dtype=np.float32).reshape(persons, frames, NUM_JOINTS, 3)
    return [arr[i, 0].copy() for i in range(persons)]


def _aware(dt: datetime) -> datetime:
    # SQLite drops the zone; every timestamp here is written in UTC.
    return dt if dt.tzinfo else dt.replace(tzinfo=timezone.utc)


class MotionRepository:
    def __init__(self, engine: Engine, retention: Retention | None = None):
        self.engine = engine
        self.retention = retention or Retention()

    def enforce_retention(self) -> int:
        """Delete what the retention policy no longer keeps (a no-op when it is off); how
        many motions went."""
        return enforce(self.engine, self.retention)

    def create(self, *, prompt: str, people: list[np.ndarray], seconds: float,
               seed: int | None = None, plan: dict | None = None, metrics: dict | None = None,
               highlights: dict | None = None, parent_id: str | None = None,
               id: str | None = None, review: dict | None = None,
               edit: dict | None = None, client_id: str | None = None) -> StoredMotion:
        """Store a motion and return it as read back. `id` may be pre-allocated (a job hands
        out the motion id before generation ends); otherwise a fresh one is drawn. `client_id`
        is the browser that made it (its "My motions" list, `for_client`)."""
        blob, frames = _pack(people)
        if client_id is not None and not valid_id(client_id):
            raise ValueError(f"malformed client id {client_id!r}")
        row = MotionRow(id=id or new_id(), prompt=prompt, persons=len(people),
                        seconds=float(seconds), seed=seed, fps=FPS, frames=frames, joints=blob,
                        plan=plan, metrics=metrics, highlights=highlights, parent_id=parent_id,
                        review=review, edit=edit, client_id=client_id)
        with Session(self.engine, expire_on_commit=False) as session:
            session.add(row)
            session.commit()
            stored = self._to_motion(row)
        if self.retention.on:
            self.enforce_retention()
        return stored

    def get(self, motion_id: str) -> StoredMotion | None:
        if not valid_id(motion_id):
            return None
        with Session(self.engine) as session:
            row = session.get(MotionRow, motion_id)
            return self._to_motion(row) if row is not None else None

    def exists(self, motion_id: str) -> bool:
        if not valid_id(motion_id):
            return False
        with Session(self.engine) as session:
            return (session.scalar(select(func.count()).where(MotionRow.id == motion_id)) or 0) > 0

    def lineage(self, motion_id: str, limit: int = 1000) -> list[MotionSummary]:
        """The versions from the root to `motion_id` (following parent_id), oldest first;
        [] for an unknown id. Stops at `limit` steps (and on a cycle)."""
        cols = (MotionRow.id, MotionRow.prompt, MotionRow.persons, MotionRow.seconds,
                MotionRow.frames, MotionRow.parent_id, MotionRow.created_at, MotionRow.edit)
        chain: list[MotionSummary] = []
        seen: set[str] = set()
        with Session(self.engine) as session:
            current = motion_id if valid_id(motion_id) else None
            while current and current not in seen and len(chain) < limit:
                seen.add(current)
                row = session.scalars(select(MotionRow).options(load_only(*cols))
                                      .where(MotionRow.id == current)).first()
                if row is None:
                    break
                chain.append(MotionSummary(id=row.id, prompt=row.prompt, persons=row.persons,
                                           seconds=row.seconds, frames=row.frames,
                                           parent_id=row.parent_id,
                                           created_at=_aware(row.created_at), edit=row.edit))
                current = row.parent_id
        return chain[::-1]

    def for_client(self, client_id: str, limit: int = 20,
                   after: str | None = None) -> list[MotionSummary] | None:
        """The motions `client_id` made (generated, edited, re-run), newest first, at most
        `limit`, each with its first frame (one (22, 3) array per person) for a thumbnail;
        [] for a malformed id. There is no listing without a client id. `after`: the page
        that follows this motion of the same client (keyset paging: motions made meanwhile
        neither repeat nor shift it); None when `after` is not one of the client's motions."""
        if not valid_id(client_id):
            return []
        cols = (MotionRow.id, MotionRow.prompt, MotionRow.persons, MotionRow.seconds,
                MotionRow.frames, MotionRow.parent_id, MotionRow.created_at, MotionRow.edit,
                MotionRow.joints)
        stmt = select(MotionRow).options(load_only(*cols)).where(MotionRow.client_id == client_id)
        with Session(self.engine) as session:
            if after is not None:
                mark = session.execute(select(MotionRow.created_at).where(
                    MotionRow.id == after, MotionRow.client_id == client_id)).first() \
                    if valid_id(after) else None
                if mark is None:
                    return None
                stmt = stmt.where((MotionRow.created_at < mark[0])
                                  | ((MotionRow.created_at == mark[0]) & (MotionRow.id > after)))
            stmt = stmt.order_by(MotionRow.created_at.desc(), MotionRow.id).limit(max(0, limit))
            return [MotionSummary(id=r.id, prompt=r.prompt, persons=r.persons, seconds=r.seconds,
                                  frames=r.frames, parent_id=r.parent_id,
                                  created_at=_aware(r.created_at), edit=r.edit,
                                  first_frame=_first_frame(r.joints, r.persons, r.frames))
                    for r in session.scalars(stmt)]

    def count_for_client(self, client_id: str) -> int:
        """How many motions `client_id` made (0 for a malformed id)."""
        if not valid_id(client_id):
            return 0
        with Session(self.engine) as session:
            return int(session.scalar(select(func.count()).select_from(MotionRow)
                                      .where(MotionRow.client_id == client_id)) or 0)

    def list(self, limit: int = 50, offset: int = 0) -> list[MotionSummary]:
        """Newest first, without the joints."""
        cols = (MotionRow.id, MotionRow.prompt, MotionRow.persons, MotionRow.seconds,
                MotionRow.frames, MotionRow.parent_id, MotionRow.created_at, MotionRow.metrics)
        stmt = (select(MotionRow).options(load_only(*cols))
                .order_by(MotionRow.created_at.desc(), MotionRow.id).limit(limit).offset(offset))
        with Session(self.engine) as session:
            return [MotionSummary(id=r.id, prompt=r.prompt, persons=r.persons, seconds=r.seconds,
                                  frames=r.frames, parent_id=r.parent_id,
                                  created_at=_aware(r.created_at), metrics=r.metrics)
                    for r in session.scalars(stmt)]

    @staticmethod
    def _to_motion(row: MotionRow) -> StoredMotion:
        return StoredMotion(id=row.id, prompt=row.prompt, persons=row.persons,
                            seconds=row.seconds, seed=row.seed,
                            people=_unpack(row.joints, row.persons, row.frames), plan=row.plan,
                            metrics=row.metrics, highlights=row.highlights,
                            parent_id=row.parent_id, created_at=_aware(row.created_at),
                            fps=row.fps, review=row.review, edit=row.edit)
