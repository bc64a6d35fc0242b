"""Train ARFlow and export it (`models/arflow/train.py`'s main, which exports to
models/weights/arflow/ after training unless --no-export; `python -m models.arflow.export`
re-exports a checkpoint alone).

  python -m models.arflow [--steps N] [--budget S] [--tiny] [--out DIR] [--weights DIR]
"""

from __future__ import annotations

from models.arflow.train import main as train


def main(argv: list[str] | None = None) -> dict:
    return train(argv, prog="python -m models.arflow")


if __name__ == "__main__":
    main()
