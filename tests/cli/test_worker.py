"""`interplay worker` and `interplay serve --workers`: their argument errors exit 2 with a
message; a worker on a real PostgreSQL runs a queued job and stops on SIGTERM, ending the job it
was running with an error event after INTERPLAY_DRAIN_S (the queued ones stay for others)."""

from __future__ import annotations

import signal
import time

import httpx
import psycopg
import pytest

from interplay.cli import main as cli
from interplay.settings import get_settings
from tests.helpers.jobs import base_env, follow, start_server, start_worker


@pytest.fixture
def env_settings(monkeypatch):
    def use(**env):
        for key, value in env.items():
            monkeypatch.setenv(key, value)
        get_settings.cache_clear()
    yield use
    get_settings.cache_clear()


def test_worker_needs_postgresql_and_a_positive_concurrency(env_settings, tmp_path, capsys):
    env_settings(DATABASE_URL=f"sqlite:///{tmp_path / 'x.db'}")
    assert cli.main(["worker"]) == 2
    assert "needs DATABASE_URL=postgresql" in capsys.readouterr().err
    env_settings(DATABASE_URL="postgresql://nobody@127.0.0.1:1/none")
    assert cli.main(["worker", "--concurrency", "0"]) == 2
    assert "--concurrency" in capsys.readouterr().err
    assert cli.main(["serve", "--workers", "0"]) == 2
    assert "--workers" in capsys.readouterr().err


def test_a_worker_runs_jobs_and_drains_on_sigterm(tmp_path, pg_url):
    env = base_env(tmp_path, pg_url, INTERPLAY_TEST_CHUNK_DELAY_S="0.2", INTERPLAY_DRAIN_S="1")
    server, base = start_server(tmp_path, env)
    worker = start_worker(tmp_path, env)
    try:
        short = httpx.post(f"{base}/api/jobs", json={"prompt": "a person walks", "seconds": 1}).json()
        events, code = follow(base, short["stream"])
        assert events[-1]["type"] == "done" and code == 1000, worker.tail()
        long = httpx.post(f"{base}/api/jobs", json={"prompt": "a person walks", "seconds": 20}).json()
        queued = httpx.post(f"{base}/api/jobs", json={"prompt": "a person runs", "seconds": 1}).json()
        with psycopg.connect(pg_url, autocommit=True) as conn:
            deadline = time.monotonic() + 30
            while conn.execute("SELECT events FROM jobs WHERE id = %s",
                               (long["job_id"],)).fetchone()[0] < 3:
                assert time.monotonic() < deadline, worker.tail()
                time.sleep(0.05)
        worker.signal(signal.SIGTERM)
        assert worker.popen.wait(30) == 0, worker.tail()
        events, code = follow(base, long["stream"])
        assert events[-1] == {"type": "error", "message": "the worker is shutting down"}
        assert code == 1000
        status = httpx.get(f"{base}/api/jobs/{long['job_id']}").json()
        assert status["status"] == "failed" and "shutting down" in status["reason"]
        # The job it had not started waits for the next worker.
        assert httpx.get(f"{base}/api/jobs/{queued['job_id']}").json()["status"] == "queued"
        worker = start_worker(tmp_path, env, name="worker2")
        events, code = follow(base, queued["stream"])
        assert events[-1]["type"] == "done" and code == 1000
    finally:
        worker.stop()
        server.stop()
