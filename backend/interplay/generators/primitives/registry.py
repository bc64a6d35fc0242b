"""The primitives by name (`PRIMITIVES`: how each is built, from `table.PRIMITIVE_TABLE`; the
phrasings it is found by, from the catalogue's entries made by it), each found from its text
through the MiniLM encoder (`find`: cosine similarity between the
text and each primitive's phrasings, the best phrasing's score per primitive; no pattern per
phrase), and built on its base posture (`build`: count, seconds, side and the table's fixed
parameters). Builder names are stable: `BUILDERS` maps each to its pure function.

    prim, sim = find("does some push-ups", get_encoder())     # (PRIMITIVES["push_up"], 0.8…)
    joints = build(prim, {"count": 3})                         # (T, 22, 3) on a captured prone base
    joints, entry = make("claps four times", get_encoder())    # found, counted, built
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from interplay.catalogue.load import catalogue, on_change
from interplay.catalogue.schema import Action
from interplay.generators.primitives.activity import activity
from interplay.generators.primitives.body import axes
from interplay.generators.primitives.contacts import hand_contacts
from interplay.generators.primitives.exercise import arm_circles, jumping_jacks, push_ups, sit_ups
from interplay.generators.primitives.gait import gait_asymmetric, gait_perturbed
from interplay.generators.primitives.head import head
from interplay.generators.primitives.legs import knee_lifts, lunges, squats
from interplay.generators.primitives.postures import posture
from interplay.generators.primitives.reach import reach_grasp_carry
from interplay.generators.primitives.table import ARMS, LEGS, PRIMITIVE_TABLE
from interplay.generators.primitives.timing import BORDER_S, seconds_for
from interplay.motion import skeleton as sk
from interplay.text.encoder import Encoder

BUILDERS: dict[str, Callable[..., np.ndarray]] = {
    "activity": activity, "hand_contacts": hand_contacts, "knee_lifts": knee_lifts, "squats": squats, "lunges": lunges,
    "push_ups": push_ups, "sit_ups": sit_ups, "jumping_jacks": jumping_jacks,
    "arm_circles": arm_circles, "reach_grasp_carry": reach_grasp_carry,
    "gait_asymmetric": gait_asymmetric, "gait_perturbed": gait_perturbed, "head": head,
}
SIDED = {"activity", "hand_contacts", "knee_lifts", "lunges", "arm_circles", "gait_asymmetric"}
PARTNER_AHEAD_M = 1.2      # where a partner stands for "look at the partner" when none is given


@dataclass(frozen=True)
class Primitive:
    name: str
    descriptions: tuple[str, ...]
    posture: str
    parts: tuple[str, ...]
    counts: bool
    seconds: float              # per cycle when it counts, else for the whole move
    builder: str
    params: dict = field(default_factory=dict, hash=False)

    def default_seconds(self, count: int = 1) -> float:
        return seconds_for(count, self.seconds) if self.counts else self.seconds


def _descriptions(name: str) -> tuple[str, ...]:
    """The phrasings a primitive is found by: the descriptions of every catalogue entry made
    by it (`made_by.primitive`), in catalogue order."""
    out: dict[str, None] = {}
    for a in catalogue().action:
        if a.made_by.primitive == name:
            out.update(dict.fromkeys(a.descriptions))
    return tuple(out)


def _activity(a: Action) -> Primitive:
    """An everyday activity of the catalogue (`made_by.moves`) as a primitive of its own name:
    counted per stroke, `cycle_s` a stroke, built on the posture its moves name."""
    mv = a.made_by.moves
    assert mv is not None
    parts = (() if mv.hands == "none" else ARMS if mv.hands in ("both", "alternate")
             else (f"{mv.hands}_arm",)) + (LEGS if mv.legs == "march" else ())
    return Primitive(name=a.name, descriptions=tuple(a.descriptions), posture=mv.posture,
                     parts=parts or ("head",), counts=True, seconds=mv.cycle_s,
                     builder="activity", params=mv.model_dump(exclude={"posture", "cycle_s"}))


def _primitives() -> dict[str, Primitive]:
    out = {row["name"]: Primitive(name=row["name"], descriptions=_descriptions(row["name"]),
                                  posture=row["posture"], parts=tuple(row["parts"]),
                                  counts=bool(row["counts"]), seconds=float(row["seconds"]),
                                  builder=row["builder"], params=dict(row["params"]))
           for row in PRIMITIVE_TABLE}
    for a in catalogue().action:
        if a.made_by.primitive == "activity" and a.descriptions:
            out[a.name] = _activity(a)
    return out


def activities() -> tuple[str, ...]:
    """The names of the catalogue's everyday activities among the primitives."""
    return tuple(n for n, p in PRIMITIVES.items() if p.builder == "activity")


def primitive_of(entry: Action | None) -> str | None:
    """The primitive a catalogue entry is made by (an activity: the entry's own name)."""
    if entry is None or entry.made_by.primitive is None:
        return None
    return entry.name if entry.made_by.primitive == "activity" else entry.made_by.primitive


# The table's primitives and the catalogue's activities; refilled in place (importers keep
# the same dict) when the catalogue in use changes.
PRIMITIVES: dict[str, Primitive] = _primitives()


_BANKS: dict[tuple[int, tuple[str, ...]], tuple[Encoder, np.ndarray, np.ndarray]] = {}
# Unit embeddings of phrasings, by (encoder, the texts themselves): the primitives' banks and
# any other phrasings matched against (primitive_steps: a verb entry's own descriptions).
_EMBEDDED: dict[tuple[int, tuple[str, ...]], tuple[Encoder, np.ndarray]] = {}


def _refresh() -> None:
    PRIMITIVES.clear()
    PRIMITIVES.update(_primitives())
    _BANKS.clear()
    _EMBEDDED.clear()


on_change(_refresh)


def unit(encoder: Encoder, text: str) -> np.ndarray:
    """The unit embedding (D,) of one text (a query)."""
    v = np.asarray(encoder.encode([text]), dtype=np.float64)[0]
    return v / max(float(np.linalg.norm(v)), 1e-12)


def embedded(encoder: Encoder, texts: tuple[str, ...]) -> np.ndarray:
    """Unit embeddings (K, D) of `texts`, computed once per encoder (the key holds its id and
    the entry the encoder itself, so a new encoder at a reused id is not served old ones)."""
    key = (id(encoder), texts)
    hit = _EMBEDDED.get(key)
    if hit is None or hit[0] is not encoder:
        emb = np.asarray(encoder.encode(list(texts)), dtype=np.float64)
        emb /= np.maximum(np.linalg.norm(emb, axis=1, keepdims=True), 1e-12)
        hit = _EMBEDDED[key] = (encoder, emb)
    return hit[1]


def _bank(encoder: Encoder, names: tuple[str, ...]) -> tuple[np.ndarray, np.ndarray]:
    """(phrasing embeddings (K, D), the primitive index of each (K,)), once per encoder."""
    key = (id(encoder), names)
    if key in _BANKS and _BANKS[key][0] is encoder:
        return _BANKS[key][1], _BANKS[key][2]
    texts, owner = [], []
    for i, n in enumerate(names):
        for d in PRIMITIVES[n].descriptions:
            texts.append(d)
            owner.append(i)
    emb = embedded(encoder, tuple(texts))
    _BANKS[key] = (encoder, emb, np.array(owner))
    return emb, np.array(owner)


def rank(text: str, encoder: Encoder, names: tuple[str, ...] | None = None
         ) -> list[tuple[Primitive, float]]:
    """Every primitive (or those named) with its similarity to `text`, best first."""
    names = tuple(names or PRIMITIVES)
    emb, owner = _bank(encoder, names)
    sims = emb @ unit(encoder, text.strip())
    best = np.full(len(names), -1.0)
    np.maximum.at(best, owner, sims)
    order = np.argsort(-best)
    return [(PRIMITIVES[names[i]], float(best[i])) for i in order]


def find(text: str, encoder: Encoder, names: tuple[str, ...] | None = None
         ) -> tuple[Primitive, float]:
    """The primitive whose phrasings are nearest `text` (cosine), and that similarity."""
    return rank(text, encoder, names)[0]


def build(prim: Primitive, params: dict, base: np.ndarray | None = None) -> np.ndarray:
    """The primitive's joints (T, 22, 3): on `base` when given, else on its posture held for
    params["seconds"] (default: its cycles' length). params: count, seconds, side, seat_m,
    partner (the other person's joints, for "look at the partner"), and any of the builder's
    own keyword arguments (they override the table's)."""
    p = dict(params)
    asked = p.pop("count", None)
    seconds = float(p.pop("seconds", 0) or 0)
    if asked:
        count = int(asked)
    elif prim.builder == "activity" and seconds:    # strokes fill the segment
        count = max(1, int(round((seconds - 2 * BORDER_S) / prim.seconds)))
    else:
        count = 2 if prim.counts else 1
    seconds = seconds or prim.default_seconds(count)
    seat = p.pop("seat_m", None)
    side = p.pop("side", None)
    partner = p.pop("partner", None)          # the other person's joints (T, 22, 3), if any
    if base is None:
        kw = {"seat_m": seat} if seat is not None else {}
        base = posture(prim.posture, seconds, **kw)
    args = {**prim.params, **p}
    if side is not None and prim.builder in SIDED:
        args["side"] = side
    if prim.builder == "head":
        if args.get("action") == "look_at" and "point" not in args:
            args["point"] = (np.asarray(partner, dtype=np.float64)[:len(base), sk.HEAD]
                             if partner is not None
                             else base[:, sk.NECK] + PARTNER_AHEAD_M * axes(base)[2])
        if prim.counts:
            args["count"] = count
        return BUILDERS["head"](base, **args)
    if prim.counts:
        args["count"] = count
    return BUILDERS[prim.builder](base, **args)


def make(text: str, encoder: Encoder, seconds: float | None = None, base: np.ndarray | None = None
         ) -> tuple[np.ndarray, dict]:
    """(joints, entry): the primitive `text` describes, with the count and side its words
    give, built for `seconds` (or its own length)."""
    from interplay.generators.retrieval.intent import count_of, side_of

    prim, sim = find(text, encoder)
    params: dict = {}
    count = count_of(text) if prim.counts else None
    if count:
        params["count"] = count
    side = side_of(text)
    if side:
        params["side"] = side
    if seconds:
        params["seconds"] = seconds
    joints = build(prim, params, base)
    return joints, {"primitive": prim.name, "similarity": round(sim, 4), **params}
