"""`interplay react actor.json --out pair.json`: the file-to-file form of the react job."""

from __future__ import annotations

import json

import numpy as np

from ..motion.metrics import clip_metrics
from ..motion.motion import Motion
from .reaction import react


def react_file(actor_motion: Motion, prompt: str | None, seed: int,
               guidance: bool = True) -> tuple[str, str]:
    """(Motion JSON text of the pair [actor, reactor], one-line summary)."""
    from ..api.motion_json import plain
    actor = np.asarray(actor_motion.people[0], dtype=np.float64)
    reactor = react(actor, prompt=prompt, seed=seed, guidance=guidance)
    people = [actor.astype(np.float32), reactor.astype(np.float32)]
    metrics = clip_metrics([p.astype(np.float64) for p in people])
    plan = {"mode": "react", "generator": "arflow", "prompt": prompt, "guidance": guidance}
    out = Motion(people, plan=plan, metrics=plain(metrics),
                 prompt=actor_motion.prompt or (prompt or ""), seed=seed)
    summary = (f"2 people, {out.frames} frames, intersection frequency "
               f"{metrics['intersection_frequency']:.3f}, volume "
               f"{metrics['intersection_volume']:.1f} cm³/frame")
    return json.dumps(plain(out.to_json()), separators=(",", ":")), summary
