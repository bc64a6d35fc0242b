"""Validation errors as plain words: one line a person (or an API client) can read, e.g.
"seconds must be at most 20 (got 999); persons must be 1 or 2 (got 3)", instead of pydantic's
"seconds: Input should be less than or equal to 20". The field's dotted location stays first, so
a client can still tell which field it was (`trajectory.points.1.0 must be a number (got true)`).
Messages nested inside a value error (the planner's path checks) are reworded the same way."""

from __future__ import annotations

import json
from typing import Any

# pydantic's wording → plain words (applied in order, anywhere in a message; a longer wording
# before its own beginning)
_WORDS: tuple[tuple[str, str], ...] = (
    ("Input should be less than or equal to ", "must be at most "),
    ("Input should be greater than or equal to ", "must be at least "),
    ("Input should be less than ", "must be less than "),
    ("Input should be greater than ", "must be more than "),
    ("Input should be a valid integer, got a number with a fractional part", "must be a whole number"),
    ("Input should be a valid integer, unable to parse string as an integer", "must be a whole number"),
    ("Input should be a valid integer", "must be a whole number"),
    ("Input should be a valid number, unable to parse string as a number", "must be a number"),
    ("Input should be a valid number", "must be a number"),
    ("Input should be a finite number", "must be a finite number"),
    ("Input should be a valid string", "must be text"),
    ("Input should be a valid boolean, unable to interpret input", "must be true or false"),
    ("Input should be a valid boolean", "must be true or false"),
    ("Input should be a valid list", "must be a list"),
    ("Input should be a valid array", "must be a list"),
    ("Input should be a valid dictionary or object to extract fields from", "must be a JSON object"),
    ("Input should be a valid dictionary", "must be a JSON object"),
    ("Input should be ", "must be "),
)
# wordings with numbers: pydantic's words before N, after it ("s" may follow), before M; ours
_COUNTED: tuple[tuple[str, str, str, str], ...] = (
    ("String should have at most ", " character", "", "must be at most {} characters long"),
    ("String should have at least ", " character", "", "must be at least {} characters long"),
    ("List should have at most ", " item", " after validation, not ", "must have at most {} items (it has {})"),
    ("List should have at least ", " item", " after validation, not ", "must have at least {} items (it has {})"),
)
_PATTERN = ("String should match pattern '", "is not in the expected form")       # then '…'
_LAST_WORDS: tuple[tuple[str, str], ...] = (
    ("Field required", "is required"),
    ("Extra inputs are not permitted", "is not a field here"),
    ("Value error, ", ""),
)


def _digits(text: str) -> str:
    """The digits `text` starts with."""
    return text[:next((i for i, c in enumerate(text) if not c.isdecimal()), len(text))]


def _counted(message: str, head: str, unit: str, tail: str, ours: str) -> str:
    """Each "<head>N<unit>[s]" (then "<tail>M" when there is a tail) reworded as `ours`."""
    out, rest = "", message
    while head in rest:
        before, _, rest = rest.partition(head)
        out += before
        numbers = [_digits(rest)]
        end = len(numbers[0]) + len(unit)
        ok = bool(numbers[0]) and rest.startswith(unit, len(numbers[0]))
        end += ok and rest.startswith("s", end)
        if ok and tail:
            ok = rest.startswith(tail, end)
            numbers.append(_digits(rest[end + len(tail):]) if ok else "")
            ok, end = bool(numbers[-1]), end + len(tail) + len(numbers[-1])
        out, rest = (out + ours.format(*numbers), rest[end:]) if ok else (out + head, rest)
    return out + rest


def _pattern_named(message: str) -> str:
    """"String should match pattern '…'" → "is not in the expected form"."""
    head, ours = _PATTERN
    out, rest = "", message
    while head in rest:
        before, _, after = rest.partition(head)
        if "'" not in after:
            break
        out, rest = out + before + ours, after.partition("'")[2]
    return out + rest


def _name_char(c: str) -> bool:
    return c.isalnum() or c in "_."


def _field_first(message: str) -> str:
    """"size_m: must be …" → "size_m must be …": a field name (a word, dots between words)
    before ": must ", ": is " or ": has " loses its colon."""
    out, start, i = "", 0, message.find(": ")
    while i >= 0:
        verb = next((v for v in ("must ", "is ", "has ") if message.startswith(v, i + 2)), None)
        before = message[start:i]
        name = before[len(before) - next((k for k, c in enumerate(reversed(before)) if not _name_char(c)),
                                         len(before)):]
        if verb and any(_name_char(c) and c != "." for c in name):
            out, start = out + message[start:i] + " " + verb, i + 2 + len(verb)
            i = message.find(": ", start)
        else:
            i = message.find(": ", i + 1)
    return out + message[start:]


# errors about the value itself (its type or range): the message says what was sent
_SAYS_INPUT = ("less_than", "greater_than", "_type", "literal_error", "finite_number", "int_from_float", "pattern",
               "int_parsing", "float_parsing", "bool_parsing", "enum")
_LOCATION_PREFIXES = ("body", "query", "path", "header")
_VERBS = ("must ", "is ", "has ", "should ", "needs ")


def plain(message: str) -> str:
    """pydantic's wording in `message` replaced by plain words."""
    for words, ours in _WORDS:
        message = message.replace(words, ours)
    for head, unit, tail, counted in _COUNTED:
        message = _counted(message, head, unit, tail, counted)
    message = _pattern_named(message)
    for words, ours in _LAST_WORDS:
        message = message.replace(words, ours)
    return _field_first(message)


def _shown(value: Any) -> str | None:
    """A short JSON rendering of a sent value, or None when it is long or not a plain value."""
    if isinstance(value, bool | int | float | str) or value is None:
        try:
            text = json.dumps(value, allow_nan=True)
        except (TypeError, ValueError):
            return None
        return text if len(text) <= 24 else None
    return None


def readable_errors(errors) -> str:
    """Pydantic errors as one readable line, e.g. "seconds must be at most 20 (got 999);
    persons must be 1 or 2 (got 3)"."""
    parts = []
    for err in errors:
        loc = [str(x) for x in err.get("loc", ()) if x not in _LOCATION_PREFIXES]
        kind = str(err.get("type", ""))
        msg = plain(str(err.get("msg", "invalid value")))
        if kind == "json_invalid":
            why = err.get("ctx", {}).get("error", "parse error")
            loc, msg = [], f"request body is not valid JSON ({why})"
        elif kind == "missing" and not loc:
            msg = "a JSON request body is required"
        elif kind == "model_attributes_type":
            msg = "request body must be a JSON object"
        if any(k in kind for k in _SAYS_INPUT) and "input" in err:
            shown = _shown(err["input"])
            if shown is not None:
                msg += f" (got {shown})"
        if not loc:
            parts.append(msg)
        else:
            joiner = " " if msg.startswith(_VERBS) else ": "
            parts.append(f"{'.'.join(loc)}{joiner}{msg}")
    return "; ".join(parts) or "invalid request"
