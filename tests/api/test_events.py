"""The job stream's contract on both sides: the TypeScript `StreamEvent` union
(frontend/src/api/types.ts) names the same events and fields as the pydantic models in
`interplay.api.events.EVENTS`, optional exactly where the server may leave a field out
(`OMIT_NONE`) and `| null` exactly where it may send null; the comparison is shown to catch a
planted difference; and `from_pipeline` rejects malformed pipeline events and passes a real
review event through unchanged."""

from __future__ import annotations

import re
import types
import typing
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from pydantic import ValidationError

from interplay.api.events import EVENTS, from_pipeline

ROOT = Path(__file__).resolve().parents[2]
TYPES_TS = ROOT / "frontend" / "src" / "api" / "types.ts"
OPEN, CLOSE = "{[(<", "}])>"
MEMBER_START = r"(?:readonly\s+)?(?:[A-Za-z_$][\w$]*|\"[^\"]+\")\s*\??\s*:"


@dataclass(frozen=True)
class Field:
    optional: bool    # may be left out of the event
    nullable: bool    # may be null when present


Schema = dict[str, dict[str, Field]]    # event type → field name → Field


# --- the TypeScript side ------------------------------------------------------------------

def _strip_comments(ts: str) -> str:
    """The text with // and /* */ comments blanked (string literals kept as they are)."""
    out, i, n = [], 0, len(ts)
    while i < n:
        c = ts[i]
        if c in "\"'`":
            j = i + 1
            while j < n and ts[j] != c:
                j += 2 if ts[j] == "\\" else 1
            out.append(ts[i:j + 1])
            i = j + 1
        elif ts.startswith("//", i):
            j = ts.find("\n", i)
            i = n if j < 0 else j
        elif ts.startswith("/*", i):
            j = ts.find("*/", i + 2)
            i = n if j < 0 else j + 2
            out.append(" ")
        else:
            out.append(c)
            i += 1
    return "".join(out)


def _split_top(text: str, seps: str) -> list[str]:
    """`text` split at the characters in `seps` outside brackets and string literals (the `>`
    of an arrow `=>` does not close a bracket)."""
    parts, depth, start, i, n = [], 0, 0, 0, len(text)
    while i < n:
        c = text[i]
        if c in "\"'`":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            i = j + 1
            continue
        if c in OPEN:
            depth += 1
        elif c in CLOSE and not (c == ">" and i and text[i - 1] == "="):
            depth -= 1
        elif depth == 0 and c in seps:
            parts.append(text[start:i])
            start = i + 1
        i += 1
    parts.append(text[start:])
    return [p.strip() for p in parts if p.strip()]


def _matching(text: str, i: int) -> int:
    """Index of the bracket closing the one at `i`."""
    depth = 0
    for j in range(i, len(text)):
        if text[j] in OPEN:
            depth += 1
        elif text[j] in CLOSE and not (text[j] == ">" and text[j - 1] == "="):
            depth -= 1
            if depth == 0:
                return j
    raise ValueError(f"unbalanced bracket at {i}")


def _declaration(ts: str, name: str) -> str:
    """The body of `type name = …;` (to the `;` at depth 0) or `interface name {…}`."""
    m = re.search(rf"\b(?:type\s+{name}\s*=|interface\s+{name}\b[^{{]*(?={{))", ts)
    if not m:
        raise ValueError(f"no declaration of {name} in types.ts")
    if m.group(0).startswith("interface"):
        start = m.end()
        return ts[start:_matching(ts, start) + 1]
    rest = ts[m.end():]
    return _split_top(rest + ";", ";")[0]


def _fields(body: str) -> dict[str, tuple[bool, str]]:
    """`{ a: T; b?: U }` → {a: (False, "T"), b: (True, "U")}."""
    assert body.startswith("{") and body.endswith("}"), body
    members: list[str] = []
    for piece in _split_top(body[1:-1], ";,\n"):    # a type may go on over several lines
        if members and not re.match(MEMBER_START, piece):
            members[-1] += " " + piece
        else:
            members.append(piece)
    out = {}
    for member in members:
        m = re.fullmatch(r"(?:readonly\s+)?([A-Za-z_$][\w$]*|\"[^\"]+\")\s*(\??)\s*:\s*(.+)", member,
                         re.S)
        if not m:
            raise ValueError(f"cannot read the member {member!r}")
        out[m.group(1).strip('"')] = (m.group(2) == "?", m.group(3).strip())
    return out


def ts_schema(ts: str, union: str = "StreamEvent") -> Schema:
    """{event type: {field: Field}} of the union `union` in a types.ts text; a member may be an
    inline object type or the name of an interface / object type declared in the same text."""
    ts = _strip_comments(ts)
    schema: Schema = {}
    for member in _split_top(_declaration(ts, union), "|"):
        body = member if member.startswith("{") else _declaration(ts, member)
        fields = _fields(body)
        optional, literal = fields.pop("type", (False, ""))
        m = re.fullmatch(r"\"([^\"]+)\"|'([^']+)'", literal)
        if optional or not m:
            raise ValueError(f"member without a literal `type`: {member[:60]!r}")
        name = m.group(1) or m.group(2)
        if name in schema:
            raise ValueError(f"event {name!r} is declared twice")
        schema[name] = {f: Field(opt, "null" in _split_top(t, "|")) for f, (opt, t) in fields.items()}
    return schema


# --- the Python side ----------------------------------------------------------------------

def _allows_none(annotation) -> bool:
    return typing.get_origin(annotation) in (typing.Union, types.UnionType) and \
        type(None) in typing.get_args(annotation)


def py_schema(events=EVENTS) -> Schema:
    """The same shape from the pydantic models: a field is optional when the server may leave
    it out (in `OMIT_NONE`: it has a default and is dropped when None), nullable when its type
    allows None and it is sent anyway. `type` is the discriminator, always sent."""
    schema: Schema = {}
    for model in events:
        (name,) = typing.get_args(model.model_fields["type"].annotation)
        schema[name] = {
            f: Field(f in model.OMIT_NONE, f not in model.OMIT_NONE and _allows_none(info.annotation))
            for f, info in model.model_fields.items() if f != "type"}
    return schema


def differences(ts: Schema, py: Schema) -> list[str]:
    """What differs between the two sides, one line each (empty when they agree)."""
    out = [f"event {e!r} only in types.ts" for e in sorted(ts.keys() - py.keys())]
    out += [f"event {e!r} only in events.py" for e in sorted(py.keys() - ts.keys())]
    for e in sorted(ts.keys() & py.keys()):
        t, p = ts[e], py[e]
        out += [f"{e}.{f} only in types.ts" for f in sorted(t.keys() - p.keys())]
        out += [f"{e}.{f} only in events.py" for f in sorted(p.keys() - t.keys())]
        for f in sorted(t.keys() & p.keys()):
            if t[f].optional != p[f].optional:
                out.append(f"{e}.{f}: optional in {'types.ts' if t[f].optional else 'events.py'} only")
            if t[f].nullable != p[f].nullable:
                out.append(f"{e}.{f}: nullable in {'types.ts' if t[f].nullable else 'events.py'} only")
    return out


# --- the tests ----------------------------------------------------------------------------

def test_the_typescript_union_mirrors_the_pydantic_events():
    ts, py = ts_schema(TYPES_TS.read_text()), py_schema()
    assert len(py) == len(EVENTS) == 11
    assert differences(ts, py) == []
    assert ts["error"] == {"message": Field(False, False), "stage": Field(True, False),
                           "cancelled": Field(True, False)}
    assert ts["correction"]["score_after"] == Field(False, True)
    assert {"summary", "score_kind", "confirmed"} <= ts["review"].keys()


def test_only_omitted_fields_have_defaults():
    """"Optional" means the same under both readings: every field other than `type` with a
    default is one left out when None, and the rest are always sent."""
    for model in EVENTS:
        with_default = {f for f, info in model.model_fields.items()
                        if not info.is_required() and f != "type"}
        assert with_default == set(model.OMIT_NONE), model.__name__
        assert all(model.model_fields[f].default is None for f in model.OMIT_NONE)


@pytest.mark.parametrize("old, new, expected", [
    ("score_kind: string;", "score_type: string;",
     ["review.score_type only in types.ts", "review.score_kind only in events.py"]),
    ("stage?: string;", "stage: string;", ["error.stage: optional in events.py only"]),
    ("score_after: number | null;", "score_after: number;",
     ["correction.score_after: nullable in events.py only"]),
    ('| { type: "metrics"; metrics: Metrics }', "", ["event 'metrics' only in events.py"]),
])
def test_a_planted_difference_is_reported(old, new, expected):
    text = TYPES_TS.read_text()
    assert text.count(old) == 1
    assert differences(ts_schema(text.replace(old, new)), py_schema()) == expected


def test_the_parser_reads_named_members_comments_and_nested_types():
    ts = """
    /** a | b; */
    export interface Ping { type: "ping"; at: number; // when | sent
      kind:
        | "a"
        | "b"
      payload?: { a: [number, string][]; f: (x: number) => void } }
    export type Ev =
      | Ping
      | { type: 'pong'; data: Record<string, number | null>; note: string | null };
    """
    assert ts_schema(ts, "Ev") == {
        "ping": {"at": Field(False, False), "kind": Field(False, False), "payload": Field(True, False)},
        "pong": {"data": Field(False, False), "note": Field(False, True)}}


def _segment(**kw) -> dict:
    return {"type": "segment", "index": 0, "status": "generating", "generator": "spam", **kw}


@pytest.mark.parametrize("event", [
    {k: v for k, v in _segment().items() if k != "index"},     # a field missing
    _segment(status="queued"),                                   # not one of the statuses
    _segment(extra=1),                                           # a field no model has
    {"type": "heartbeat"},                                       # an unknown event
    {"index": 0, "status": "done", "generator": "spam"},         # no type at all
])
def test_from_pipeline_rejects_malformed_events(event):
    with pytest.raises(ValidationError):
        from_pipeline(event)


def test_from_pipeline_omits_none_only_where_declared():
    correction = {"type": "correction", "segment": 1, "round": 1, "accepted": False,
                  "instruction": {"kind": "regenerate", "prompt": "walk"}, "score_before": 0.4,
                  "score_after": None}
    assert from_pipeline(correction) == correction             # score_after stays, null
    assert from_pipeline({**correction, "reason": "no SPAM"})["reason"] == "no SPAM"
    assert from_pipeline({"type": "error", "message": "boom"}) == {"type": "error", "message": "boom"}
    assert from_pipeline(_segment()) == _segment()


class _Encoder:
    """A stand-in for MiniLM: deterministic unit vectors from the text's shape."""

    def encode(self, texts: list[str]) -> np.ndarray:
        v = np.array([[len(t) % 7 + 1.0, t.count(" ") + 1.0, 1.0] for t in texts])
        return v / np.linalg.norm(v, axis=1, keepdims=True)


def test_a_real_review_event_round_trips():
    from interplay.review.reviewer import review
    from tests.helpers.synthetic_motion import fk_motion

    walk, _ = fk_motion(60, "walk")
    from interplay.planner.schema import Segment

    seg = Segment(index=2, prompt="a person walks forward", base="a person walks", start=0,
                  end=60, seconds=3.0, persons=[0],
                  edits={"left_arm": "raises the left arm above the head"})
    event = review(seg, [walk], encoder=_Encoder(), round=1).event()
    assert event["confirmed"] == {"left_arm": False} and event["instructions"]
    assert set(event) == {"type", *py_schema()["review"]}
    assert from_pipeline(event) == event
