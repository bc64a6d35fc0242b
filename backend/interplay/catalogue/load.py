"""The catalogue file read and validated once per process.

    cat = catalogue()                   # the packaged actions.toml and activities.toml
    cat.get("jump").checks              # [Check(check="jump_count", count="{count}")]
    use_catalogue(path)                 # tests: another file (a temporary catalogue) from now on

Every stage asks `catalogue()` when it needs the vocabulary, so a test that points it at another
file sees that file's entries planned, generated and reviewed.
"""

from __future__ import annotations

import tomllib
from collections.abc import Callable
from functools import lru_cache
from pathlib import Path

from pydantic import ValidationError

from interplay.catalogue.schema import Catalogue

PATH = Path(__file__).with_name("actions.toml")
# Everyday activities made by the `activity` primitive, kept apart from the verbs and gestures
# for length; packaged with them as one catalogue.
ACTIVITIES = Path(__file__).with_name("activities.toml")
_current: dict[str, Catalogue] = {}
_listeners: list[Callable[[], None]] = []


def read(path: Path | str, *more: Path | str) -> Catalogue:
    """A catalogue file (and more files whose entries follow its own), validated; ValueError
    with the file, entry and field when it is not one."""
    path = Path(path)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        for extra in map(Path, more):
            data.setdefault("action", []).extend(
                tomllib.loads(extra.read_text(encoding="utf-8")).get("action", []))
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{path.name}: not TOML: {exc}") from None
    try:
        return Catalogue.model_validate(data)
    except ValidationError as exc:
        where = "; ".join(f"{'.'.join(str(x) for x in e['loc'])}: {e['msg']}" for e in exc.errors()[:5])
        raise ValueError(f"{path.name}: {where}") from None


def catalogue() -> Catalogue:
    """The catalogue in use (the packaged file unless `use_catalogue` named another)."""
    if "cat" not in _current:
        _current["cat"] = read(PATH, ACTIVITIES)
    return _current["cat"]


def on_change(fn: Callable[[], None]) -> None:
    """Call `fn` whenever the catalogue in use changes (caches built from it clear themselves)."""
    _listeners.append(fn)


def use_catalogue(path: Path | str | None) -> None:
    """Use another catalogue file from now on (None: the packaged one again)."""
    if path is None:
        _current.pop("cat", None)
    else:
        _current["cat"] = read(path)
    for fn in _listeners:
        fn()


@lru_cache(maxsize=1)
def counted_once() -> frozenset[str]:
    """The words of the actions whose count of one the planner keeps ("does a squat" → "squats
    once", the checks then count one): each entry marked `once`, by its one-word name ("jump";
    "boxing jab" by its name "jab")."""
    out: set[str] = set()
    for a in catalogue().action:
        if a.once:
            out.update(n for n in [a.name, *a.names] if " " not in n)
    return frozenset(out)


on_change(counted_once.cache_clear)
