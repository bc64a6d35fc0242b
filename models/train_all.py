"""`make train`: retrain every model from the processed data, export ONNX to models/weights/
and write the model cards. The list below is the whole of it, in order, each entry the
model's own command:

  1. SPAM, its ablations and the text–motion evaluator   python -m models.spam --all
     and the evaluator's export and card                 python -m models.evaluator.export
  2. the text ↔ pair evaluator (eval-pair's FID)          python -m models.pair_evaluator
  3. ARFlow, two-person reactions                        python -m models.arflow
  4. CODA, two-person generation                         python -m models.coda --all

  python -m models.train_all [--scale 0.5]     (--scale: SPAM's and CODA's time budgets)
"""

from __future__ import annotations

import sys


def main(argv: list[str] | None = None) -> None:
    from models.arflow.__main__ import main as arflow
    from models.coda.__main__ import main as coda
    from models.evaluator.export import main as evaluator_export
    from models.pair_evaluator.__main__ import main as pair_evaluator
    from models.spam.__main__ import main as spam

    spam(["--all", *(argv or [])])
    evaluator_export([])      # SPAM's pipeline trains the evaluator; this ships it
    pair_evaluator([])
    arflow([])
    coda(["--all", *(argv or [])])


if __name__ == "__main__":
    main(sys.argv[1:])
