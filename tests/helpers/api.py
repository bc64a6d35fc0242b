"""API test helpers: a small deterministic generator to inject instead of the real one, and
a job run end to end through POST /api/jobs and its WebSocket."""

from __future__ import annotations

import numpy as np
from fastapi.testclient import TestClient

from interplay.generators.plan import GenerationPlan
from interplay.motion.skeleton import FPS, rest_joints
from interplay.planner.plan import plan


class FakeGenerator:
    """Rest-pose people walking towards each other, in 20-frame chunks; can be told to fail."""

    def __init__(self, chunk: int = 20, fail_after: int | None = None):
        self.chunk, self.fail_after = chunk, fail_after

    def plan(self, req) -> GenerationPlan:
        return GenerationPlan.from_plan(plan(req.prompt, req.persons, req.seconds),
                                        seed=req.seed or 0, generator="retrieval")

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
