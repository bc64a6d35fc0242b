"""A pose struck while travelling is a second step: "runs in a zigzag while striking a T-pose"
→ "runs in a zigzag, then runs in a zigzag holding a T-pose" (the pose is then held while the
travel goes on). The pose is one the lexicon names with a held form (`hold` in actions.toml);
what opens it ("while striking", "while getting into") is words.toml's `striking_while`.
"""

from __future__ import annotations

from interplay.catalogue.words import words
from interplay.planner import lexicon, temporal
from interplay.planner.decompose import split_subject
from interplay.planner.verbs import lookup


def onset_poses(text: str) -> tuple[str, list[str]]:
    """"runs in a zigzag while striking <pose>" → "runs in a zigzag, then runs in a zigzag holding
    <pose>": a pose struck during travel is a second step (the pose is then held)."""
    struck = _struck(text)
    if struck is None:
        return text, []
    begin, pose, end = struck
    entry = lexicon.find(pose)
    if entry is None or entry.hold is None:
        return text, []
    head = text[:begin]
    start = max(head.rfind(c) for c in ",.;") + 1
    clause = head[start:]
    words = temporal.normalize(clause).split()
    if not any((h := lookup(w)) and h[0].kind == "travel" for w in words):
        return text, []
    again = split_subject(" ".join(words))[1]
    new = f"{head}, then {again} holding {pose}{text[end:]}"
    return new, [f"temporal: '{text[begin:end].strip()}' during travel → the pose is struck, then held "
                 f"while travelling ('{again}' twice)"]


def _struck(text: str) -> tuple[int, str, int] | None:
    """The first " while striking <pose>" (words.toml's `striking_while`, after a space): where
    its spaces begin, the pose's words (to the clause's end: , . ;) and where they end."""
    for found in words("striking_while", ignore_case=True).finditer(text):
        begin, after = found.start, found.end
        while begin > 0 and text[begin - 1].isspace():
            begin -= 1
        spaces = after
        while spaces < len(text) and text[spaces].isspace():
            spaces += 1
        end = spaces
        while end < len(text) and text[end] not in ",.;":
            end += 1
        if begin == found.start or spaces == after or (end == spaces and spaces - after < 2):
            continue                        # no space before or after, or no words after
        if end == spaces:                   # only spaces: the last of them is the "pose"
            return begin, text[spaces - 1:spaces], spaces
        return begin, text[spaces:end], end
    return None
