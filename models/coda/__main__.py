"""Train, choose sampling settings for, export and document CODA (`models/coda/pipeline.py`).

  python -m models.coda --all [--scale 0.5] [--early]
"""

from __future__ import annotations

from models.coda.pipeline import main as pipeline


def main(argv: list[str] | None = None) -> None:
    pipeline(argv, prog="python -m models.coda")


if __name__ == "__main__":
    main()
