"""What the `interplay` command shares: its user error (exit code 2), reading and writing
motion files, and argument types."""

from __future__ import annotations

import argparse
import json
from pathlib import Path


class CliError(Exception):
    """A user error: printed as `interplay: error: …`, exit code 2."""


def read_motion(path: str):
    from interplay.motion.motion import Motion
    p = Path(path)
    if not p.is_file():
        raise CliError(f"{path}: no such file")
    try:
        return Motion.from_json(json.loads(p.read_text()))
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise CliError(f"{path}: not valid JSON ({exc})") from None
    except ValueError as exc:
        raise CliError(f"{path}: not a motion file: {exc}") from None


def _out_path(path: str) -> Path:
    p = Path(path)
    if p.is_dir():
        raise CliError(f"{path} is a directory; give a file name")
    if not p.parent.is_dir():
        raise CliError(f"{p.parent}: no such directory")
    return p


def write_text(path: str, text: str) -> None:
    _out_path(path).write_text(text)


def write_bytes(path: str, data: bytes) -> None:
    _out_path(path).write_bytes(data)


def seconds(text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of seconds") from None


def frame_range(text: str) -> list[int]:
    try:
        a, b = (int(x) for x in text.split(":"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a frame range a:b") from None
    if not 0 <= a < b:
        raise argparse.ArgumentTypeError(f"{text!r}: need 0 ≤ a < b") from None
    return [a, b]
