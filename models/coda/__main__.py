"""Train, choose sampling settings for, export and document CODA (`models/coda/pipeline.py`).

  python -m models.coda --all [--scale 0.5]
"""

from __future__ import annotations

import sys

import models.spam  # noqa: F401  (sets OpenMP's wait policy before torch loads)
from models.coda.pipeline import main

if __name__ == "__main__":
    main(sys.argv[1:])
