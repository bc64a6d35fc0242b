"""Word lists are catalogue data (actions.toml's `[words.lists]`, words.toml), not tables in
code: a module of backend/interplay outside catalogue/ may not define, at module or class level,
a tuple, list, set or frozenset (or a dict of them) of three or more lower-case words or phrases
(strings of letters, spaces, apostrophes, hyphens or '*'). Names that are identifiers, not words
a user types, are allowed with a reason; the vocabulary still in code may only shrink. The rule
is shown to fail on a planted table in a temporary tree."""

from __future__ import annotations

import ast
import re
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[2] / "backend" / "interplay"
_WORDISH = re.compile(r"[a-z][a-z '\-*]*")
_COLLECTIONS = ("tuple", "list", "set", "frozenset")

# Identifiers and fixed inputs, not vocabulary read from a prompt: allowed, one reason each.
IDENTIFIERS = {
    "bench/api.py:PROMPTS": "the benchmark's input prompts, not words the code looks for",
    "bench/pair.py:PROMPTS": "the benchmark's input prompts, not words the code looks for",
    "cli/leaves_report.py:PROMPTS": "the report's input prompts, not words the code looks for",
    "generators/interaction/scenes/partners.py:PARTS": "part identifiers of the touch entry's `parts`",
    "generators/retrieval/intent.py:TRAVELS": "values of the intent's travel field",
    "generators/retrieval/intent.py:ACTIONS": "names of measured actions (retrieval index keys)",
    "generators/retrieval/intent.py:POSTURES": "posture identifiers",
    "generators/retrieval/intent.py:LOW": "posture identifiers",
    "generators/retrieval/measured.py:DIRECTIONS": "keys of the measured directions",
    "generators/retrieval/measured.py:POSTURE_KEYS": "keys of the measured postures",
    "generators/retrieve_edit/leg_edit.py:CHAIN": "joint names of the skeleton",
    "generators/spam/files.py:GRAPH_INPUTS": "input names of the exported ONNX graphs",
    "motion/captions.py:MINOR": "phrases of the captions this module writes itself, not a user's",
    "motion/labels.py:FAMILIES": "capture family identifiers",
    "motion/pair/resolve.py:CONTACTS": "contact mode identifiers",
    "pipeline/messages.py:_LOCATION_PREFIXES": "pydantic error location keys",
    "pipeline/messages.py:_VERBS": "words of pydantic's own error messages, not a prompt's",
    "planner/schema.py:_OPTIONAL": "field names of the plan schema",
    "planner/verbs.py:_KINDS": "verb kind identifiers",
    "store/db.py:_RACES": "database error message fragments",
    "store/jobs.py:TERMINAL": "job state identifiers",
    "store/retention.py:TERMINAL": "job state identifiers",
    "trajectory/apply.py:ANCHORS": "anchor identifiers of a trajectory",
    "trajectory/travel.py:TRAVELS": "travel direction identifiers (the plan's `travel` values)",
}
# Vocabulary still written in code (issue 23): may only shrink; move each to the catalogue.
LEGACY = {
    "motion/pair/bases.py:NOT_AHEAD",    # words of the captures' own captions; motion may not import the catalogue
}


def _elements(node: ast.expr) -> list[ast.expr] | None:
    if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
        return node.elts
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in _COLLECTIONS \
            and len(node.args) == 1:
        return _elements(node.args[0])
    return None


def _is_table(node: ast.expr) -> bool:
    """A collection of three or more lower-case words or phrases."""
    elts = _elements(node)
    return elts is not None and len(elts) >= 3 and all(
        isinstance(e, ast.Constant) and isinstance(e.value, str) and _WORDISH.fullmatch(e.value) for e in elts)


def _names(tree: ast.Module) -> list[str]:
    """The module- and class-level names bound to a word table (or a dict of them)."""
    bodies = [tree.body] + [c.body for c in tree.body if isinstance(c, ast.ClassDef)]
    out = []
    for body in bodies:
        for st in body:
            if isinstance(st, ast.Assign):
                targets, value = st.targets, st.value
            elif isinstance(st, ast.AnnAssign) and st.value is not None:
                targets, value = [st.target], st.value
            else:
                continue
            values = [v for v in value.values if v is not None] if isinstance(value, ast.Dict) else [value]
            if any(_is_table(v) for v in values):
                out += [t.id for t in targets if isinstance(t, ast.Name)]
    return out


def word_tables(root: Path) -> set[str]:
    """"module:NAME" of every word table under `root`, outside catalogue/."""
    found = set()
    for path in sorted(root.rglob("*.py")):
        rel = path.relative_to(root).as_posix()
        if not rel.startswith("catalogue/"):
            found |= {f"{rel}:{name}" for name in _names(ast.parse(path.read_text(encoding="utf-8")))}
    return found


def test_no_word_table_outside_the_catalogue():
    found = word_tables(PACKAGE)
    new = sorted(found - set(IDENTIFIERS) - LEGACY)
    assert not new, (f"word lists in code: {new}; put them in catalogue/words.toml (or actions.toml's "
                     "[words.lists]) and read them with catalogue.words, or allowlist an identifier here")


def test_the_allowlists_name_only_tables_that_are_there():
    found = word_tables(PACKAGE)
    stale = sorted((set(IDENTIFIERS) | LEGACY) - found)
    assert not stale, f"allowlisted but gone (take them off): {stale}"
    assert not set(IDENTIFIERS) & LEGACY


def test_a_planted_table_is_found(tmp_path):
    (tmp_path / "planner").mkdir()
    (tmp_path / "catalogue").mkdir()
    (tmp_path / "planner" / "m.py").write_text(
        'WORDS = ("walk*", "run", "jog")\n'
        'PARTS = {"arm": ["arm", "elbow*", "wrist"], "leg": ["leg"]}\n'
        'class C:\n    NAMES = frozenset({"one of them", "the other\'s", "high-five"})\n'
        'KINDS = ("high_five", "hug", "push")\n'          # an identifier with an underscore
        'TWO = ("walk", "run")\n'                         # fewer than three
        'CAPS = ("Walk", "run", "jog")\n'                 # not lower-case words
        'def f():\n    LOCAL = ("walk", "run", "jog")\n'  # inside a function
        'N = (1, 2, 3)\n', encoding="utf-8")
    (tmp_path / "catalogue" / "w.py").write_text('WORDS = ("walk", "run", "jog")\n', encoding="utf-8")
    assert word_tables(tmp_path) == {"planner/m.py:WORDS", "planner/m.py:PARTS", "planner/m.py:NAMES"}
