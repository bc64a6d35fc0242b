"""The words the studio's code knows, for the `fresh` split of `interplay eval-prompts`.

The fresh split is written in words the code has no table for: every content word of its
prompts must be missing from the string literals of the product's code (planner lexicons,
retrieval and interaction keywords, review phrases, pipeline and API strings) at the commit
that added the split. This module collects those words and writes them, with the commit they
were taken from, to `eval/data/fresh_vocabulary.json`; `tests/eval/prompts/test_fresh_split.py`
holds the prompts to it and recomputes the file from that commit.

What counts as a word of the code: every string literal of `backend/interplay/**/*.py` (f-string
parts and regex sources included; a regex's escapes such as `\\b` or `\\s` are dropped first),
and every word of its data files (the catalogue's `actions.toml`: keys, values and comments),
split at non-letters and camelCase humps, lower-cased. Docstrings are left out (they document,
no code reads them), and so are `eval/` and `motion/checks/`: the benchmark itself, whose
suite and checks may name what they measure.

    python -m interplay.eval.prompts.vocabulary            # rewrite the snapshot from HEAD
"""

from __future__ import annotations

import ast
import json
import subprocess
from collections.abc import Iterable
from pathlib import Path

ROOT = Path(__file__).resolve().parents[4]                # the repository
PACKAGE = "backend/interplay"
EXCLUDED = ("backend/interplay/eval/", "backend/interplay/motion/checks/")
SNAPSHOT = Path(__file__).resolve().parents[1] / "data" / "fresh_vocabulary.json"

_LOWER, _UPPER = "abcdefghijklmnopqrstuvwxyz", "ABCDEFGHIJKLMNOPQRSTUVWXYZ"


# Words a prompt cannot do without and that name no action, so they are not held to the
# rule: articles, prepositions and particles, conjunctions, pronouns and possessives,
# auxiliaries, quantities and numbers, and the words for who does it ("person", "people",
# "someone") and which side ("left", "right"). Every other word of a fresh prompt — its verbs,
# nouns, adjectives and adverbs — is a content word and must be unknown to the code.
STOPWORDS = frozenset("""
a an the and or but nor so as than
at by for from in into of off on onto out over to under up down with without against like
i me my you your he him his she her it its we us our they them their this that these those
is are be being been do does did have has had not no
each other both either some any all few several
one two three four five six seven eight nine ten once twice times
person people someone somebody left right then while
""".split())
def _letter_runs(text: str) -> list[str]:
    """The runs of the letters a to z in `text`."""
    return "".join(c if c in _LOWER else " " for c in text).split()


def tokens(text: str) -> list[str]:
    """Lower-case words of a prompt (hyphens and apostrophes split words: "pinky-swear",
    "buddy's" → "pinky", "swear"; "buddy", "s")."""
    return _letter_runs(text.lower())


def content_words(text: str) -> list[str]:
    """The words of a prompt held to the rule: not stopwords and longer than one letter."""
    return [w for w in tokens(text) if w not in STOPWORDS and len(w) > 1]


def forms(word: str) -> set[str]:
    """A word and the stems of its simple inflections (-s, -es, -ies, -ing, -ed, a doubled
    consonant before -ing / -ed), each of ≥ 3 letters: "juggling" → juggl, juggle;
    "tapping" → tapp, tap."""
    out = {word}
    for suffix, repl in (("ies", "y"), ("ied", "y"), ("es", ""), ("s", ""), ("ing", ""),
                         ("ing", "e"), ("ed", ""), ("ed", "e"), ("d", "")):
        if word.endswith(suffix) and len(word) - len(suffix) + len(repl) >= 3:
            out.add(word[:len(word) - len(suffix)] + repl)
    for suffix in ("ing", "ed"):
        stem = word[:-len(suffix)]
        if word.endswith(suffix) and len(stem) >= 4 and stem[-1] == stem[-2]:
            out.add(stem[:-1])
    return out


class Known:
    """Whether the code knows a word: one of its forms is a form of a snapshot word, or a
    snapshot word of ≥ 4 letters begins it (the planner matches stems such as "wrestl",
    "chas", "applau" as prefixes; a short word such as "arm" would begin too many others)."""

    def __init__(self, words: Iterable[str]):
        self.words = set(words)
        self.stems: set[str] = set()
        for w in self.words:
            self.stems |= forms(w)
        self.prefixes = {w for w in self.words if len(w) >= 4}

    def why(self, word: str) -> str | None:
        """The snapshot word that makes `word` known, or None."""
        hit = forms(word) & self.stems
        if hit:
            return sorted(hit)[0]
        for n in range(4, len(word) + 1):
            if word[:n] in self.prefixes:
                return word[:n]
        return None


DATA_FILES = (".toml", ".json", ".yaml", ".yml", ".txt", ".csv")


def scanned(path: str) -> bool:
    """Whether a repository path is part of the code whose words are collected: a module or
    a data file the code reads (word lists live in both)."""
    return (path.startswith(PACKAGE + "/") and path.endswith((".py", *DATA_FILES))
            and not any(path.startswith(x) for x in EXCLUDED))


def words_of_file(path: str, text: str) -> set[str]:
    """A module's string-literal words, or every word of a data file."""
    return words_of_source(text) if path.endswith(".py") else words_of_text(text)


def docstrings(tree: ast.AST) -> set[int]:
    """ids of the Constant nodes that are docstrings (first statement of a module, class or
    function body)."""
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                out.add(id(body[0].value))
    return out


def words_of_text(text: str) -> set[str]:
    """Lower-case words of one string literal (regex escapes dropped, camelCase split)."""
    first, *after = text.split("\\")               # a backslash and a letter: \b \s \w \d …
    text = first + "".join(" " + p[1:] if p[:1] and p[0] in _LOWER + _UPPER else "\\" + p for p in after)
    humps = "".join(c + " " if c in _LOWER and n in _UPPER else c for c, n in zip(text, text[1:] + " "))
    return set(_letter_runs(humps.lower()))


def words_of_source(source: str) -> set[str]:
    """Words of every string literal of one Python module except its docstrings."""
    tree = ast.parse(source)
    skip = docstrings(tree)
    out: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in skip:
            out |= words_of_text(node.value)
    return out


def collect(files: Iterable[tuple[str, str]]) -> list[str]:
    """The sorted word set of these (path, text) files."""
    out: set[str] = set()
    for path, text in files:
        out |= words_of_file(path, text)
    return sorted(out)


def _git(*args: str) -> str:
    return subprocess.run(["git", *args], cwd=ROOT, check=True, capture_output=True,
                          text=True).stdout


def paths_at(commit: str) -> list[str]:
    """The scanned paths in the tree of `commit`."""
    return sorted(p for p in _git("ls-tree", "-r", "--name-only", commit, PACKAGE).splitlines()
                  if scanned(p))


def words_at(commit: str) -> list[str]:
    """The code's words at `commit` (read with `git show`, so the working tree's uncommitted
    edits do not count)."""
    return collect((p, _git("show", f"{commit}:{p}")) for p in paths_at(commit))


def snapshot(commit: str) -> dict:
    full = _git("rev-parse", commit).strip()
    return {"about": "every word of the string literals (docstrings aside) of backend/interplay's "
                     "modules and of its data files, outside eval/ and motion/checks/, at this "
                     "commit; the fresh split's content words must be none of them "
                     "(interplay.eval.prompts.vocabulary)",
            "commit": full, "excluded": list(EXCLUDED), "words": words_at(full)}


def load_snapshot(path: Path = SNAPSHOT) -> dict:
    return json.loads(Path(path).read_text())


def main() -> None:
    snap = snapshot("HEAD")
    SNAPSHOT.write_text(json.dumps(snap, indent=0) + "\n")
    print(f"{len(snap['words'])} words at {snap['commit'][:10]} → {SNAPSHOT}")


if __name__ == "__main__":
    main()
