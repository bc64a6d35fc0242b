"""Every request's cost is bounded whatever its shape: trajectories of every form are limited in
length, points and coordinates (readable 422s), JSON types are strict, bodies above the limit
are 413 before they are parsed, and the worst request the limits allow runs through the API in
≤ 2 s (of CPU: the shared machine's other load does not count) and ≤ 300 MB more RSS than the
ordinary jobs before it, measured in a fresh process."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
from fastapi.testclient import TestClient

from interplay.api.app import create_app
from interplay.settings import Settings
from tests.helpers.api import FakeGenerator
from tests.helpers.paths import REPO

JOB = {"prompt": "a person walks", "seconds": 6}


@pytest.fixture
def settings(tmp_path) -> Settings:
    """SQLite only (overrides the conftest's SQLite + PostgreSQL pair): nothing here depends on
    the database."""
    return Settings(var_dir=tmp_path / "var", frontend_dist=tmp_path / "dist",
                    database_url=f"sqlite:///{tmp_path / 'var' / 'test.db'}", job_queue="embedded")


def _detail(client, body, path="/api/jobs"):
    r = client.post(path, json=body)
    assert r.status_code == 422, r.text
    detail = r.json()["detail"]
    assert isinstance(detail, str)
    return detail


@pytest.mark.parametrize("trajectory,message", [
    # The requests: 600 m inside ±100 m (2.47 GB, 21.9 s before), a waypoint 20 km away.
    ({"points": [[-100, 0], [100, 0.1], [-100, 0.2], [100, 0]]},
     "the drawn path is 600 m long; the limit is 200 m"),
    ({"shape": "polyline", "waypoints": [[20000, 20000]]}, "within ±100 m"),
    ({"shape": "free", "waypoints": [[0, 0], [0, -150]]}, "within ±100 m, got -150"),
    ({"shape": "circle", "size_m": 50, "turns": 20}, "the circle path is 3142 m long; the limit is 200 m"),
    ({"shape": "zigzag", "distance_m": 200, "size_m": 50}, "the zigzag path is 10002 m long"),
    ({"shape": "line", "distance_m": 150, "turn_at": {"clock": 6, "after_m": 200}},
     "the line path is 275 m long"),
    ({"shape": "line", "turn_at": {"clock": 3, "after_m": 1e9}}, "after_m"),
    ({"shape": "polyline", "waypoints": [[0, i % 2] for i in range(2001)]}, "at most 2000 items"),
    ({"points": [[0, i % 2] for i in range(2001)]}, "at most 2000 items"),
    ({"points": [[0, 0], [101, 0]]}, "within ±100 m"),
    ({"points": [[0, 0], [1e308, 0]]}, "within ±100 m"),
])
def test_paths_beyond_the_limits_are_422_with_the_reason(fake_client, trajectory, message):
    assert message in _detail(fake_client, {**JOB, "trajectory": trajectory})


def test_a_drawn_path_must_be_walkable_in_the_motions_length(fake_client):
    path = {"points": [[0, 0], [0, 45]]}
    assert ("the drawn path is 45.0 m long; a 4 s motion covers at most 40 m (10 m/s)"
            in _detail(fake_client, {**JOB, "seconds": 4, "trajectory": path}))
    assert fake_client.post("/api/jobs", json={**JOB, "seconds": 5, "trajectory": path}).status_code == 201


@pytest.mark.parametrize("body,field", [
    ({**JOB, "seconds": True}, "seconds"),
    ({**JOB, "seconds": "6"}, "seconds"),
    ({**JOB, "persons": True}, "persons"),
    ({**JOB, "persons": 1.0}, "persons"),
    ({**JOB, "persons": "1"}, "persons"),
    ({**JOB, "seed": "7"}, "seed"),
    ({**JOB, "seed": 7.0}, "seed"),
    ({**JOB, "seed": True}, "seed"),
    ({**JOB, "trajectory": {"person": True, "points": [[0, 0], [1, 1]]}}, "trajectory.person"),
    ({**JOB, "trajectory": {"points": [[0, 0], [True, 1]]}}, "trajectory.points.1.0"),
    ({**JOB, "trajectory": {"points": [[0, 0], ["1", 1]]}}, "trajectory.points.1.0"),
    ({**JOB, "trajectory": {"shape": "circle", "size_m": "3"}}, "size_m"),
    ({**JOB, "trajectory": {"shape": "circle", "clockwise": "yes"}}, "clockwise"),
    ({**JOB, "trajectory": {"shape": "circle", "turns": True}}, "turns"),
    ({**JOB, "trajectory": {"shape": "line", "turn_at": {"clock": "3"}}}, "clock"),
])
def test_types_are_strict(fake_client, body, field):
    assert field in _detail(fake_client, body)


def test_json_numbers_of_the_right_kind_are_accepted(fake_client):
    ok = {**JOB, "seconds": 3, "persons": 2, "seed": 7,
          "trajectory": {"person": 1, "points": [[0, 0], [1.5, 2]]}}
    assert fake_client.post("/api/jobs", json=ok).status_code == 201
    ok = {**JOB, "seconds": 2.5, "trajectory": {"shape": "circle", "size_m": 3, "turns": 1.5,
                                                "clockwise": True}}
    assert fake_client.post("/api/jobs", json=ok).status_code == 201


def test_edit_types_are_strict(fake_client):
    from tests.helpers.api import run_job
    job, _ = run_job(fake_client, **JOB)
    path = f"/api/motions/{job['motion_id']}/edit"
    assert "seed" in _detail(fake_client, {"prompt": "waves", "seed": "3"}, path)
    assert "frames.0" in _detail(fake_client, {"prompt": "waves", "frames": ["0", 10]}, path)
    assert "the drawn path is 600 m" in _detail(fake_client, {"trajectory": {
        "points": [[-100, 0], [100, 0.1], [-100, 0.2], [100, 0]]}}, path)


# ---- the request-body limit --------------------------------------------------------------

@pytest.fixture
def small_limit_client(settings):
    app = create_app(settings.model_copy(update={"max_body_bytes": 4096}), generator=FakeGenerator())
    with TestClient(app) as client:
        yield client


def test_a_body_above_the_limit_is_413_with_a_message(small_limit_client):
    body = json.dumps({**JOB, "prompt": "a person walks", "pad": "x" * 5000})
    r = small_limit_client.post("/api/jobs", content=body, headers={"content-type": "application/json"})
    assert r.status_code == 413
    assert r.json() == {"detail": f"request body too large: the limit is 4096 bytes, this one is "
                                  f"{len(body)} bytes"}
    assert r.headers["x-content-type-options"] == "nosniff"


def test_a_streamed_body_without_content_length_is_counted_too(small_limit_client):
    sent = []

    def chunks():
        for _ in range(100):                              # 100 × 1 KiB, no Content-Length
            sent.append(1)
            yield b" " * 1024
    r = small_limit_client.post("/api/jobs", content=chunks(),
                                headers={"content-type": "application/json"})
    assert "content-length" not in r.request.headers
    assert r.status_code == 413 and "the limit is 4096 bytes" in r.json()["detail"], r.text


def test_a_body_within_the_limit_is_served(small_limit_client):
    r = small_limit_client.post("/api/jobs", json=JOB)
    assert r.status_code == 201, r.text


def test_the_default_limit_takes_the_largest_valid_path(fake_client):
    points = [[round(-99.9999 + i * 0.05, 4), round(-99.9999 + (i % 2) * 0.05, 4)] for i in range(2000)]
    r = fake_client.post("/api/jobs", json={**JOB, "seconds": 20, "trajectory": {"points": points}})
    assert r.status_code == 201, r.text
    r = fake_client.post("/api/jobs", content=b'{"prompt": "' + b"x" * (300 * 1024) + b'"}',
                         headers={"content-type": "application/json"})
    assert r.status_code == 413 and "262144" in r.json()["detail"]


# ---- the worst request, end to end -----------------------------------------------------------

SCRIPT = r"""
import json, resource, sys, tempfile, time
from pathlib import Path
from fastapi.testclient import TestClient
from interplay.api.app import create_app
from interplay.settings import Settings
from tests.helpers.api import FakeGenerator, run_job

def rss_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024

tmp = Path(tempfile.mkdtemp())
settings = Settings(var_dir=tmp / "var", frontend_dist=tmp / "dist",
                    database_url=f"sqlite:///{tmp / 'var' / 'test.db'}")
body = {"prompt": "a person walks", "seconds": 20, "seed": 1}
out = {}
with TestClient(create_app(settings, generator=FakeGenerator())) as client:
    for name, trajectory in [("ordinary", {"points": [[0, 0], [1, 0.5], [2, 0], [3, -0.5]]}),
                             ("ordinary preset", {"shape": "circle"})]:
        cpu = time.process_time()
        run_job(client, **body, trajectory=trajectory)
        out[name] = time.process_time() - cpu
    base = rss_mb()
    wall = {}
    for name, trajectory in json.loads(sys.stdin.read()).items():
        t, cpu = time.perf_counter(), time.process_time()
        job, events = run_job(client, **body, trajectory=trajectory)
        out[name], wall[name] = time.process_time() - cpu, time.perf_counter() - t
        assert events[-1]["type"] == "done", events[-1]
print(json.dumps({"seconds": out, "wall_s": wall, "extra_rss_mb": rss_mb() - base}))
"""


def test_the_worst_requests_the_limits_allow_finish_in_2_s_and_300_mb():
    from tests.trajectory.test_cost import DRAWN, PRESETS
    cases = {**{k: {"points": v} for k, v in DRAWN.items()}, **PRESETS}
    proc = subprocess.run([sys.executable, "-c", SCRIPT], input=json.dumps(cases), text=True,
                          capture_output=True, cwd=REPO, timeout=600,
                          env={"PYTHONPATH": str(REPO), "PATH": "/usr/bin:/bin"})
    assert proc.returncode == 0, proc.stderr[-3000:]
    result = json.loads(proc.stdout.strip().splitlines()[-1])
    seconds = result["seconds"]
    for name in cases:
        assert seconds[name] <= 2.0, (name, seconds)
    assert result["extra_rss_mb"] <= 300, result
