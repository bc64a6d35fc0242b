"""Engine creation: SQLite by default (a file in the var dir), PostgreSQL when the URL says so.

Several processes may start on one database at once (`interplay serve --workers N`, workers):
the tables are made once, under an advisory lock on PostgreSQL, and on SQLite by retrying what
another process made first."""

from __future__ import annotations

import time
from pathlib import Path

from sqlalchemy import Connection, Engine, create_engine, event, inspect, text
from sqlalchemy.engine import make_url
from sqlalchemy.exc import IntegrityError, OperationalError, ProgrammingError

from interplay.store.models import Base


def make_engine(url: str) -> Engine:
    """An engine for `url` with the tables created (idempotent)."""
    parsed = make_url(url)
    if parsed.get_backend_name() == "sqlite":
        if parsed.database and parsed.database != ":memory:":
            Path(parsed.database).parent.mkdir(parents=True, exist_ok=True)
        # Generation runs in worker threads: let them share the engine's connections.
        engine = create_engine(url, connect_args={"check_same_thread": False})

        @event.listens_for(engine, "connect")
        def _pragmas(conn, _record):
            cur = conn.cursor()
            cur.execute("PRAGMA foreign_keys=ON")
            cur.execute("PRAGMA journal_mode=WAL")
            cur.close()
    else:
        try:
            engine = create_engine(url, pool_pre_ping=True)
        except ImportError as exc:  # e.g. DATABASE_URL=postgresql://… without psycopg
            raise RuntimeError(f"no driver for {parsed.drivername!r} ({exc}); for PostgreSQL "
                               "install the extra: pip install -e '.[postgres]'") from None
    _create_schema(engine)
    return engine


SCHEMA_LOCK = 0x1A7E4C     # pg_advisory_xact_lock key: one process makes the tables at a time
_RACES = ("already exists", "duplicate", "database is locked")


def _create_schema(engine: Engine, attempts: int = 10) -> None:
    """The tables and the columns added since (idempotent, and safe when processes race)."""
    for attempt in range(attempts):
        try:
            with engine.begin() as conn:
                if engine.dialect.name == "postgresql":
                    conn.execute(text("SELECT pg_advisory_xact_lock(:k)"), {"k": SCHEMA_LOCK})
                Base.metadata.create_all(conn)
                _add_missing_columns(conn)
            return
        except (OperationalError, ProgrammingError, IntegrityError) as exc:
            if attempt == attempts - 1 or not any(r in str(exc).lower() for r in _RACES):
                raise
            time.sleep(0.05 * (attempt + 1))   # another process made them first: look again


def _add_missing_columns(conn: Connection) -> None:
    """Columns added to `motions` after a database was created (nullable: JSON, client_id),
    added in place with their indexes so an existing store keeps working."""
    have = {c["name"] for c in inspect(conn).get_columns("motions")}
    table = Base.metadata.tables["motions"]
    added = set()
    for col in table.columns:
        if col.name not in have and col.nullable:
            kind = col.type.compile(dialect=conn.dialect)
            conn.execute(text(f'ALTER TABLE motions ADD COLUMN "{col.name}" {kind}'))
            added.add(col.name)
    for index in table.indexes:
        if added & {c.name for c in index.columns}:
            index.create(conn, checkfirst=True)
