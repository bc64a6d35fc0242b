"""`make train`: retrain every model from the processed data, export ONNX to models/weights/
and write the model cards. The list below is the whole of it, in order:

  1. SPAM, its ablations and the text–motion evaluator   python -m models.spam --all
  2. the text ↔ pair evaluator (eval-pair's FID)          models.pair_evaluator.train + export
  3. ARFlow, two-person reactions                        models.arflow.train
  4. CODA, two-person generation                         python -m models.coda --all

  python -m models.train_all [--scale 0.5]
"""

from __future__ import annotations

import sys

import models.spam  # noqa: F401  (sets OpenMP's wait policy before torch loads)


def main(argv: list[str] | None = None) -> None:
    from models.arflow.train import main as arflow
    from models.coda.pipeline import main as coda
    from models.pair_evaluator.export import main as pair_evaluator_export
    from models.pair_evaluator.train import main as pair_evaluator
    from models.spam.__main__ import main as spam

    spam(["--all", *(argv or [])])
    pair_evaluator([])
    pair_evaluator_export([])
    arflow([])
    coda(["--all", *(argv or [])])


if __name__ == "__main__":
    main(sys.argv[1:])
