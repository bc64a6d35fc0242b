"""Fixtures for the API tests: an app on a temporary SQLite file and dist dir, with either the
real generator (loaded once per session) or a small deterministic fake injected through
`create_app(generator=…)`."""

from __future__ import annotations

import numpy as np
import pytest
from fastapi.testclient import TestClient

from interplay.agents.planner import plan_json
from interplay.api.app import create_app
from interplay.motion.skeleton import FPS, rest_joints
from interplay.settings import Settings


class FakeGenerator:
    """Rest-pose people walking towards each other, in 20-frame chunks; can be told to fail."""

    def __init__(self, chunk: int = 20, fail_after: int | None = None):
        self.chunk, self.fail_after = chunk, fail_after

    def plan(self, req) -> dict:
        return plan_json(req.prompt, req.persons, req.seconds)

    def stream(self, req, plan):
        total = round(req.seconds * FPS)
        t = np.arange(total)[:, None, None] / FPS
        rng = np.random.default_rng(req.seed)
        rest = rest_joints()
        people = []
        for p in range(req.persons):
            x = -0.6 + 1.2 * p
            joints = rest[None] + np.array([x, 0.0, 0.0]) + rng.normal(0, 0.01, (total, 22, 3))
            joints[..., 0] += (0.2 if p == 0 else -0.2) * t[..., 0]
            people.append(joints)
        for k, start in enumerate(range(0, total, self.chunk)):
            if self.fail_after is not None and k >= self.fail_after:
                raise RuntimeError("the fake generator broke on purpose")
            yield start, [j[start:start + self.chunk] for j in people]


@pytest.fixture
def settings(tmp_path) -> Settings:
    return Settings(var_dir=tmp_path / "var", frontend_dist=tmp_path / "dist",
                    database_url=f"sqlite:///{tmp_path / 'var' / 'test.db'}")


@pytest.fixture
def fake_client(settings):
    with TestClient(create_app(settings, generator=FakeGenerator())) as client:
        yield client


@pytest.fixture(scope="session")
def real_generator():
    from interplay.agents.generator import load_generator
    from interplay.settings import get_settings
    return load_generator(get_settings().data_dir)   # models/data unless INTERPLAY_DATA_DIR


@pytest.fixture
def real_client(settings, real_generator):
    with TestClient(create_app(settings, generator=real_generator)) as client:
        yield client


def run_job(client: TestClient, **body) -> tuple[dict, list[dict]]:
    """POST a job and collect every event of its stream."""
    r = client.post("/api/jobs", json=body)
    assert r.status_code == 201, r.text
    job = r.json()
    events = []
    with client.websocket_connect(job["stream"]) as ws:
        while True:
            events.append(ws.receive_json())
            if events[-1]["type"] in ("done", "error"):
                break
    return job, events
