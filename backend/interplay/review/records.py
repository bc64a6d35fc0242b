"""What the reviewer returns: one `Review` per round of a segment (its `event()` is the job
stream's review event) and the whole `Corrected` loop."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Literal

# ok: shows its words; correct: corrections follow (last round: polish left undone);
# failed: still misses its words after them (its checks say why); not_covered: the studio had
# nothing for the words and showed the nearest; unconfirmed: nothing failed, but the words are
# ones the evaluator's calibration does not hold for, so nothing confirmed them either.
Verdict = Literal["ok", "correct", "failed", "not_covered", "unconfirmed"]
VERDICTS: tuple[str, ...] = ("ok", "correct", "failed", "not_covered", "unconfirmed")


@dataclass
class Review:
    segment: int
    round: int
    captions: dict                 # part → caption text (person 0), parts as in motion.captions
    summary: str
    score: float
    score_kind: str                # "evaluator" | "pair_evaluator" | "caption_agreement"
    confirmed: dict                # planned part → bool
    body_confirmed: bool | None    # None: the base has no cue to check
    checks: dict
    instructions: list = field(default_factory=list)
    verdict: Verdict = "ok"
    person_captions: list = field(default_factory=list)
    threshold: float | None = None     # the calibrated threshold the score was judged by
    confidence: float | None = None    # calibrated P(the motion shows its words | score)

    @property
    def metrics(self) -> dict:
        return self.checks["metrics"]

    def event(self) -> dict:
        """The job stream's `review` event."""
        return {"type": "review", "segment": self.segment, "round": self.round,
                "captions": self.captions, "summary": self.summary, "score": self.score,
                "score_kind": self.score_kind, "confirmed": self.confirmed,
                "checks": self.checks, "instructions": self.instructions,
                "verdict": self.verdict}

    def to_json(self) -> dict:
        return asdict(self)


@dataclass
class Corrected:
    people: list                   # final joints per person (segment frames)
    reviews: list                  # Review per round (round 0 = before any correction)
    corrections: list              # correction events (dicts)

    @property
    def first(self) -> Review:
        return self.reviews[0]

    @property
    def last(self) -> Review:
        return self.reviews[-1]

    def history(self) -> dict:
        return {"reviews": [r.to_json() for r in self.reviews], "corrections": self.corrections}
