"""The `interplay` command."""

from __future__ import annotations

import sys


def main(argv: list[str] | None = None) -> int:
    print("interplay: commands are being built", file=sys.stderr)
    return 2
