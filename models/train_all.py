"""`make train`: retrain every model from the processed data, export ONNX to models/weights/
and write the model cards. The list below is the whole of it, in order, each entry the
model's own command:

  1. SPAM, its ablations and the text–motion evaluator   python -m models.spam --all
     and the evaluator's export and card                 python -m models.evaluator.export
  2. the text ↔ pair evaluator (eval-pair's FID)          python -m models.pair_evaluator
  3. ARFlow, two-person reactions                        python -m models.arflow
  4. CODA, two-person generation                         python -m models.coda --all

  python -m models.train_all [--scale 0.5] [--exclude-noncommercial]
      --scale: SPAM's and CODA's time budgets
      --exclude-noncommercial (`make train EXCLUDE_NONCOMMERCIAL=1`): every stage trains
      without the clips whose licence forbids commercial use (Bandai Namco, CC BY-NC 4.0), so
      the weights carry no non-commercial term; each model card says so
      (models/common/sources.py). By default every source in models/data is used.
"""

from __future__ import annotations

import sys


def main(argv: list[str] | None = None) -> None:
    from models.arflow.__main__ import main as arflow
    from models.coda.__main__ import main as coda
    from models.common.sources import set_excluding_noncommercial
    from models.evaluator.export import main as evaluator_export
    from models.pair_evaluator.__main__ import main as pair_evaluator
    from models.spam.__main__ import main as spam

    argv = list(argv or [])
    if "--exclude-noncommercial" in argv:
        argv.remove("--exclude-noncommercial")
        set_excluding_noncommercial(True)
    spam(["--all", *argv])
    evaluator_export([])      # SPAM's pipeline trains the evaluator; this ships it
    pair_evaluator([])
    arflow([])
    coda(["--all", *argv])


if __name__ == "__main__":
    main(sys.argv[1:])
