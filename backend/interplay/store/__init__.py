"""Persistence: SQLAlchemy models and a repository; SQLite by default, PostgreSQL by DATABASE_URL."""

from .db import make_engine
from .models import new_id
from .repository import MotionRepository, MotionSummary, StoredMotion, valid_id

__all__ = ["make_engine", "new_id", "MotionRepository", "MotionSummary", "StoredMotion", "valid_id"]
