"""What every retargeted clip of the newer sources (bandai-namco, cmu-iclone, cmu-asfamc,
deepmimic) is checked for before the build keeps it, recorded in its meta the way
`cmu_daz` records CMU's: the capture rate and its evidence (`frame_rate.estimate_true_fps`
with the source's stated rate as the prior, plus the centre of mass's fall in flights),
broken root tracks (as `frame_rate.motion_defects`, with a cap for athletes, below) and foot
contact (below).

Foot contact, on the final joints (20 fps, canonical, floor at y = 0):
  * support: the longest stretch in which every joint stays more than SUPPORT_CLEARANCE above
    the floor. A jump or flip leaves the floor for 0.3–0.8 s (DeepMimic's backflip 0.6 s,
    HDM05's hops ≤ 0.5 s); a person sitting on or hanging from something the capture does
    not hold (CMU's playground climbs) is off the floor for seconds. Over MAX_UNSUPPORTED_S
    is a defect.
  * sliding: the share of frames in which a planted foot joint moves faster than 0.5 m/s
    (`metrics.person_metrics`' skating ratio). The existing sources stay at or under 0.22
    (HDM05's short grabs; CMU walks ≤ 0.07); over MAX_SKATING_RATIO is a defect.
  * sinking: the 98th percentile of the lowest joint's depth below the floor; over
    MAX_SINK means the floor estimate or the root track is off.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import canonicalize
from interplay.motion.metrics import centre_of_mass, person_metrics
from interplay.motion.retarget.frame_rate import GRAVITY_RANGE, estimate_true_fps

# Broken root: the 99th-percentile horizontal centre-of-mass acceleration (0.2 s smoothing)
# over this at every candidate rate. `frame_rate.motion_defects` caps CMU's walkers at 6 m/s²;
# the newer sources hold fighting moves and acrobatics that legitimately pass 6 at their true
# rate (Bandai Namco's kick 6.3 at 30 fps, CMU's soccer kick 11_01 7.3 at 120, DeepMimic's
# backflip 8.7 at 16), while the two broken CMU tracks (07_12, 09_10) exceed 14 at every rate.
MAX_ROOT_ACCELERATION = 9.0
# m: every joint above this means nothing touches the floor (a dancer on demi-pointe lifts
# the ball-of-foot joint 12–15 cm: CMU 05_05 in cmu-iclone).
SUPPORT_CLEARANCE = 0.20
MAX_UNSUPPORTED_S = 1.0
MAX_SKATING_RATIO = 0.30
MAX_SINK = 0.05            # m


def _longest_run(mask: np.ndarray) -> int:
    best = run = 0
    for m in mask:
        run = run + 1 if m else 0
        best = max(best, run)
    return best


def contact_report(joints: np.ndarray, fps: float = sk.FPS) -> dict:
    """Foot-contact figures of final joints (T, 22, 3): longest unsupported stretch (s),
    skating ratio, mean planted-foot speed (m/s) and the 98th-percentile sink (m)."""
    joints = np.asarray(joints, dtype=np.float64)
    lowest = joints[..., 1].min(axis=1)
    m = person_metrics(joints, int(fps))
    return {
        "unsupported_s": round(_longest_run(lowest > SUPPORT_CLEARANCE) / fps, 3),
        "skating_ratio": round(m["skating_ratio"], 3),
        "foot_skating_m_s": round(m["foot_skating"], 3),
        "sink_p98_m": round(float(np.percentile(np.maximum(0.0, -lowest), 98)), 3),
    }


def contact_defects(report: dict) -> list[str]:
    """Reasons from `contact_report`'s figures that a clip's feet do not meet the floor."""
    out = []
    if report["unsupported_s"] > MAX_UNSUPPORTED_S:
        out.append(f"no joint touches the floor for {report['unsupported_s']:.1f} s (over "
                   f"{MAX_UNSUPPORTED_S:g} s: held up by something the capture lacks)")
    if report["skating_ratio"] > MAX_SKATING_RATIO:
        out.append(f"planted feet slide in {report['skating_ratio']:.0%} of frames "
                   f"(over {MAX_SKATING_RATIO:.0%})")
    if report["sink_p98_m"] > MAX_SINK:
        out.append(f"the body sinks {report['sink_p98_m'] * 100:.0f} cm below the floor")
    return out


def com_flight_gravity(joints: np.ndarray, fps: float, clearance: float = 0.06,
                       min_frames: int = 3) -> float | None:
    """Downward acceleration (m/s²) of the centre of mass over the longest stretch in which
    every joint is more than `clearance` above the floor (a parabola fit), None without one.
    Unlike `frame_rate.flight_gravity` (the pelvis, with both feet up) it holds in flips and
    spins, where the pelvis turns about the centre of mass."""
    lowest = joints[..., 1].min(axis=1)
    air = np.r_[False, lowest > np.percentile(lowest, 2) + clearance, False]
    edges = np.flatnonzero(np.diff(air.astype(int)))
    if edges.size == 0:
        return None
    starts, ends = edges[::2], edges[1::2]
    k = int(np.argmax(ends - starts))
    if ends[k] - starts[k] < min_frames:
        return None
    t = np.arange(starts[k], ends[k])
    curvature = np.polyfit((t - t.mean()) / fps, centre_of_mass(joints)[t, 1], 2)[0]
    return float(-2.0 * curvature)


def decide_rate(native: np.ndarray, stated: float, candidates: Sequence[float], meta: dict,
                keep_stated: bool = False) -> float:
    """The capture rate of native joints (T, 22, 3) in metres at the file's frame spacing:
    estimate_true_fps with the stated rate as prior (or the stated rate itself when
    keep_stated, the estimate still recorded). Records the stated rate, the estimate, the
    per-candidate evidence (gait_stats plus `com_gravity`) and any broken-root defect in meta
    (as cmu_daz does) and returns the rate used."""
    native = np.asarray(native, dtype=np.float64)
    estimate, table = estimate_true_fps(native, candidates=tuple(candidates), prior=stated)
    meta["stated_fps"] = stated
    meta["fps_estimate"] = estimate
    evidence = {}
    for c, stats in table.items():
        row: dict = {k: (round(v, 3) if isinstance(v, float) else v) for k, v in stats.items()}
        g = com_flight_gravity(native, c)
        row["com_gravity"] = None if g is None else round(g, 2)
        evidence[f"{c:g}"] = row
    meta["fps_evidence"] = evidence
    acc = {c: s["com_acceleration_p99"] for c, s in table.items()}
    meta.setdefault("defects", [])
    if all(a > MAX_ROOT_ACCELERATION for a in acc.values()):
        rates = ", ".join(f"{a:.0f} m/s² at {c:g} fps" for c, a in sorted(acc.items()))
        meta.setdefault("defects", []).append(
            f"centre of mass accelerates implausibly at every capture rate ({rates}): broken root translation")
    rate = float(stated) if keep_stated else estimate
    meta["native_fps"] = rate
    meta["source_fps"] = rate
    return rate


def gravity_agrees(meta: dict, rate: float) -> bool | None:
    """Whether the centre of mass falls at a gravity-like rate (frame_rate.GRAVITY_RANGE) at
    `rate` in meta's evidence; None when the clip has no flight."""
    row = meta["fps_evidence"].get(f"{rate:g}", {})
    g = row.get("com_gravity")
    return None if g is None else bool(GRAVITY_RANGE[0] <= g <= GRAVITY_RANGE[1])


def check_contact(joints: np.ndarray, meta: dict) -> None:
    """Records contact_report in meta["contact_check"] and adds its defects to meta["defects"]."""
    report = contact_report(joints)
    meta["contact_check"] = report
    meta.setdefault("defects", []).extend(contact_defects(report))


def record_fit(fitted: np.ndarray, raw: np.ndarray, meta: dict) -> None:
    """The fit error of joints on fixed bones against the mapped capture (mean and max, mm)."""
    err = np.linalg.norm(fitted - raw, axis=-1)                   # (T, 22) metres
    meta["fit_error_mean_mm"] = round(float(err.mean()) * 1000, 2)
    meta["fit_error_max_mm"] = round(float(err.max()) * 1000, 2)


def settle(fitted: np.ndarray, meta: dict) -> np.ndarray:
    """One person's fitted joints in the canonical frame (its transform in meta["canonical"]),
    their foot contact checked (`check_contact`)."""
    (joints,), transform = canonicalize([fitted])
    meta["canonical"] = transform
    check_contact(joints, meta)
    return joints
