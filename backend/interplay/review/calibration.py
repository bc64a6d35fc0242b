"""The evaluators' calibration at run time (numpy only): the threshold under which a segment's
evaluator score fails it, and a logistic fit of P(the motion shows its words | score) that
other code puts into a segment's `coverage.confidence`.

`calibration.json` lives beside the weights it was measured with (models/weights/evaluator/,
models/weights/pair_evaluator/) and records their sha256: a calibration of other weights is
not used (the reviewer then judges without a threshold and says so in the log). It is written
by `interplay review-calibrate` (`interplay.eval.calibrate`) on the held-out test split and
read once, when the evaluator loads (`EvaluatorRuntime.load` → `.calibration`).

    cal = load_calibration(DEFAULT_DIR)      # None when absent or for other weights
    cal.passes(0.087)                        # False: 0.087 < cal.threshold
    cal.confidence(0.087)                    # 0.03
    confidence(0.42)                         # the shipped single-person evaluator's
"""

from __future__ import annotations

import hashlib
import json
import logging
import math
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from interplay.settings import REPO_ROOT

log = logging.getLogger(__name__)
FILE = "calibration.json"
WEIGHT_FILES = ("motion_encoder.onnx", "text_proj.npz", "normalizer.npz")
EVALUATOR_DIR = REPO_ROOT / "models" / "weights" / "evaluator"
PAIR_EVALUATOR_DIR = REPO_ROOT / "models" / "weights" / "pair_evaluator"


def weights_sha256(directory: str | Path) -> str:
    """One sha256 over an evaluator's weight files (names and bytes, in a fixed order)."""
    h = hashlib.sha256()
    for name in WEIGHT_FILES:
        h.update(name.encode())
        h.update((Path(directory) / name).read_bytes())
    return h.hexdigest()


@dataclass(frozen=True)
class Calibration:
    """A calibrated evaluator: `threshold` on its cosine, P(match | s) = σ(a·s + b)."""
    threshold: float
    a: float
    b: float
    kind: str = "evaluator"            # "evaluator" | "pair_evaluator"
    weights_sha256: str = ""
    domain: dict = field(default_factory=dict)     # pair: the texts it can judge (see from_json)

    def passes(self, score: float) -> bool:
        return float(score) >= self.threshold

    def confidence(self, score: float) -> float:
        """Calibrated P(the motion shows the text | its score), in [0, 1]."""
        z = self.a * float(score) + self.b
        return 1.0 / (1.0 + math.exp(-z)) if z >= 0 else math.exp(z) / (1.0 + math.exp(z))

    @classmethod
    def from_json(cls, data: dict) -> "Calibration":
        return cls(threshold=float(data["threshold"]), a=float(data["logistic"]["a"]),
                   b=float(data["logistic"]["b"]), kind=str(data.get("kind", "evaluator")),
                   weights_sha256=str(data.get("weights_sha256", "")),
                   domain=dict(data.get("domain") or {}))


def load_calibration(directory: str | Path, check: bool = True) -> Calibration | None:
    """The calibration beside an evaluator's weights, or None when there is none or (`check`)
    it was measured on other weights."""
    path = Path(directory) / FILE
    if not path.is_file():
        return None
    data = json.loads(path.read_text())
    cal = Calibration.from_json(data)
    if check:
        try:
            actual = weights_sha256(directory)
        except OSError:
            return None
        if actual != cal.weights_sha256:
            log.warning("%s was measured on other weights (sha256 %s…, these are %s…): not used; "
                        "run `interplay review-calibrate`", path, cal.weights_sha256[:12], actual[:12])
            return None
    return cal


@lru_cache(maxsize=4)
def _default(kind: str) -> Calibration | None:
    return load_calibration(PAIR_EVALUATOR_DIR if kind == "pair_evaluator" else EVALUATOR_DIR)


def confidence(score: float, kind: str = "evaluator") -> float | None:
    """The shipped evaluator's (`kind`: "evaluator" or "pair_evaluator") calibrated confidence
    that a motion shows its words given its cosine `score`; None without a calibration."""
    cal = _default(kind)
    return None if cal is None else cal.confidence(score)
