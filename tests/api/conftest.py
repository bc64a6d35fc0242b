"""Fixtures for the API tests: an app on a temporary SQLite file or PostgreSQL database and a
dist dir, with either the real generator (loaded once per session) or a small deterministic
fake injected through `create_app(generator=…)`."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from interplay.api.app import create_app
from interplay.settings import Settings
from tests.helpers.api import FakeGenerator


@pytest.fixture(params=["sqlite", "postgres"])
def settings(request, tmp_path) -> Settings:
    """Every API test runs on SQLite and on a real PostgreSQL (the session's throw-away
    cluster, an empty database per test; the jobs run on this process's worker threads, as
    with SQLite: procrastinate and worker processes have their own tests)."""
    (tmp_path / "var").mkdir(exist_ok=True)
    url = f"sqlite:///{tmp_path / 'var' / 'test.db'}"
    if request.param == "postgres":
        url = request.getfixturevalue("pg_url")
    return Settings(var_dir=tmp_path / "var", frontend_dist=tmp_path / "dist",
                    database_url=url, job_queue="embedded")


@pytest.fixture
def fake_client(settings):
    with TestClient(create_app(settings, generator=FakeGenerator())) as client:
        yield client


@pytest.fixture(scope="session")
def real_generator():
    from interplay.generators.router import load_generator
    return load_generator()   # the settings' data and weights (models/ unless INTERPLAY_…)


@pytest.fixture
def real_client(settings, real_generator):
    with TestClient(create_app(settings, generator=real_generator)) as client:
        yield client
