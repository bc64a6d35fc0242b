"""Which processed sources a training run uses, and what the model card says about them.

`make train` trains on every source in `models/data`. `make train EXCLUDE_NONCOMMERCIAL=1`
(`python -m models.train_all --exclude-noncommercial`, or INTERPLAY_EXCLUDE_NONCOMMERCIAL=1 for
one model's own command) leaves out every clip whose licence forbids commercial use (Bandai
Namco's CC BY-NC 4.0, `interplay.data.licences`), so the weights carry no non-commercial term.
Every trainer takes its clips from `training_clips`, records `training_data(...)` with its
numbers, and its card prints `licence_section(...)` from them.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

from interplay.data.licences import SOURCE_LICENCE, commercial_only, is_noncommercial, weights_notice
from interplay.motion.clip import DATA_DIR, Clip, default_clips

ENV = "INTERPLAY_EXCLUDE_NONCOMMERCIAL"


def excluding_noncommercial() -> bool:
    """Whether this training run leaves out non-commercial data (the environment switch)."""
    return os.environ.get(ENV, "").strip().lower() in ("1", "true", "yes")


def set_excluding_noncommercial(on: bool) -> None:
    """Turn the switch on or off for this process (and the stages it runs)."""
    if on:
        os.environ[ENV] = "1"
    else:
        os.environ.pop(ENV, None)


def training_clips(data_dir: str | Path = DATA_DIR, clips: Iterable[Clip] | None = None) -> list[Clip]:
    """The clips a training run may use: `clips` (default: the processed set in data_dir)
    without the non-commercial ones when the switch is on."""
    pool = list(default_clips(str(data_dir)) if clips is None else clips)
    return commercial_only(pool, excluding_noncommercial())


def training_data(clips: Iterable[Clip]) -> dict:
    """What a card needs to know about the clips weights were trained on: their sources (with
    clip counts), the licence strings, and whether non-commercial data was left out."""
    clips = list(clips)
    sources: dict[str, int] = {}
    for c in clips:
        sources[c.source] = sources.get(c.source, 0) + 1
    return {"sources": dict(sorted(sources.items())),
            "licences": sorted({c.licence for c in clips}),
            "excluded_noncommercial": excluding_noncommercial(),
            "noncommercial_clips": sum(is_noncommercial(c.licence) for c in clips)}


def licence_section(info: dict | None) -> list[str]:
    """The model card's "Training data and licence" section from `training_data`'s record
    (None: weights trained before the record existed, on CMU and HDM05 data only)."""
    lines = ["## Training data and licence", ""]
    if not info:
        return lines + ["Trained before the card recorded its sources: on the CMU (cmu-bvh, cmu-salsa, "
                        "cmu-8action) and HDM05 clips of `models/data` and composed pairs of them.", "",
                        *weights_notice(["CMU", "CC BY-SA 3.0 (HDM05)"]), ""]
    used = ", ".join(f"{s} ({n} clips)" for s, n in info["sources"].items())
    lines.append(f"Trained on: {used}.")
    if info["excluded_noncommercial"]:
        left_out = sorted(s for s, lic in SOURCE_LICENCE.items() if not lic.commercial)
        lines.append(f"Retrained with `--exclude-noncommercial` (`make train EXCLUDE_NONCOMMERCIAL=1`): "
                     f"no clip of {', '.join(left_out)} or any other non-commercial source was used.")
    lines += ["", *weights_notice(info["licences"]), ""]
    return lines
