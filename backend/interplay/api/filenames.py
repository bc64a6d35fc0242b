"""Download names: `interplay-<prompt words>-<id>.<ext>` (e.g.
`interplay-two-people-shake-hands-Xy…Q.glb`), so a folder of exports says what each one is.
The words are the prompt's, slugified (ASCII letters and digits, lower case, joined by "-";
accents folded, everything else dropped) and bounded to `MAX_WORDS_CHARS` characters at a word
boundary; without any, the name is `interplay-<id>.<ext>`. The studio's download names
(frontend/src/api/filenames.ts) are the same function."""

from __future__ import annotations

import unicodedata

MAX_WORDS_CHARS = 48


_WORD_CHARS = frozenset("abcdefghijklmnopqrstuvwxyz0123456789")

def slug(prompt: str | None, limit: int = MAX_WORDS_CHARS) -> str:
    """The prompt's words as a file-name part: "Two people shake hands!" → "two-people-shake-hands"."""
    text = unicodedata.normalize("NFKD", prompt or "").encode("ascii", "ignore").decode("ascii")
    words = "".join(c if c in _WORD_CHARS else " " for c in text.lower()).split()
    out = ""
    for word in words:
        joined = f"{out}-{word}" if out else word
        if len(joined) > limit:
            if not out:             # one very long word: cut it
                out = word[:limit]
            break
        out = joined
    return out


def export_name(motion_id: str, prompt: str | None, ext: str, suffix: str = "") -> str:
    """`interplay-<slug>-<id><suffix>.<ext>`; `suffix` such as "-person1" or "-skeleton"."""
    words = slug(prompt)
    return f"interplay-{words + '-' if words else ''}{motion_id}{suffix}.{ext}"


def content_disposition(name: str) -> str:
    """The attachment header for a name made by `export_name` (ASCII only, no quotes)."""
    return f'attachment; filename="{name}"'
