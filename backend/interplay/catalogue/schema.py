"""The catalogue's entries as validated pydantic models, read from `actions.toml`.

    Action   {name, kind, descriptions, words, names, text, hold, persons, roles, parts, counts,
              seconds, speed, speed_band, posture, ends_in, made_by, checks, examples, …}
    Catalogue {actions, words}

An action is one thing a person (or two) can be asked to do. `words` are the word forms that
name it in a prompt (a trailing `*` takes any ending: "sprint*" is sprint, sprints, sprinting);
`names` are the set phrases of a gesture or pose ("t pose", "fist pump"), rewritten to its
`text`; `phrases` are templates with optional words that find it in a segment's words
("arm* [held] out to (the|his|her) side*", see `grammar.template_source`); `descriptions` are
sentences the text encoder compares prompts with. `kind` says how the planner treats it:
travel / whole / part / light are motion verbs (a light verb carries no motion itself: "does",
"performs"), gesture and pose are named movements rewritten to their `text`, interaction is a
two-person kind, manner a way of doing it ("slowly", "tired"), move a movement the studio
builds from body-part primitives when the words are near its descriptions ("taps the chest"). `made_by` says how the studio makes it; `checks` name the benchmark's checks
(`motion/checks/named.py`) that confirm it on the motion.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

Kind = Literal["travel", "whole", "part", "light", "gesture", "pose", "interaction", "manner", "move"]
Part = Literal["arm", "arms", "leg", "legs", "head", "body"]
Posture = Literal["standing", "sitting", "lying", "kneeling", "squatting", "crawling", "all_fours",
                  "prone", "supine"]
SpeedBand = Literal["slow", "walk", "jog", "run", "sprint"]


class Moves(BaseModel):
    """An everyday activity told part by part (CoMA's part instructions), built by the
    `activity` primitive (`generators/primitives/activity.py`) on a captured base posture:
    which hands move, where (`at`, a point on the body; `reach_m` ahead of it), along which
    axis of the body and how far (`amplitude_m`, end to end), how long one stroke takes
    (`cycle_s`), whether both hands hold one thing (`together`), the trunk's forward lean, the
    head's pitch (down: looking at the hands) and the legs' own move."""
    model_config = ConfigDict(extra="forbid")
    posture: Literal["standing", "seated", "floor", "kneeling", "prone", "supine", "all_fours", "walk"] = "standing"
    hands: Literal["right", "left", "both", "alternate", "none"] = "right"
    at: Literal["chest", "face", "ear", "overhead", "waist", "low", "side", "hang", "lap"] = "chest"
    axis: Literal["up", "forward", "side", "circle", "still"] = "up"
    amplitude_m: float = Field(default=0.25, ge=0.0, le=0.8)
    reach_m: float = Field(default=0.3, ge=0.0, le=0.7)
    cycle_s: float = Field(default=0.8, gt=0.1, le=8.0)
    together: bool = False
    lean_deg: float = Field(default=0.0, ge=-20.0, le=80.0)
    head_deg: float = Field(default=0.0, ge=-45.0, le=45.0)
    legs: Literal["still", "march", "bounce", "hop"] = "still"


class MadeBy(BaseModel):
    """How the studio makes it: captured families (retrieval's clips by caption), a primitive
    (built per body part, `generators/primitives`; `moves` for the `activity` primitive), or
    a composition kind for two people."""
    model_config = ConfigDict(extra="forbid")
    families: list[str] = Field(default_factory=list)
    primitive: str | None = None
    moves: Moves | None = None
    composition: str | None = None

    @model_validator(mode="after")
    def _moves_need_activity(self):
        if (self.moves is not None) != (self.primitive == "activity"):
            raise ValueError("made_by.moves goes with primitive = 'activity', and only with it")
        return self

    @property
    def how(self) -> str:
        # captured families come first: a primitive only serves an entry no capture makes
        return ("composed" if self.composition else "capture" if self.families else
                "primitive" if self.primitive else "capture")


class Check(BaseModel):
    """A named check of `motion/checks/named.py` with its parameters; `{count}` or `{side}` in
    a string parameter is filled from the segment."""
    model_config = ConfigDict(extra="allow")
    check: str


class Action(BaseModel):
    model_config = ConfigDict(extra="forbid")
    name: str = Field(min_length=1)
    kind: Kind
    descriptions: list[str] = Field(default_factory=list)
    words: list[str] = Field(default_factory=list)      # word forms that name it ("sprint*")
    not_before: list[str] = Field(default_factory=list)  # words that cancel a match when next
    names: list[str] = Field(default_factory=list)      # set phrases of a gesture or pose
    followed_by: list[str] = Field(default_factory=list)  # a name counts only before these (or a clause end)
    phrases: list[str] = Field(default_factory=list)    # templates that name it in a segment's words (grammar.py)
    part_phrases: list[str] = Field(default_factory=list)  # … in one part's instruction, when looser
    ik: str | None = None             # the pose or lift the IK lays over captures for it (retrieve_edit)
    text: str | None = None           # gestures / poses: what the body does, third person
    hold: str | None = None           # poses: the held pose as a "with …" phrase
    persons: list[int] = Field(default_factory=lambda: [1])
    roles: list[str] = Field(default_factory=list)
    contact: Literal["hands", "hug"] | None = None   # interactions: the two touch (hands; a hug)
    actor_words: list[str] = Field(default_factory=list)      # interactions: words of the one who starts it
    responder_words: list[str] = Field(default_factory=list)  # … and of the one who responds
    part: Part | None = None          # verbs: the limb it moves by default
    parts: list[str] = Field(default_factory=list)     # body parts it moves (CoMA's parts)
    counts: bool = False              # it is counted per cycle ("three jumps")
    once: bool = False                # a count of one said ("a jump", "throws a punch") is kept: "once"
    counts_as: str | None = None      # the counted event the checks see (a hop counts as a jump)
    seconds: float = Field(default=2.0, gt=0)          # one performance / one cycle
    speed: float | None = Field(default=None, gt=0)    # travel: metres per second
    speed_band: SpeedBand | None = None
    posture: Posture | None = None    # the base posture it needs
    ends_in: str | None = None        # the posture it leaves the body in
    forms: list[str] = Field(default_factory=list)     # irregular verbs: third, gerund, past, participle
    doubles: bool = False             # verbs: the last consonant doubles (hop → hopping)
    nouns: list[str] = Field(default_factory=list)     # nouns that name it ("a squat")
    noun_only: bool = False           # done as a noun, not a verb ("does a handstand")
    made_by: MadeBy = Field(default_factory=MadeBy)
    checks: list[Check] = Field(default_factory=list)
    examples: list[str] = Field(default_factory=list)

    @model_validator(mode="after")
    def _consistent(self):
        if self.forms and len(self.forms) != 4:
            raise ValueError(f"{self.name}: forms are third, gerund, past, participle (4 words)")
        if self.kind in ("gesture", "pose") and not (self.names or self.phrases):
            raise ValueError(f"{self.name}: a {self.kind} needs names or phrases")
        if self.names and not self.text:
            raise ValueError(f"{self.name}: named phrases are rewritten to a text; it has none")
        if self.hold is not None and not self.hold.startswith("with "):
            raise ValueError(f"{self.name}: hold is a 'with …' phrase")
        return self


def takes(check: str, param: str) -> bool:
    """Does the named check (`motion/checks/named.py`) take this parameter?"""
    import inspect

    from interplay.motion.checks.named import CHECKS
    spec = CHECKS.get(check)
    return spec is not None and param in inspect.signature(spec.fn).parameters


def specs(action: Action, count: int | None = None, side: str | None = None,
          takes_at_least=lambda check: takes(check, "at_least")) -> list[dict]:
    """The action's checks as specs for `run_check`, "{count}" and "{side}" filled from the
    segment: a count not asked becomes "at least one" where the check takes `at_least` (else
    the check is left out: it cannot be held to a count nobody asked), a side not named "any"."""
    out = []
    for c in action.checks:
        spec: dict | None = {"check": c.check}
        for key, value in (c.model_extra or {}).items():
            if spec is None:
                break
            if value == "{count}":
                if count is None:
                    spec = {**spec, "at_least": 1} if takes_at_least(c.check) else None
                    continue
                value = count
            elif value == "{side}":
                value = side or "any"
            spec[key] = value
        if spec is not None:
            out.append(spec)
    return out


class Words(BaseModel):
    """Word lists of sentence structure that are vocabulary too: what introduces a named
    gesture ("does", "strikes"), the adjectives and nouns around its name."""
    model_config = ConfigDict(extra="forbid")
    name_adjectives: list[str] = Field(default_factory=list)
    name_tails: list[str] = Field(default_factory=list)
    lists: dict[str, list[str]] = Field(default_factory=dict)


class Catalogue(BaseModel):
    model_config = ConfigDict(extra="forbid")
    action: list[Action]
    words: Words = Field(default_factory=Words)

    @model_validator(mode="after")
    def _unique(self):
        seen: set[str] = set()
        for a in self.action:
            if a.name in seen:
                raise ValueError(f"two entries named {a.name!r}")
            seen.add(a.name)
        return self

    def get(self, name: str) -> Action | None:
        return next((a for a in self.action if a.name == name), None)

    def of_kind(self, *kinds: str) -> list[Action]:
        return [a for a in self.action if a.kind in kinds]
