"""Committed model weights: whether a weights folder may be served (an untrained placeholder
export loads but must not be), shared by SPAM's and CODA's loaders."""

from __future__ import annotations

import json
from pathlib import Path


def placeholder_reason(weights_dir: Path, model: str) -> str | None:
    """Why `model`'s weights in `weights_dir` must not be served although they load: an
    untrained placeholder export (config.json "trained": false, or a model card titled as a
    placeholder); None when they may be served."""
    try:
        if json.loads((weights_dir / "config.json").read_text()).get("trained") is False:
            return f"the {model} weights in {weights_dir} are marked untrained"
    except (OSError, ValueError):
        return None
    card = weights_dir / "MODEL_CARD.md"
    title = next((ln for ln in card.read_text().splitlines() if ln.strip()), "") if card.is_file() else ""
    if "placeholder" in title.lower() or "untrained" in title.lower():
        return f"the {model} weights in {weights_dir} are an untrained placeholder"
    return None
