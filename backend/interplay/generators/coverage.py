"""Each segment's `coverage` once the generator has made its plan: the planner's reading of the
words (`planner.resolve.coverage_of`) refined by what the segment was made from.

- composed two-person plans: `composed`, the composition's kind as the entry;
- captured segments: the similarity of the caption their captures were found by (the best
  piece's text score), and for a segment whose words nothing in the catalogue names
  (`nearest`) what was shown instead: that caption, so the studio, the CLI and the reviewer
  can say "not in the library — showing the nearest: …".

    cover(plan, index)       # sets plan.segments[i].coverage, adds a reason per nearest segment
"""

from __future__ import annotations

from interplay.generators.plan import GenerationPlan, GenerationSegment
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.planner.schema import Coverage

# Kinds whose people each play their own words (one-person generator): the words, not the
# kind, say whether the segment is covered.
SOLO_KINDS = ("together", "face_to_face")


def _best_piece(seg: GenerationSegment):
    pieces = [p for t in (seg.retrieval.tracks if seg.retrieval else []) for p in t]
    return max(pieces, key=lambda p: p.score) if pieces else None


def nearest_note(seg: GenerationSegment) -> str | None:
    """The plan's words for a segment nothing covers."""
    cov = seg.coverage
    if cov is None or cov.how != "nearest":
        return None
    shown = f": {cov.shown}" if cov.shown else ""
    return (f"segment {seg.index}: '{seg.prompt}' is not in the library — showing the nearest"
            f"{shown} (text similarity {cov.similarity:.2f})")


def cover(plan: GenerationPlan, index: RetrievalIndex | None = None) -> None:
    """Set every segment's coverage from the plan as made; nearest segments get a reason."""
    for seg in plan.segments:
        cov = seg.coverage or Coverage(how="capture", similarity=1.0)
        # A composed scene covers the segment whatever the planner read in its words (the
        # kind was found by its entry's words or descriptions), except the kinds that play
        # each person's own part through the one-person generator (SOLO_KINDS)
        kind = (plan.composition or {}).get("kind")
        if plan.generator == "compose" and kind and (cov.how != "nearest" or kind not in SOLO_KINDS):
            cov = cov.model_copy(update={"how": "composed", "entry": kind})
        best = _best_piece(seg)
        if best is not None and cov.how in ("nearest", "capture") and cov.entry is None:
            shown = cov.shown
            if index is not None:
                try:
                    shown = index.clip(best.clip).prompt
                except KeyError:
                    pass
            cov = cov.model_copy(update={"similarity": round(max(-1.0, min(1.0, best.score)), 4),
                                         "shown": (shown or "")[:300]})
        seg.coverage = cov
        note = nearest_note(seg)
        if note is not None and note not in plan.reasons:
            plan.reasons.append(note)
