"""The studio's green / amber / red bands for the clip metrics (frontend/src/ui/metricBands.json),
from the real motion captures of the processed data set (interplay.motion.clip.default_clips(),
synthetic pairs left out): every 4 s window (2 s apart, like a studio motion) of every real
capture is measured with interplay.motion.metrics.clip_metrics — one-person metrics per person
(CMU, HDM05, the salsa dancers each alone), two-person metrics on the real pairs (CMU salsa).

For a metric where less is better the band is green up to the 90th percentile of the captures
(what nine in ten real motions reach), amber up to their 99th, red beyond; for the closest
distance between two people (less is worse: below zero the bodies are inside each other) it is
the mirror image (green from the 10th percentile up, amber from the 1st). A floor keeps a
band from being narrower than what matters on screen (`FLOOR`, a millimetre or so): the
captures' bone deviation (IK fitting noise, ~0.2 mm) and ground penetration (~0) are so small
that a band that narrow would paint a generated motion amber for a fraction of a millimetre.

    .venv/bin/python frontend/scripts/metric_bands.py > frontend/src/ui/metricBands.json
"""

from __future__ import annotations

import json
import sys
from collections import Counter

import numpy as np

from interplay.motion.clip import default_clips
from interplay.motion.metrics import clip_metrics
from interplay.motion.skeleton import FPS

WINDOW_S, STRIDE_S = 4.0, 2.0
LOWER_IS_BETTER = ["foot_skating", "skating_ratio", "bone_deviation", "ground_penetration",
                   "floating", "intersection_volume", "intersection_frequency"]
HIGHER_IS_BETTER = ["min_distance"]
# The smallest thresholds worth showing, in the metric's own unit (m, m/s, share, cm³).
FLOOR = {"bone_deviation": 0.001, "ground_penetration": 0.001, "floating": 0.005,
         "foot_skating": 0.01, "skating_ratio": 0.01, "intersection_volume": 1.0,
         "intersection_frequency": 0.01}


def windows(people: list[np.ndarray]):
    t = people[0].shape[0]
    n, step = int(WINDOW_S * FPS), int(STRIDE_S * FPS)
    if t <= n:
        yield people
        return
    for a in range(0, t - n + 1, step):
        yield [p[a:a + n] for p in people]


def main() -> None:
    clips = [c for c in default_clips() if not c.synthetic]
    single: dict[str, list[float]] = {}
    pair: dict[str, list[float]] = {}
    sources: Counter = Counter()
    for c in clips:
        sources[c.source] += 1
        for w in windows(c.people):
            for p in w:
                for k, v in clip_metrics([p]).items():
                    single.setdefault(k, []).append(v)
            if len(w) == 2:
                for k, v in clip_metrics(w).items():
                    if k in ("intersection_volume", "intersection_frequency", "min_distance"):
                        pair.setdefault(k, []).append(v)
    values = {**single, **pair}
    bands = {}
    for k in LOWER_IS_BETTER + HIGHER_IS_BETTER:
        v = np.asarray(values[k], dtype=np.float64)
        q = {f"p{p}": float(np.percentile(v, p)) for p in (1, 10, 50, 90, 99)}
        if k in LOWER_IS_BETTER:
            floor = FLOOR.get(k, 0.0)
            green, amber = max(q["p90"], floor), max(q["p99"], 2 * floor)
            band = {"better": "lower", "green": green, "amber": amber}
        else:
            band = {"better": "higher", "green": q["p10"], "amber": q["p1"]}
        bands[k] = {**band, "windows": int(v.size), **{n: round(x, 6) for n, x in q.items()}}
        for n in ("green", "amber"):
            bands[k][n] = float(f"{bands[k][n]:.4g}")
    out = {
        "about": "Green/amber/red bands of the clip metrics from real captures; made by "
                 "frontend/scripts/metric_bands.py (see its docstring and docs/studio.md).",
        "window_s": WINDOW_S, "stride_s": STRIDE_S,
        "captures": dict(sorted(sources.items())),
        "bands": bands,
    }
    json.dump(out, sys.stdout, indent=2)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
