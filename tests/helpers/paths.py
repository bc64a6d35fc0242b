"""Where the tests find the repository and its committed raw capture fixtures."""

from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
RAW = REPO / "tests" / "fixtures" / "raw"     # small real captures of every source format
