"""Engine creation: SQLite by default (a file in the var dir), PostgreSQL when the URL says so."""

from __future__ import annotations

from pathlib import Path

from sqlalchemy import Engine, create_engine, event, inspect, text
from sqlalchemy.engine import make_url

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
    Base.metadata.create_all(engine)
    _add_missing_columns(engine)
    return engine


def _add_missing_columns(engine: Engine) -> None:
    """Columns added to `motions` after a database was created (nullable: JSON, client_id),
    added in place with their indexes so an existing store keeps working."""
    have = {c["name"] for c in inspect(engine).get_columns("motions")}
    table = Base.metadata.tables["motions"]
    with engine.begin() as conn:
        added = set()
        for col in table.columns:
            if col.name not in have and col.nullable:
                kind = col.type.compile(dialect=engine.dialect)
                conn.execute(text(f'ALTER TABLE motions ADD COLUMN "{col.name}" {kind}'))
                added.add(col.name)
        for index in table.indexes:
            if added & {c.name for c in index.columns}:
                index.create(conn, checkfirst=True)
