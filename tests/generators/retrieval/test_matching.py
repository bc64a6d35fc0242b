import numpy as np

from interplay.generators.retrieval.matching import best_start, pose_features
from tests.helpers.synthetic_motion import fk_motion


def test_features_ignore_where_the_person_stands_and_faces():
    a, _ = fk_motion(40, "walk")
    b, _ = fk_motion(40, "walk", yaw=2.1)
    b = b + np.array([3.0, 0.0, -1.0], dtype=np.float32)
    np.testing.assert_allclose(pose_features(a), pose_features(b), atol=1e-4)


def test_best_start_finds_the_same_gait_phase():
    walk, _ = fk_motion(120, "walk")                  # 0.9 Hz gait: one cycle ≈ 22 frames
    f = pose_features(walk)
    target = f[70]
    start = best_start(f, target, 0, 40)
    cycle = 20 / 0.9
    phase_error = abs((70 - start) / cycle - round((70 - start) / cycle))
    assert phase_error < 0.1
    # The opposite phase (half a cycle later) is a poor match.
    assert np.linalg.norm(f[start] - target) < 0.3 * np.linalg.norm(f[int(70 - cycle / 2)] - target)
