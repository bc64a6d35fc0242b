"""The reviewer's learned judge: does the motion show its words? The text–motion evaluator's
cosine for one person, the pair evaluator's for two (when the text is one of the interactions
it was trained on), each compared with the threshold calibrated on held-out captures
(`review.calibration`, `interplay review-calibrate`); a segment under it fails whatever the
word-list checks say. Without an evaluator the score is the captions' MiniLM agreement with the
text and there is no threshold.

    j = judge(people, seg.prompt, texts, summaries, evaluator, pair_evaluator, encoder)
    j.failure     # "the motion does not match its words: evaluator score 0.09 < 0.36" or None
    j.confidence  # calibrated P(the motion shows its words), None without a calibration
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.review.agreement import caption_agreement
from interplay.review.calibration import Calibration
from interplay.text.encoder import Encoder

WORDS = "words"                 # the key of a judge failure in a review's checks["failed"]


@dataclass(frozen=True)
class Judged:
    score: float
    kind: str                   # "evaluator" | "pair_evaluator" | "caption_agreement"
    threshold: float | None     # None: no calibrated threshold judged this segment
    confidence: float | None
    failure: str | None
    text: str = ""              # the words the score is of


_DOMAIN: dict[tuple, np.ndarray] = {}


def in_domain(cal: Calibration, text: str, encoder: Encoder) -> bool:
    """Whether the calibration holds for `text`: its MiniLM cosine to the nearest text the
    evaluator was trained with is at least the calibration's `min_similarity` (the one-person
    evaluator was never shown "a person climbs a ladder", the pair evaluator has no kind for
    "two people box": their scores for such words were not calibrated)."""
    texts = tuple(cal.domain.get("texts") or ())
    if not texts:
        return True
    key = (id(encoder), texts)
    if key not in _DOMAIN:
        _DOMAIN[key] = np.asarray(encoder.encode(list(texts)))
    sims = _DOMAIN[key] @ np.asarray(encoder.encode([text])[0])
    return float(np.max(sims)) >= float(cal.domain.get("min_similarity", 0.0))


def judge(people: list[np.ndarray], prompt: str, texts: list[str], summaries: list[str],
          evaluator=None, pair_evaluator=None, encoder: Encoder | None = None,
          base: str | None = None, vouched: bool = False) -> Judged:
    """Score one segment (`people` (T, 22, 3) each; `texts` each person's words, `prompt` the
    segment's) and judge it by the calibrated threshold that applies (module doc). `base`: one
    person's base motion when the plan lays part edits over it (CoMA's M_base + Edit(P_edit)):
    the evaluator, trained on whole-body captures and their captions, judges the base, and the
    part edits are judged by the captions (`review.agreement`). `vouched`: the generator made
    the segment from what its catalogue has for these words (coverage capture, primitive or
    composed); then one person's words the evaluator's calibration does not hold for
    (`in_domain`) are not judged by its threshold. Unvouched words always are: a low score
    is the only evidence there is, and the reviewer does not pass words nothing confirms."""
    cal: Calibration | None = None
    if len(people) == 2 and pair_evaluator is not None and encoder is not None \
            and getattr(pair_evaluator, "calibration", None) is not None \
            and in_domain(pair_evaluator.calibration, prompt, encoder):
        score = pair_evaluator.score(np.stack(people), prompt)
        kind, cal, text = "pair_evaluator", pair_evaluator.calibration, prompt
    elif evaluator is not None:
        said = [base] if base and len(people) == 1 else texts
        score = float(np.mean([evaluator.score(p, t) for p, t in zip(people, said)]))
        kind, text = "evaluator", said[0]
        cal = getattr(evaluator, "calibration", None) if len(people) == 1 else None
        if isinstance(cal, Calibration) and vouched and encoder is not None \
                and not in_domain(cal, said[0], encoder):
            cal = None          # words it was not calibrated on, that the catalogue covers
    else:
        if encoder is None:
            raise ValueError("judging by caption agreement needs a text encoder")
        score = float(np.mean([caption_agreement(s, t, encoder) for s, t in zip(summaries, texts)]))
        kind, text = "caption_agreement", texts[0]
    if not isinstance(cal, Calibration):
        return Judged(score, kind, None, None, None, text)
    failure = None if cal.passes(score) else (
        f"the motion does not match its words: {kind.replace('_', ' ')} score {score:.2f} "
        f"< {cal.threshold:.2f}")
    return Judged(score, kind, cal.threshold, round(cal.confidence(score), 4), failure, text)


def not_covered(seg) -> str | None:
    """Why a segment the generator could only show the nearest thing for is not covered, or
    None (`planner.schema.Coverage`: how == "nearest")."""
    cov = getattr(seg, "coverage", None)
    if cov is None or cov.how != "nearest":
        return None
    shown = f"'{cov.shown}'" if cov.shown else "the nearest clip"
    return (f"nothing the studio has shows '{seg.prompt}': it shows {shown} instead "
            f"(similarity {cov.similarity:.2f})")
