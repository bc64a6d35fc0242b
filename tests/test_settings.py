"""Settings from the environment: var dir, database URL (SQLite default, PostgreSQL as given)."""

from __future__ import annotations

import importlib.util

import pytest

from interplay.settings import REPO_ROOT, Settings
from interplay.store import make_engine


def test_defaults_live_in_the_repo(monkeypatch):
    for var in ("DATABASE_URL", "INTERPLAY_VAR_DIR", "INTERPLAY_PORT", "INTERPLAY_DATA_DIR"):
        monkeypatch.delenv(var, raising=False)
    s = Settings()
    assert s.var_dir == REPO_ROOT / "var" and s.frontend_dist == REPO_ROOT / "frontend" / "dist"
    assert s.db_url == f"sqlite:///{REPO_ROOT / 'var' / 'interplay.db'}"
    assert (s.host, s.port, s.data_dir) == ("127.0.0.1", 8000, None)


def test_environment_overrides(monkeypatch, tmp_path):
    monkeypatch.setenv("INTERPLAY_VAR_DIR", str(tmp_path))
    monkeypatch.setenv("INTERPLAY_PORT", "9123")
    monkeypatch.delenv("DATABASE_URL", raising=False)
    s = Settings()
    assert s.port == 9123 and s.db_url == f"sqlite:///{tmp_path / 'interplay.db'}"
    for given, want in [("postgres://u:p@db:5432/ip", "postgresql+psycopg://u:p@db:5432/ip"),
                        ("postgresql://u@db/ip", "postgresql+psycopg://u@db/ip"),
                        ("postgresql+psycopg://u@db/ip", "postgresql+psycopg://u@db/ip"),
                        ("sqlite:////srv/ip.db", "sqlite:////srv/ip.db")]:
        monkeypatch.setenv("DATABASE_URL", given)
        assert Settings().db_url == want
    monkeypatch.setenv("INTERPLAY_PORT", "not a port")
    with pytest.raises(ValueError):
        Settings()


@pytest.mark.skipif(importlib.util.find_spec("psycopg") is not None,
                    reason="psycopg installed: the driver is there")
def test_postgres_without_its_driver_says_what_to_install():
    with pytest.raises(RuntimeError, match=r"\[postgres\]"):
        make_engine("postgresql+psycopg://u@127.0.0.1:1/ip")
