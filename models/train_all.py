"""`make train`: retrain every single-person model from the processed data (SPAM, its
ablations, the text–motion evaluator when present), the pair evaluator, ARFlow and CODA (two-person
generation, models/coda, ≤ 25 min), export ONNX
and write the model cards.

  python -m models.train_all [--scale 0.5]
"""

from __future__ import annotations

import models.spam  # noqa: F401  (sets OpenMP's wait policy before torch loads)
from models.spam.train import main as spam_main


def main(argv: list[str] | None = None) -> None:
    spam_main(["--all", *(argv or [])])
    # the text ↔ pair evaluator behind eval-react's FID (≤ 5 min), then its export and card
    from models.pair_evaluator.export import main as pair_export
    from models.pair_evaluator.train import main as pair_train
    pair_train([])
    pair_export([])
    from models.arflow.train import main as arflow_main   # two-person reactions (≤ 15 min)
    arflow_main([])
    from models.coda.train import main as coda_main       # two-person generation (≤ 25 min)
    coda_main(["--all", *(argv or [])])


if __name__ == "__main__":
    import sys

    main(sys.argv[1:])
