"""Per-frame highlights of a motion as the studio draws them: who touches where (contacts),
which body parts interpenetrate, and the two people's closest distance; the same lists for
streamed chunks and for stored motions."""

from __future__ import annotations

import numpy as np

from interplay.motion.metrics import frame_highlights
from interplay.pipeline.motion_json import plain


def highlight_lists(window: list[np.ndarray], skip: int, persons: int) -> dict:
    """{contacts, penetration, min_distance} of `window` (one (n, 22, 3) array per person)
    without its first `skip` frames, which are context (velocity-based contacts need the frame
    before): contacts [[person, joint], …] and penetration [[person, part], …] per frame,
    min_distance per frame for two people (None for one)."""
    h = plain(frame_highlights(window))
    dist = h.get("min_distance")
    return {
        "contacts": [[[int(p), int(j)] for p, j in f] for f in h["contacts"][skip:]],
        "penetration": [[[int(p), str(part)] for p, part in f] for f in h["penetration"][skip:]],
        "min_distance": ([None if d is None else round(float(d), 4) for d in dist[skip:]]
                         if persons > 1 and dist is not None else None),
    }
