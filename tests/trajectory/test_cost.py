"""The trajectory editor's cost is bounded whatever the path: the worst paths the request limits
allow (2000 drawn points over 200 m, presets and waypoints at their longest) are mapped onto a
20 s walk in under 2 s of CPU and 300 MB, measured in a fresh process (its own peak RSS, and
numpy's allocations by tracemalloc); paths far beyond the limits (a library caller's, unvalidated) stay
bounded too, because the work is linear in the points and the sample and knot counts are capped.
Before the bounds, the issue's drawn path [[-100, 0], [100, 0.1], [-100, 0.2], [100, 0]] took
21.5 s and 1.9 GB here and one waypoint at (20 km, 20 km) 115 s and 4.1 GB."""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest

from interplay.pipeline.requests import MAX_COORD, MAX_PATH_M, MAX_POINTS, TrajectoryIn
from interplay.planner.schema import TrajectorySpec, spec_length
from tests.helpers.paths import REPO

MAX_SECONDS_PER_PATH = 2.0
MAX_EXTRA_MB = 300.0


def _back_and_forth(n: int, legs: int, half_width: float) -> list[list[float]]:
    """n points along `legs` straight legs across ±half_width (the issue's shape)."""
    xs = np.concatenate([np.linspace(-half_width, half_width, n // legs) * (-1) ** i
                         for i in range(legs)])
    zs = np.linspace(0.0, 0.2, len(xs))
    return np.round(np.stack([xs, zs], axis=1), 4).tolist()


def _jagged(n: int, total: float) -> list[list[float]]:
    """n points of a random walk `total` metres long: a turn at every point."""
    rng = np.random.default_rng(0)
    angle = rng.uniform(-np.pi, np.pi, n - 1)
    steps = np.stack([np.sin(angle), np.cos(angle)], axis=1) * (total / (n - 1))
    return np.round(np.concatenate([[[0.0, 0.0]], np.cumsum(steps, axis=0)]), 4).tolist()


def _circle_size(turns: float) -> float:
    return math.floor(MAX_PATH_M / (math.pi * turns) * 100) / 100


DRAWN = {
    "2000 points back and forth over 200 m": _back_and_forth(MAX_POINTS, 2, 49.99),
    "2000 points turning at every point, 200 m": _jagged(MAX_POINTS, MAX_PATH_M * 0.999),
}
PRESETS = {
    "circle, 20 turns, 200 m": {"shape": "circle", "turns": 20, "size_m": _circle_size(20)},
    "spiral, 20 turns, 200 m": {"shape": "spiral", "turns": 20, "size_m": 6.1},
    "zigzag, 200 m": {"shape": "zigzag", "distance_m": 40, "size_m": 4.89},
    "s_curve, 200 m": {"shape": "s_curve", "distance_m": 167, "size_m": 50},
    "line turning back after 100 m": {"shape": "line", "distance_m": 200, "turn_at": {"clock": 6, "after_m": 100}},
    "polyline, 2000 waypoints": {"shape": "polyline", "waypoints": _jagged(MAX_POINTS, MAX_PATH_M * 0.999)},
    "free, 2000 waypoints": {"shape": "free", "waypoints": _back_and_forth(MAX_POINTS, 2, 49.99)},
    "square, 200 m": {"shape": "square", "size_m": 50},
}
# Far beyond the limits (rejected by the request schema): the editor itself stays bounded.
BEYOND = {
    "the issue's drawn path, 600 m": ("points", [[-100, 0], [100, 0.1], [-100, 0.2], [100, 0]]),
    "one waypoint at (20 km, 20 km)": ("spec", {"shape": "polyline", "waypoints": [[20000, 20000]]}),
    "circle of 50 m, 20 turns (3.1 km)": ("spec", {"shape": "circle", "size_m": 50, "turns": 20}),
    "zigzag 200 m long, 50 m wide (10 km)": ("spec", {"shape": "zigzag", "distance_m": 200, "size_m": 50}),
}

# Run in a fresh interpreter: a 20 s walk (400 frames), one ordinary path first (so that what
# numpy and the BLAS keep is in the baseline), then each case: its CPU time (the process's, all
# threads: what the work costs, whatever else loads the shared machine; wall time is reported
# beside it), numpy's peak by tracemalloc, and the process's peak RSS over the baseline.
SCRIPT = r"""
import json, resource, sys, time, tracemalloc
import numpy as np
from interplay.pipeline.orchestrator import DRAWN_PATH
from interplay.trajectory.apply import apply_trajectory
from tests.helpers.synthetic_motion import fk_motion

def rss_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024

joints, _ = fk_motion(400, "walk", speed=3.0)
def run(kind, value):
    if kind == "points":
        return apply_trajectory(joints, np.asarray(value, dtype=np.float64), cfg=DRAWN_PATH)
    return apply_trajectory(joints, value)

run("points", [[0, 0], [1, 0.5], [2, 0], [3, -0.5]])
run("spec", {"shape": "circle"})
base = rss_mb()
out = {}
for name, (kind, value) in json.loads(sys.stdin.read()).items():
    t, cpu = time.perf_counter(), time.process_time()
    moved = run(kind, value)
    seconds, wall = time.process_time() - cpu, time.perf_counter() - t
    tracemalloc.start()
    run(kind, value)
    peak = tracemalloc.get_traced_memory()[1] / 2**20
    tracemalloc.stop()
    out[name] = {"seconds": seconds, "wall_s": wall, "traced_mb": peak,
                 "finite": bool(np.isfinite(moved).all())}
print(json.dumps({"cases": out, "extra_rss_mb": rss_mb() - base}))
"""


def _measure(cases: dict) -> dict:
    proc = subprocess.run([sys.executable, "-c", SCRIPT], input=json.dumps(cases), text=True,
                          capture_output=True, cwd=REPO, timeout=600,
                          env={"PYTHONPATH": str(REPO), "PATH": "/usr/bin:/bin"})
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


def test_the_worst_paths_the_limits_allow_are_allowed_and_at_the_limits():
    for points in DRAWN.values():
        path = TrajectoryIn.model_validate({"points": points})
        assert len(points) == MAX_POINTS and 0.99 * MAX_PATH_M <= path.length() <= MAX_PATH_M
        assert max(abs(c) for p in points for c in p) <= MAX_COORD
    for spec in PRESETS.values():
        TrajectoryIn.model_validate(spec)
        length = spec_length(TrajectorySpec.model_validate(spec))
        assert 0.97 * MAX_PATH_M <= length <= MAX_PATH_M, (spec["shape"], length)
    for kind, value in BEYOND.values():
        with pytest.raises(ValueError, match="limit is 200 m|within ±100 m"):
            TrajectoryIn.model_validate({"points": value} if kind == "points" else value)


@pytest.fixture(scope="module")
def measured():
    cases = {**{k: ("points", v) for k, v in DRAWN.items()},
             **{k: ("spec", v) for k, v in PRESETS.items()}, **BEYOND}
    return _measure(cases)


@pytest.mark.parametrize("name", [*DRAWN, *PRESETS, *BEYOND])
def test_each_path_is_mapped_in_bounded_time_and_memory(measured, name):
    case = measured["cases"][name]
    assert case["finite"]
    assert case["seconds"] <= MAX_SECONDS_PER_PATH, case
    assert case["traced_mb"] <= MAX_EXTRA_MB, case


def test_the_process_peak_stays_within_the_budget(measured):
    assert measured["extra_rss_mb"] <= MAX_EXTRA_MB, measured
