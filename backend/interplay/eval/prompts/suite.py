"""The prompt suite of `interplay eval-prompts` (`eval/data/prompts.json`), loaded and checked.

Each prompt: id, split ("dev" to tune on, "test" to report), category, prompt (as a user types
it), persons, seconds, start (the posture of its first frame: "standing", "lying", "sitting",
… or "any"), contact (whether the two people are asked to touch) and checks, each
`{"check": name, …parameters}` naming a check of `interplay.motion.checks.named.CHECKS`.

The `fresh` split lives in its own file (`eval/data/fresh_prompts.json`, `load_split("fresh")`):
prompts written in words the code has no table for (`vocabulary.py`), one-person, two-person
and part edits. A part edit's entry has `"edit": {"part": …, "text": …}`: the prompt is the
base motion, the text is what the user types into the studio's edit of that part, and its
checks may compare the edited motion with the base (`Spec.base`).

The `fresh2` split (`eval/data/fresh2_prompts.json`, `load_split("fresh2")`): everyday prompts
(category "everyday", one person; "two_person") written blind, by someone who read only the
check functions (`motion/checks`), never the studio's vocabulary, catalogue, planner,
generators, the other prompt files or any output, so it measures how the studio generalises.

The `fresh3` split (`eval/data/fresh3_prompts.json`, `load_split("fresh3")`): a second blind
held-out set written the same way (30 one-person "everyday" prompts: chores, exercise, sports,
gestures, emotions, work, play; 30 "two_person": greetings, helping, handing, playing, sports,
dancing, comforting, arguing, chasing, teaching), its checks chosen before any output was seen.

The `fresh4` split (`eval/data/fresh4_prompts.json`, `load_split("fresh4")`): a third blind
held-out set written the same way (25 one-person "everyday" prompts: chores, work, sports,
play, gestures, emotions; 35 "two_person": greetings, helping, guiding, carrying, handing,
tickling, chasing, fleeing, shoving, sparring, teaching, dancing, consoling, play fighting),
its checks chosen before any output was seen.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

from interplay.motion.checks.named import CHECKS

SUITE = Path(__file__).resolve().parents[1] / "data" / "prompts.json"
FRESH = SUITE.with_name("fresh_prompts.json")
FRESH2 = SUITE.with_name("fresh2_prompts.json")
FRESH3 = SUITE.with_name("fresh3_prompts.json")
FRESH4 = SUITE.with_name("fresh4_prompts.json")
SPLITS = ("dev", "test", "fresh", "fresh2", "fresh3", "fresh4")
# The splits with a file of their own (every prompt there of that split); dev and test share SUITE.
SPLIT_FILES: dict[str, Path] = {"fresh": FRESH, "fresh2": FRESH2, "fresh3": FRESH3, "fresh4": FRESH4}
# Table order; the names as the table prints them.
CATEGORIES: dict[str, str] = {
    "single": "single actions",
    "counts": "counts",
    "sequences": "sequences",
    "directions_speeds": "directions & speeds",
    "styles": "styles",
    "part_locomotion": "part actions + locomotion",
    "poses_held": "poses held",
    "down_up": "getting down & up",
    "sports_fighting": "sports & fighting",
    "paths": "named paths",
    "two_person": "two-person interactions",
}
# Categories outside the table's fixed set, shown where used: the fresh split's part edits, and
# dev's everyday words for what the captures lack (exercise, chores, head moves: the
# open-vocabulary path is tuned on them; the fresh split is its blind counterpart).
FRESH_CATEGORIES: dict[str, str] = {"edits": "part edits", "everyday": "everyday words (dev)",
                                    "activities": "everyday activities (dev)"}
# A category's name in one split's table where the shared one would mislead (fresh2's,
# fresh3's and fresh4's "everyday" prompts are held out, not dev's tuning prompts).
SPLIT_LABELS: dict[str, dict[str, str]] = {"fresh2": {"everyday": "everyday (held out, blind)"},
                                           "fresh3": {"everyday": "everyday (held out, blind)"},
                                           "fresh4": {"everyday": "everyday (held out, blind)"}}
STARTS = ("standing", "any", "low", "lying", "sitting", "kneeling", "all_fours")


@dataclass(frozen=True)
class Prompt:
    id: str
    split: str
    category: str
    prompt: str
    persons: int
    seconds: float
    checks: tuple[dict, ...]
    start: str = "standing"
    contact: bool = False
    kind: str = ""               # two-person prompts: greeting, contact, pushing, following, …
    edit: dict | None = None     # {"part": …, "text": …}: a part edit made on the base motion
    extra: dict = field(default_factory=dict)


def _prompt(d: dict) -> Prompt:
    where = f"prompt {d.get('id', '?')!r}"
    for key in ("id", "split", "category", "prompt", "persons", "seconds", "checks"):
        if key not in d:
            raise ValueError(f"{where}: missing {key!r}")
    if d["split"] not in SPLITS:
        raise ValueError(f"{where}: split must be one of {SPLITS}, got {d['split']!r}")
    if d["category"] not in CATEGORIES and d["category"] not in FRESH_CATEGORIES:
        raise ValueError(f"{where}: unknown category {d['category']!r}")
    if d["persons"] not in (1, 2):
        raise ValueError(f"{where}: persons must be 1 or 2")
    if not 0 < float(d["seconds"]) <= 60:
        raise ValueError(f"{where}: seconds must be in (0, 60]")
    start = d.get("start", "standing")
    if start not in STARTS:
        raise ValueError(f"{where}: start must be one of {STARTS}, got {start!r}")
    checks = d["checks"]
    if not isinstance(checks, list) or not checks:
        raise ValueError(f"{where}: needs at least one check")
    edit = d.get("edit")
    if edit is not None and (not isinstance(edit, dict) or not isinstance(edit.get("part"), str)
                             or not isinstance(edit.get("text"), str) or d["persons"] != 1):
        raise ValueError(f"{where}: an edit is {{'part': str, 'text': str}} on one person")
    for c in checks:
        name = c.get("check") if isinstance(c, dict) else None
        if name not in CHECKS:
            raise ValueError(f"{where}: unknown check {name!r}")
        if CHECKS[name].persons == 2 and d["persons"] != 2:
            raise ValueError(f"{where}: {name} needs two people")
        if CHECKS[name].base and edit is None:
            raise ValueError(f"{where}: {name} compares an edit with its base; the prompt has no edit")
    known = {"id", "split", "category", "prompt", "persons", "seconds", "checks", "start",
             "contact", "kind", "edit"}
    return Prompt(id=d["id"], split=d["split"], category=d["category"], prompt=d["prompt"],
                  persons=int(d["persons"]), seconds=float(d["seconds"]),
                  checks=tuple(dict(c) for c in checks), start=start,
                  contact=bool(d.get("contact", False)), kind=d.get("kind", ""),
                  edit=dict(edit) if edit is not None else None, extra={k: v for k, v in d.items() if k not in known})


def load_suite(path: Path = SUITE) -> list[Prompt]:
    """Every prompt of the suite, validated (unique ids, known splits, categories and checks)."""
    prompts = [_prompt(d) for d in json.loads(Path(path).read_text())["prompts"]]
    ids = [p.id for p in prompts]
    dup = sorted({i for i in ids if ids.count(i) > 1})
    if dup:
        raise ValueError(f"duplicate prompt ids: {dup}")
    return prompts


def select(prompts: list[Prompt], split: str | None = None, categories=None,
           ids=None) -> list[Prompt]:
    """The prompts of one split (None: both), optionally only some categories or ids."""
    return [p for p in prompts if (split is None or p.split == split)
            and (not categories or p.category in categories) and (not ids or p.id in ids)]


def load_split(split: str, ids=None) -> list[Prompt]:
    """The prompts of one split (optionally only some ids): dev and test from the suite, fresh,
    fresh2, fresh3 and fresh4 from their own files (every prompt there must be of that split)."""
    if split not in SPLITS:
        raise ValueError(f"split must be one of {SPLITS}, got {split!r}")
    path = SPLIT_FILES.get(split)
    if path is None:
        return select(load_suite(), split, ids=ids)
    prompts = load_suite(path)
    wrong = [p.id for p in prompts if p.split != split]
    if wrong:
        raise ValueError(f"{path.name} holds prompts of other splits: {wrong}")
    return select(prompts, split, ids=ids)


def table_categories(prompts: list[Prompt]) -> dict[str, str]:
    """The categories a report shows: every suite category, then the fresh-only ones that
    these prompts use."""
    used = {p.category for p in prompts}
    return {**CATEGORIES, **{k: v for k, v in FRESH_CATEGORIES.items() if k in used}}


def category_labels(split: str | None = None) -> dict[str, str]:
    """Every category's name as a report's table prints it, in that split's words."""
    return {**CATEGORIES, **FRESH_CATEGORIES, **SPLIT_LABELS.get(split or "", {})}
