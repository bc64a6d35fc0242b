"""One person's track for a segment, drawn for what the segment asks (`intent.py`): a plain
text match when it asks nothing more, else the constrained candidates and draws of
`constrained.py`, checked (`verify.py`) before they are kept. In order, the first that the
captures can give:

1. a change of posture (starting lying or sitting, ending seated, lying, kneeling or back up):
   one piece from the starting posture to the end posture, its last pose then held;
2. a counted action (jump three times, kick twice with the right leg): exactly that many;
3. a direction of travel (backwards, sideways): views that travel that way;
4. a named side (a right kick, the left hand): views of that side.

A first segment that asks nothing more is still drawn to start standing (unless its intent
starts elsewhere).

A track may last fewer frames than its segment: the generator then holds its last pose (a
posture reached and kept, the quiet after a counted action) to the segment's end.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from interplay.generators.retrieval import constrained as con
from interplay.generators.retrieval import counts, on_the_spot, postures, verify
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.generators.retrieval.intent import LOW, Intent, count_of

STANDING = "a person stands still"


def start_end(index: RetrievalIndex, intent: Intent, after: dict | None
             ) -> tuple[str | None, str | None]:
    """(start, end) postures the segment must start and end in; None where it need not."""
    start, end = intent.start, intent.end
    before = postures.posture_at(index, after)
    if start is None and (intent.rises or end in LOW or end == "standing"):
        start = before if after else "standing"
    if start == end:
        return None, None
    return start, end


def single_track(index: RetrievalIndex, text: str, frames: int, rng: np.random.Generator,
                 after: dict | None, intent: Intent) -> list[dict]:
    """The pieces of one person's track for a segment (see the module doc); a count asked of
    an action the captures perform whole (a cartwheel, a flip, a spin) is kept exact."""
    pieces = _drawn(index, on_the_spot.travelling(text, intent), frames, rng, after, intent)
    # (spins are held to their turn, not to whole captures: a spin capture may turn less)
    count = count_of(text) if intent.action is None and intent.hold is None and intent.turn is None else None
    return _counted_whole(index, pieces, count) if count else pieces


# A piece that covers this share of its capture is one whole performance of it (a cartwheel,
# a flip: captures a second or three long, chained to fill the segment when no count is read).
WHOLE = 0.6


def _counted_whole(index: RetrievalIndex, pieces: list[dict], count: int) -> list[dict]:
    """The track cut after `count` whole performances when it holds more ("does a cartwheel
    once" drawn as three); the generator holds the last pose to the segment's end, as after a
    counted jump (a standing capture drawn on from there finds waving and fidgeting ones)."""
    whole = 0
    for i, p in enumerate(pieces):
        whole += (p["end"] - p["start"]) >= WHOLE * index.clip(p["clip"]).frames
        if whole == count:
            return pieces[:i + 1]
    return pieces


def _drawn(index: RetrievalIndex, text: str, frames: int, rng: np.random.Generator,
           after: dict | None, intent: Intent) -> list[dict]:
    plain = lambda: index.track(text, frames, rng, after=after)  # noqa: E731
    if intent.plain:
        if after is None and intent.start in (None, "standing"):
            # a motion starts standing unless asked otherwise: runs, dances and hops captured
            # mid-stride or mid-step are drawn again (`verify.pick`)
            return verify.pick(index, plain, frames, verify.checks(intent, first=True)) or plain()
        return plain()
    start, end = start_end(index, intent, after)
    draw: Callable[[], list[dict] | None] | None = None
    specs = verify.checks(intent, start, end, first=after is None)
    if intent.in_place and intent.action is None and not intent.still:
        # a way of travelling done on the spot ("march in place", "jog on the spot"): the
        # captures that stay put are of other actions (a kick, a dance), so draws are not
        # held to it; the drawn march is kept on the spot afterwards (on_the_spot.py)
        specs = [s for s in specs if s["check"] != "stays_in_place"]
    if end is not None and start is not None and (start in LOW or end in LOW):
        options = postures.posture_options(index, text, start, end, frames, after)
        if options:
            draw = lambda: postures.posture_draw(index, options, frames, rng, after)  # noqa: E731
    if draw is None and intent.action is not None and intent.count is not None:
        reps = counts.count_options(index, text, intent, frames)
        count = intent.count
        if reps:
            draw = lambda: counts.count_draw(index, reps, frames, count, rng, after)  # noqa: E731
    if draw is None and (intent.travel is not None or intent.side is not None):
        cands = (con.travel_candidates(index, text, intent.travel, frames) if intent.travel is not None
                 else con.side_candidates(index, text, intent))
        wide = con.TRAVEL_MARGIN if intent.travel is not None else None
        short = index.narrow(cands, rng, wide) if cands else []
        if short:
            draw = lambda: index.chain(short, frames, rng, [0], after)  # noqa: E731
    if draw is None and intent.still:   # "stops walking and stands still": the nearest
        # captures of those words still walk; standing ones, from where the last one ended
        draw = lambda: index.track(STANDING, frames, rng, after=after)  # noqa: E731
    if draw is None:       # nothing narrower to draw from: text draws, checked (a speed band)
        return (verify.pick(index, plain, frames, specs) or plain()) if specs else plain()
    return verify.pick(index, draw, frames, specs) or plain()
