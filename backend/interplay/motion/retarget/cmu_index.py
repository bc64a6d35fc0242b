"""CMU's own trial index (`cmu-index/cmu_index.csv`): description and capture frame rate of
every trial, e.g. `2,3,"run/jog",120`. Extra columns (cgspeed's spreadsheet adds frame counts
and status) are ignored."""

from __future__ import annotations

import csv
from pathlib import Path


def read_cmu_index(path: str | Path) -> dict[tuple[int, int], tuple[str, int]]:
    """{(subject, trial): (description, capture fps)} from CMU's index CSV."""
    out: dict[tuple[int, int], tuple[str, int]] = {}
    with open(path, newline="", encoding="utf-8", errors="replace") as f:
        rows = csv.reader(f)
        header = next(rows, None)
        if not header or len(header) < 4 or "subject" not in header[0].lower():
            raise ValueError(f"{path}: expected a header 'Subject, Trial #, Motion Description, framerate'")
        for line, row in enumerate(rows, start=2):
            if not row or not row[0].strip():
                continue
            try:
                subject, trial, fps = int(row[0]), int(row[1]), int(float(row[3]))
            except (IndexError, ValueError):
                raise ValueError(f"{path}:{line}: cannot read subject/trial/framerate from {row[:4]}") from None
            out[(subject, trial)] = (row[2].strip(), fps)
    return out
