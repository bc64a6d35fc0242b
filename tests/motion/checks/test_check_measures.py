"""The measures the named checks are built on, on exact synthetic inputs."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.motion.checks import measures as M


def test_dips_count_completed_dips_with_hysteresis():
    r = np.array([1.0, 0.9, 0.7, 0.8, 0.72, 0.95, 1.0, 0.6, 0.9, 0.7])
    assert [(s, b, e) for s, b, e in M.dips(r)] == [(1, 2, 5), (6, 7, 8)]   # the last is not back up
    assert M.dips(np.full(10, 0.5)) == []                                   # never stood: no dip


def test_pelvis_pops_measure_a_cut_not_a_speed():
    t = np.arange(40)
    j = np.zeros((40, 22, 3))
    j[:, :, 2] = 0.2 * t[:, None]                          # 4 m/s, steady
    assert M.pelvis_pops(j).max() < 1e-9
    j[25:, :, 0] += 0.3
    assert M.pelvis_pops(j)[25] == pytest.approx(0.3)


def test_shape_distance_is_zero_on_the_shape_and_blind_to_pose():
    for shape in M.CLOSED_SHAPES:
        t = M._template(shape, 200)
        c, s = np.cos(0.7), np.sin(0.7)
        moved = 3.0 * t[::-1] @ np.array([[c, -s], [s, c]]) + np.array([5.0, -2.0])
        assert M.shape_distance(np.roll(moved, 37, axis=0), shape) < 0.05
    assert M.shape_distance(3 * M._template("circle", 200), "square") > 0.08


def test_fit_circle_and_swept_angle():
    a = np.linspace(0, np.pi, 50)
    pts = np.stack([2 + 1.5 * np.cos(a), 1 + 1.5 * np.sin(a)], axis=1)
    centre, r, res = M.fit_circle(pts)
    assert np.allclose(centre, [2, 1]) and r == pytest.approx(1.5) and res < 1e-6
    assert M.swept_angle(pts, centre) == pytest.approx(180.0)


def test_resample_path_is_even():
    p = np.array([[0, 0], [1, 0], [1, 3]], float)
    q = M.resample_path(p, 5)
    assert np.allclose(np.linalg.norm(np.diff(q, axis=0), axis=1), 1.0)
