"""Parsing BVH text for `formats/bvh.read_bvh`: the sections, the HIERARCHY's tokens (ROOTs,
JOINTs, End Sites, OFFSETs, CHANNELS; any order of channels, tabs or spaces, CRLF line ends) and
the MOTION header's words, with a readable ValueError for what is not BVH. numpy only.

    names, parents, offsets, channels, end_sites = parse_hierarchy(tokens)
"""

from __future__ import annotations

from pathlib import Path

import numpy as np


def channel(name: str) -> tuple[str, str] | None:
    """A channel name's (axis, kind): "Xposition" → ("X", "position"), any case; None if not one."""
    axis, kind = name[:1].upper(), name[1:].lower()
    return (axis, kind) if axis in ("X", "Y", "Z") and kind in ("position", "rotation") else None


def section(text: str, word: str) -> tuple[int, int] | None:
    """(start, end) of the first line that holds only `word` (any case, spaces around it)."""
    at = 0
    for line in text.split("\n"):
        if line.strip().upper() == word:
            return at, at + len(line)
        at += len(line) + 1
    return None


def words_after(text: str, *words: str) -> str | None:
    """The text after `words` at its start (any case; spaces before the first, at least one
    between the others, any after the last), or None when it does not start so."""
    for i, word in enumerate(words):
        if i and not text[:1].isspace():
            return None
        text = text.lstrip()
        if text[:len(word)].lower() != word.lower():
            return None
        text = text[len(word):]
    return text.lstrip()


def digits(text: str) -> str:
    """The digits `text` starts with."""
    return text[:next((i for i, c in enumerate(text) if not c.isdecimal()), len(text))]




def read_text(text_or_path: str | Path) -> str:
    if isinstance(text_or_path, Path):
        return text_or_path.read_text()
    if "HIERARCHY" in text_or_path[:256].upper():
        return text_or_path
    path = Path(text_or_path)
    if not path.is_file():
        raise ValueError(f"not BVH text and no such file: {text_or_path[:80]!r}")
    return path.read_text()


def parse_hierarchy(tokens: list[str]):
    names: list[str] = []
    parents: list[int] = []
    offsets: list[np.ndarray] = []
    channels: list[tuple[str, ...]] = []
    end_sites: list[list] = []             # [parent joint, offset]
    stack: list[tuple[str, int]] = []      # open blocks: ("joint", j) or ("end", e)
    pending: tuple[str, int] | None = None
    i = 0
    while i < len(tokens):
        tok, key = tokens[i], tokens[i].upper()
        if key in ("ROOT", "JOINT"):
            if i + 1 >= len(tokens):
                raise ValueError(f"{tok} without a name")
            joints_open = [j for kind, j in stack if kind == "joint"]
            if key == "JOINT" and not joints_open:
                raise ValueError(f"JOINT {tokens[i + 1]} outside any ROOT")
            if key == "ROOT" and stack:
                raise ValueError(f"ROOT {tokens[i + 1]} inside another joint")
            names.append(tokens[i + 1])
            parents.append(joints_open[-1] if key == "JOINT" else -1)
            offsets.append(np.zeros(3))
            channels.append(())
            pending = ("joint", len(names) - 1)
            i += 2
        elif key == "END":
            if i + 1 >= len(tokens) or tokens[i + 1].upper() != "SITE" or not stack or stack[-1][0] != "joint":
                raise ValueError("End Site must follow 'End' and sit inside a joint")
            end_sites.append([stack[-1][1], np.zeros(3)])
            pending = ("end", len(end_sites) - 1)
            i += 2
        elif tok == "{":
            if pending is None:
                raise ValueError("'{' without a ROOT/JOINT/End Site before it")
            stack.append(pending)
            pending = None
            i += 1
        elif tok == "}":
            if not stack:
                raise ValueError("unbalanced '}' in HIERARCHY")
            stack.pop()
            i += 1
        elif key == "OFFSET":
            if not stack:
                raise ValueError("OFFSET outside a joint")
            try:
                value = np.array([float(v) for v in tokens[i + 1:i + 4]])
            except ValueError:
                raise ValueError(f"bad OFFSET {tokens[i + 1:i + 4]}") from None
            if value.shape != (3,):
                raise ValueError("OFFSET needs three numbers")
            kind, k = stack[-1]
            if kind == "joint":
                offsets[k] = value
            else:
                end_sites[k][1] = value
            i += 4
        elif key == "CHANNELS":
            if not stack or stack[-1][0] != "joint":
                raise ValueError("CHANNELS outside a joint")
            try:
                count = int(tokens[i + 1])
            except (IndexError, ValueError):
                raise ValueError("CHANNELS needs a count") from None
            chans = tuple(tokens[i + 2:i + 2 + count])
            bad = [c for c in chans if not channel(c)]
            if len(chans) != count or bad:
                raise ValueError(f"bad CHANNELS for {names[stack[-1][1]]}: {chans}")
            channels[stack[-1][1]] = chans
            i += 2 + count
        else:
            raise ValueError(f"unexpected token {tok!r} in HIERARCHY")
    if stack:
        raise ValueError("HIERARCHY ends with unclosed braces")
    if not names:
        raise ValueError("HIERARCHY has no ROOT")
    return names, parents, offsets, channels, end_sites

