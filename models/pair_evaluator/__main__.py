"""Train the text ↔ pair evaluator, then export it and write its card: `train.py`'s main, then
`export.py`'s on the checkpoint it wrote (each also runs alone:
`python -m models.pair_evaluator.train`, `python -m models.pair_evaluator.export`).

  python -m models.pair_evaluator [--steps N] [--seconds S] [--tiny] [--out DIR] [--weights DIR]
"""

from __future__ import annotations

from models.evaluator.cli import train_and_export
from models.pair_evaluator import export, train


def main(argv: list[str] | None = None) -> int:
    return train_and_export(argv, "python -m models.pair_evaluator", __doc__.split("\n")[0],
                            train.main, export.main, train.DEFAULT_OUT, "pair_evaluator.pt",
                            export.WEIGHTS)


if __name__ == "__main__":
    raise SystemExit(main())
