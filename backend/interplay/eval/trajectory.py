"""Measure the trajectory editor on real walks: for each curve shape, how far the walk ends from
the curve's end, how well the facing follows the curve's tangent, and foot skating before and
after (metrics.foot_skating: mean horizontal speed of planted foot joints, m/s).

    python -m interplay.eval.trajectory [--json] [--keep-size] [--data DIR]

The walks are the processed set's test-split clips prompted "a person walks forward".
"""

from __future__ import annotations

import argparse
import json
from dataclasses import replace

import numpy as np

from interplay.motion.clip import DATA_DIR, Clip, default_clips
from interplay.motion.kinematics import facing_angle
from interplay.trajectory.apply import (
    DEFAULT,
    TrajectoryConfig,
    anchor_pose,
    map_trajectory,
    skating,
    travel,
)
from interplay.trajectory.curves import make_curve

WALK_PROMPT = "a person walks forward"


def free_drawing(seed: int = 0) -> list[list[float]]:
    """A stand-in for a path drawn in the browser: a wavy 5 m stroke sampled at uneven mouse
    intervals with 2 cm of hand jitter, starting at the origin heading +Z."""
    rng = np.random.default_rng(seed)
    t = np.cumsum(rng.uniform(0.3, 1.7, 120))
    t = (t - t[0]) / (t[-1] - t[0])
    pts = np.stack([0.6 * np.sin(2.5 * np.pi * t) * t, 5.0 * t], axis=1)
    pts[1:] += rng.normal(0.0, 0.02, (len(pts) - 1, 2))
    return pts.round(4).tolist()


EXAMPLE_SPECS: dict[str, dict] = {
    "line": {"shape": "line"},
    "arc": {"shape": "arc"},
    "circle": {"shape": "circle"},
    "circle cw": {"shape": "circle", "clockwise": True},
    "zigzag": {"shape": "zigzag"},
    "s_curve": {"shape": "s_curve"},
    "heart": {"shape": "heart"},
    "figure_eight": {"shape": "figure_eight"},
    "square": {"shape": "square"},
    "spiral": {"shape": "spiral"},
    "polyline": {"shape": "polyline", "waypoints": [[0.0, 2.0], [-1.5, 3.5], [-1.5, 5.0]]},
    "free": {"shape": "free", "waypoints": free_drawing()},
}


def walk_clips(data_dir: str = str(DATA_DIR)) -> list[Clip]:
    return [c for c in default_clips(data_dir) if c.prompt == WALK_PROMPT and c.split == "test"]


def heading_error(joints: np.ndarray, curve: np.ndarray) -> np.ndarray:
    """Degrees (T,) between each frame's facing direction and the tangent of the curve (M, 2)
    at the curve point nearest the pelvis."""
    pelvis = joints[:, 0][:, [0, 2]]
    near = np.linalg.norm(pelvis[:, None] - curve[None], axis=-1).argmin(axis=1)
    tangent = np.gradient(curve, axis=0)[near]
    diff = facing_angle(joints) - np.arctan2(tangent[:, 0], tangent[:, 1])
    return np.degrees(np.abs((diff + np.pi) % (2 * np.pi) - np.pi))


def _placed(raw: np.ndarray, joints: np.ndarray, scale: float, cfg: TrajectoryConfig) -> np.ndarray:
    """The requested curve (N, 2) where the editor put it (trajectory.anchor_pose), scaled about
    its start as the editor scaled it."""
    origin, a = anchor_pose(joints, travel(joints, cfg=cfg), cfg=cfg)
    pts = raw
    if cfg.anchor != "world":
        rel = raw - raw[0]
        pts = origin + np.stack([np.cos(a) * rel[:, 0] + np.sin(a) * rel[:, 1],
                                 -np.sin(a) * rel[:, 0] + np.cos(a) * rel[:, 1]], axis=1)
    return pts[0] + scale * (pts - pts[0])


def _point_along(pts: np.ndarray, s: float) -> np.ndarray:
    """The point s metres along a polyline (N, 2), straight on past its end."""
    arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(pts, axis=0), axis=1))])
    if s >= arc[-1]:
        d = pts[-1] - pts[-2]
        return pts[-1] + (s - arc[-1]) * d / np.linalg.norm(d)
    return np.array([np.interp(s, arc, pts[:, i]) for i in range(2)])


def measure(joints: np.ndarray, spec: dict, cfg: TrajectoryConfig = DEFAULT) -> dict:
    """One walk on one curve, against the requested (raw) curve placed as the editor placed it:
    end error (m) from the curve's end (None when the curve keeps its size: the walk then ends
    wherever its own distance takes it), the pelvis's largest distance from the curve (m,
    carried on straight past its end), the share of the curve's length walked, median heading
    error (degrees), skating before / turned without foot pinning / after (m/s), the largest
    ankle move the pinning made (m) and the 95th percentile turning rate (degrees/s)."""
    joints = np.asarray(joints, dtype=np.float64)
    raw = make_curve(spec)
    result = map_trajectory(joints, raw, cfg=cfg)
    unpinned = map_trajectory(joints, raw, cfg=replace(cfg, pin_feet=False))["joints"]
    placed = _placed(raw, joints, result["scale"], cfg)
    walked = travel(joints, cfg=cfg).s[-1]
    total = float(np.linalg.norm(np.diff(placed, axis=0), axis=1).sum())
    on = np.concatenate([placed] + [[_point_along(placed, total + d)]
                                    for d in np.arange(0.01, max(walked - total, 0.0) + 0.01, 0.01)])
    out = result["joints"]
    pelvis = out[:, 0, [0, 2]]
    ankles = [7, 8]
    return {
        "end_error": float(np.linalg.norm(pelvis[-1] - placed[-1])) if cfg.scale_to_motion else None,
        "path_error": float(np.linalg.norm(pelvis[:, None] - on[None], axis=-1).min(axis=1).max()),
        "walked_share": float(walked / total),
        "heading_error": float(np.median(heading_error(out, result["curve"]))),
        "skating_before": skating(joints), "skating_unpinned": skating(unpinned),
        "skating_after": skating(out), "scale": result["scale"],
        "foot_shift": float(np.linalg.norm((out - unpinned)[:, ankles][..., [0, 2]], axis=-1).max()),
        "turn_rate": float(np.percentile(np.degrees(np.abs(np.diff(result["turn"]))) * 20, 95)),
    }


def shape_table(clips: list[Clip] | None = None, specs: dict[str, dict] = EXAMPLE_SPECS,
                cfg: TrajectoryConfig = DEFAULT) -> list[dict]:
    """Per shape, over the walks: mean and worst end error (cm), worst distance of the pelvis
    from the curve (cm), mean share of the curve walked, median heading error (deg), mean
    skating before / unpinned / after
    (m/s), worst after/before ratio, mean curve scale, worst ankle move by the pinning (cm),
    mean 95th percentile turning rate (deg/s)."""
    clips = walk_clips() if clips is None else clips
    rows = []
    for name, spec in specs.items():
        ms = [measure(c.people[0], spec, cfg) for c in clips]
        col = {k: np.array([m[k] for m in ms], dtype=float) for k in ms[0]}
        rows.append({
            "shape": name, "walks": len(ms),
            "end_cm_mean": float(col["end_error"].mean() * 100) if cfg.scale_to_motion else None,
            "end_cm_max": float(col["end_error"].max() * 100) if cfg.scale_to_motion else None,
            "walked_share": float(col["walked_share"].mean()),
            "path_cm_max": float(col["path_error"].max() * 100),
            "heading_deg": float(np.median(col["heading_error"])),
            "skating_before": float(col["skating_before"].mean()),
            "skating_unpinned": float(col["skating_unpinned"].mean()),
            "skating_after": float(col["skating_after"].mean()),
            "skating_ratio_max": float((col["skating_after"] / col["skating_before"]).max()),
            "scale": float(col["scale"].mean()),
            "foot_shift_cm_max": float(col["foot_shift"].max() * 100),
            "turn_rate_p95": float(col["turn_rate"].mean()),
        })
    return rows


def markdown(rows: list[dict]) -> str:
    head = ("| shape | walks | end error cm (mean / max) | pelvis off curve, cm (max) | share of "
            "curve walked | heading error ° (median) | skating m/s: before → turned, no pinning → "
            "after | worst after/before | curve scale | ankle moved by pinning, cm (max) | "
            "turning °/s (p95) |\n|---|---|---|---|---|---|---|---|---|---|---|")
    end = lambda r: ("–" if r["end_cm_mean"] is None
                     else f"{r['end_cm_mean']:.1f} / {r['end_cm_max']:.1f}")
    lines = [f"| {r['shape']} | {r['walks']} | {end(r)} | {r['path_cm_max']:.1f} | "
             f"{r['walked_share']:.2f} | {r['heading_deg']:.1f} | {r['skating_before']:.3f} → "
             f"{r['skating_unpinned']:.3f} → {r['skating_after']:.3f} | {r['skating_ratio_max']:.2f} | "
             f"{r['scale']:.2f} | {r['foot_shift_cm_max']:.0f} | {r['turn_rate_p95']:.0f} |"
             for r in rows]
    return "\n".join([head] + lines)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(prog="python -m interplay.eval.trajectory",
                                     description=__doc__.split("\n\n")[0])
    parser.add_argument("--json", action="store_true", help="print the rows as JSON")
    parser.add_argument("--data", default=str(DATA_DIR), help="processed data directory")
    parser.add_argument("--keep-size", action="store_true",
                        help="keep each curve's own size (scale_to_motion=False)")
    args = parser.parse_args(argv)
    cfg = replace(DEFAULT, scale_to_motion=not args.keep_size)
    rows = shape_table(walk_clips(args.data), cfg=cfg)
    print(json.dumps(rows, indent=1) if args.json else markdown(rows))


if __name__ == "__main__":
    main()
