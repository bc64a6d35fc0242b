"""A real PostgreSQL for the tests: `scripts/postgres.sh` installs Debian's `postgresql` when it
is missing (as root), starts a throw-away cluster on a free loopback port for the session, and
stops it at the end. `pg_url` hands each test an empty database (the public schema dropped and
made again).

Without PostgreSQL (and no root to install it) the PostgreSQL tests are skipped, unless
INTERPLAY_REQUIRE_POSTGRES=1 (what `make test` sets), when they fail instead.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "postgres.sh"


@pytest.fixture(scope="session")
def pg_cluster():
    """(libpq URL, cluster dir) of the session's cluster."""
    run = subprocess.run(["sh", str(SCRIPT), "start"], capture_output=True, text=True,
                         timeout=600)
    if run.returncode != 0:
        message = f"no PostgreSQL for the tests: {run.stderr.strip()[-2000:]}"
        if os.environ.get("INTERPLAY_REQUIRE_POSTGRES") == "1":
            pytest.fail(message)
        pytest.skip(message)
    url, _, where = run.stdout.strip().splitlines()[-1].partition(" ")
    try:
        yield url, where
    finally:
        subprocess.run(["sh", str(SCRIPT), "stop", where], capture_output=True, timeout=120)


def reset(url: str) -> None:
    import psycopg
    with psycopg.connect(url, autocommit=True) as conn:
        conn.execute("DROP SCHEMA IF EXISTS public CASCADE")
        conn.execute("CREATE SCHEMA public")


@pytest.fixture
def pg_url(pg_cluster) -> str:
    """An empty database on the session's cluster (libpq URL; DATABASE_URL takes it as is)."""
    url = pg_cluster[0]
    reset(url)
    return url
