"""Retention: how much the store keeps (off by default).

    max_motions   keep at most this many motions: storing one more deletes the oldest
    max_age_s     delete motions (and ended jobs) older than this

A deleted motion's edits keep their own rows (their `parent_id` becomes null); the job that
made it keeps its row, so `GET /api/motions/{id}` can say the motion was deleted. Ended job
rows are deleted by age, and with a count limit alone kept to the newest 10 × max_motions.
Motions an active job still reads (a react job's actor, an edit's parent) are never deleted.
"""

from __future__ import annotations

from dataclasses import dataclass
from datetime import datetime, timedelta, timezone

from sqlalchemy import Engine, delete, func, select, update

from interplay.store.models import JobRow, MotionRow

ACTIVE = ("queued", "running")
TERMINAL = ("done", "failed", "cancelled")


@dataclass(frozen=True)
class Retention:
    max_motions: int | None = None
    max_age_s: float | None = None

    @property
    def on(self) -> bool:
        return self.max_motions is not None or self.max_age_s is not None


def _in_use(conn) -> set[str]:
    """Motions an active job reads: a react job's actor, an edit's parent."""
    used: set[str] = set()
    for spec in conn.scalars(select(JobRow.spec).where(JobRow.state.in_(ACTIVE))):
        for key in ("actor_motion_id", "parent_id"):
            if isinstance(spec, dict) and isinstance(spec.get(key), str):
                used.add(spec[key])
    return used


def enforce(engine: Engine, policy: Retention, now: datetime | None = None) -> int:
    """Delete what the policy no longer keeps; how many motions were deleted."""
    if not policy.on:
        return 0
    now = now or datetime.now(timezone.utc)
    deleted = 0
    with engine.begin() as conn:
        keep = _in_use(conn)
        if policy.max_age_s is not None:
            cutoff = now - timedelta(seconds=policy.max_age_s)
            old = [i for i in conn.scalars(select(MotionRow.id).where(MotionRow.created_at < cutoff))
                   if i not in keep]
            deleted += _delete_motions(conn, old)
            conn.execute(delete(JobRow).where(JobRow.state.in_(TERMINAL),
                                              JobRow.created_at < cutoff))
        if policy.max_motions is not None:
            count = conn.scalar(select(func.count()).select_from(MotionRow)) or 0
            excess = count - policy.max_motions
            if excess > 0:
                oldest = conn.scalars(select(MotionRow.id)
                                      .order_by(MotionRow.created_at, MotionRow.id)
                                      .limit(excess + len(keep)))
                victims = [i for i in oldest if i not in keep][:excess]
                deleted += _delete_motions(conn, victims)
            cap = 10 * policy.max_motions
            ended = select(JobRow.id).where(JobRow.state.in_(TERMINAL)) \
                .order_by(JobRow.created_at.desc(), JobRow.id).offset(cap)
            extra = list(conn.scalars(ended))
            for i in range(0, len(extra), 500):
                conn.execute(delete(JobRow).where(JobRow.id.in_(extra[i:i + 500])))
    return deleted


def _delete_motions(conn, ids: list[str]) -> int:
    for i in range(0, len(ids), 500):
        part = ids[i:i + 500]
        # Edits of a deleted motion keep their rows: parent_id → null (also where the
        # database does not enforce the foreign key's ON DELETE SET NULL).
        conn.execute(update(MotionRow).where(MotionRow.parent_id.in_(part))
                     .values(parent_id=None))
        conn.execute(delete(MotionRow).where(MotionRow.id.in_(part)))
    return len(ids)
