"""Persistence: SQLAlchemy models and a repository; SQLite by default, PostgreSQL by DATABASE_URL."""

from interplay.store.db import make_engine
from interplay.store.jobs import JobRecord, JobStore
from interplay.store.models import new_id
from interplay.store.repository import MotionRepository, MotionSummary, StoredMotion, valid_id
from interplay.store.retention import Retention

__all__ = ["make_engine", "new_id", "MotionRepository", "MotionSummary", "StoredMotion", "valid_id",
           "JobRecord", "JobStore", "Retention"]
