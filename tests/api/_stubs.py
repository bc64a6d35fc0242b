"""TEMPORARY: stand-ins for modules other engineers are still writing (removed once they land)."""
import sys
import types
from dataclasses import dataclass

import numpy as np

try:
    import interplay.agents.generator  # noqa: F401
except ImportError:
    m = types.ModuleType("interplay.agents.generator")

    @dataclass(frozen=True)
    class Request:
        prompt: str
        persons: int = 1
        seconds: float = 6.0
        seed: int | None = None
    m.Request = Request
    sys.modules[m.__name__] = m

try:
    import interplay.motion.metrics  # noqa: F401
except ImportError:
    m = types.ModuleType("interplay.motion.metrics")

    def clip_metrics(people, fps=20):
        return {"bone_deviation": 0.0, "floating": float(np.mean(people[0][..., 1].min(-1)))}

    def frame_highlights(people):
        t = people[0].shape[0]
        feet = [[[p, 10]] if x[i, 10, 1] < 0.05 else [] for i in range(t) for p, x in [(0, people[0])]]
        d = (np.linalg.norm(people[0][:, None] - people[1][:, :, None], axis=-1).min((1, 2))
             if len(people) > 1 else np.full(t, np.nan))
        return {"contacts": feet, "penetration": [[] for _ in range(t)], "min_distance": d}
    m.clip_metrics, m.frame_highlights = clip_metrics, frame_highlights
    sys.modules[m.__name__] = m

try:
    import interplay.motion.bvh  # noqa: F401
except ImportError:
    m = types.ModuleType("interplay.motion.bvh")
    m.write_bvh = lambda joints, fps=20, offsets=None: f"HIERARCHY\nROOT pelvis\nMOTION\nFrames: {len(joints)}\n"
    sys.modules[m.__name__] = m
