"""The word lists of `words.toml`: words the planner, the generators and the reviewer look for
that name no action of actions.toml (who does it, touches, places, parts of the body, directions,
context); and `tables.toml`: the questions the planner answers, the reviewer's caption cues and
the held poses; validated. Their phrases are found in a text as words by `catalogue.phrases`.

    words("review_hug").search("they hug each other")     → Found(start=5, end=8, text='hug')
    words("pair_both").whole("the two friends")          → True
"""

from __future__ import annotations

import tomllib
from functools import lru_cache
from pathlib import Path
from typing import Annotated

from pydantic import AfterValidator, BaseModel, ConfigDict, field_validator

from interplay.catalogue.phrases import Found, Phrases, parse, tokens

__all__ = ["Found", "Phrases", "parse", "tokens", "words", "lists", "questions", "cues", "poses", "WordLists"]

PATH = Path(__file__).with_name("words.toml")
TABLES = Path(__file__).with_name("tables.toml")         # questions, caption cues, held poses


def _parsed(phrases: list[str]) -> list[str]:
    """The phrases, each checked to parse (a ValueError names the one that does not)."""
    for p in phrases:
        parse(p)
    return phrases


PhraseList = Annotated[list[str], AfterValidator(_parsed)]


class Question(BaseModel):
    """A question the planner answers with a motion: the phrases that say what it is about."""
    model_config = ConfigDict(extra="forbid")
    keys: PhraseList
    answer: str
    about: str


class Cue(BaseModel):
    """A planned text's words and the caption phrases that show it (review/agreement.py)."""
    model_config = ConfigDict(extra="forbid")
    said: PhraseList
    shown: list[str]


class Pose(BaseModel):
    """A pose held over a segment (planner/manner/holds.py): the words that name it, its
    instruction ("{side}": written per arm) and whether it is one action of both arms."""
    model_config = ConfigDict(extra="forbid")
    said: PhraseList
    instruction: str
    together: bool = False


class WordLists(BaseModel):
    """words.toml: named lists of phrases, and the questions (the file says what each is for)."""
    model_config = ConfigDict(extra="forbid")
    lists: dict[str, list[str]]
    question: list[Question] = []
    part_cue: list[Cue] = []
    body_cue: list[Cue] = []
    pose: list[Pose] = []

    @field_validator("lists")
    @classmethod
    def _phrases_parse(cls, lists: dict[str, list[str]]) -> dict[str, list[str]]:
        for name, phrases in lists.items():
            if not phrases:
                raise ValueError(f"{name}: an empty list")
            _parsed(phrases)                          # raises on a bracket left open
        return lists


@lru_cache(maxsize=1)
def word_lists() -> WordLists:
    """words.toml and tables.toml, validated."""
    data = {**tomllib.loads(PATH.read_text(encoding="utf-8")), **tomllib.loads(TABLES.read_text(encoding="utf-8"))}
    return WordLists.model_validate(data)


def lists() -> dict[str, list[str]]:
    return word_lists().lists


def cues(table: str) -> tuple[tuple[Phrases, tuple[str, ...]], ...]:
    """words.toml's part or body cues: (the planned text's phrases, the caption phrases)."""
    return _cues(table)


@lru_cache(maxsize=2)
def _cues(table: str) -> tuple[tuple[Phrases, tuple[str, ...]], ...]:
    rows = word_lists().part_cue if table == "part" else word_lists().body_cue
    return tuple((Phrases(c.said), tuple(c.shown)) for c in rows)


@lru_cache(maxsize=1)
def poses() -> tuple[tuple[Phrases, str, bool], ...]:
    """The held poses words.toml names: (their phrases, the instruction, both arms as one)."""
    return tuple((Phrases(p.said), p.instruction, p.together) for p in word_lists().pose)


@lru_cache(maxsize=1)
def questions() -> tuple[tuple[Phrases, str, str], ...]:
    """The questions words.toml answers: (their phrases, any case; the answer; what it is about)."""
    return tuple((Phrases(q.keys, ignore_case=True), q.answer, q.about) for q in word_lists().question)


@lru_cache(maxsize=None)
def words(name: str, ignore_case: bool = False) -> Phrases:
    """The phrases of one list of words.toml."""
    return Phrases(lists()[name], ignore_case)
