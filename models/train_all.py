"""`make train`: retrain every single-person model from the processed data (SPAM, its
ablations, the text–motion evaluator when present), export ONNX and write the model card.

  python -m models.train_all [--scale 0.5]
"""

from __future__ import annotations

import models.spam  # noqa: F401  (sets OpenMP's wait policy before torch loads)
from models.spam.train import main as spam_main


def main(argv: list[str] | None = None) -> None:
    spam_main(["--all", *(argv or [])])
    from models.arflow.train import main as arflow_main   # two-person reactions (≤ 15 min)
    arflow_main([])


if __name__ == "__main__":
    import sys

    main(sys.argv[1:])
