"""The checks every clip of the newer sources passes (interplay.motion.retarget.checks), on
synthetic motion with known answers."""

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.retarget.checks import (
    MAX_ROOT_ACCELERATION,
    com_flight_gravity,
    contact_defects,
    contact_report,
    decide_rate,
)


def _standing(t: int) -> np.ndarray:
    rest = sk.rest_joints()
    rest = rest - [0, rest[:, 1].min(), 0]
    return np.repeat(rest[None], t, axis=0)


def test_a_ballistic_hop_falls_at_gravity_and_a_prop_is_flagged():
    fps = 60
    joints = _standing(120)
    t = np.arange(30) / fps
    joints[40:70, :, 1] += 2.0 * t[:, None] * 1.0 - 0.5 * 9.81 * t[:, None] ** 2 + 0.25
    assert abs(com_flight_gravity(joints, fps) - 9.81) < 0.2
    assert abs(com_flight_gravity(joints, 2 * fps) - 4 * 9.81) < 1.0
    # Held 0.5 m up for 2 s: nothing under the feet.
    held = _standing(60)
    held[10:50, :, 1] += 0.5
    report = contact_report(held)
    assert report["unsupported_s"] == 2.0 and "floor" in contact_defects(report)[0]
    assert contact_defects(contact_report(_standing(40))) == []


def test_decide_rate_records_evidence_and_broken_roots():
    joints = _standing(200)
    joints[..., 2] += np.linspace(0, 2.0, 200)[:, None]               # a slow glide
    meta: dict = {}
    assert decide_rate(joints, 30.0, (30.0, 60.0), meta) == 30.0 and meta["defects"] == []
    assert set(meta["fps_evidence"]) == {"30", "60"} and meta["stated_fps"] == 30.0
    # A root that teleports half a metre four times accelerates beyond any athlete at both rates.
    jitter = _standing(200)
    for k in (40, 80, 120, 160):
        jitter[k:, :, 0] += 0.5
    meta = {}
    decide_rate(jitter, 30.0, (30.0, 60.0), meta)
    assert meta["defects"] and "broken root" in meta["defects"][0]
    assert all(e["com_acceleration_p99"] > MAX_ROOT_ACCELERATION for e in meta["fps_evidence"].values())
    meta = {}
    assert decide_rate(joints, 30.0, (30.0, 60.0, 15.0), meta, keep_stated=True) == 30.0
    assert meta["source_fps"] == 30.0
