"""Validation errors as plain words: one line a person (or an API client) can read, e.g.
"seconds must be at most 20 (got 999); persons must be 1 or 2 (got 3)", instead of pydantic's
"seconds: Input should be less than or equal to 20". The field's dotted location stays first, so
a client can still tell which field it was (`trajectory.points.1.0 must be a number (got true)`).
Messages nested inside a value error (the planner's path checks) are reworded the same way."""

from __future__ import annotations

import json
import re
from typing import Any

# pydantic's wording → plain words (applied in order, anywhere in a message)
_WORDS: tuple[tuple[re.Pattern[str], str], ...] = tuple((re.compile(a), b) for a, b in (
    (r"Input should be less than or equal to ", "must be at most "),
    (r"Input should be greater than or equal to ", "must be at least "),
    (r"Input should be less than ", "must be less than "),
    (r"Input should be greater than ", "must be more than "),
    (r"Input should be a valid integer(, got a number with a fractional part|, unable to parse string as an integer)?",
     "must be a whole number"),
    (r"Input should be a valid number(, unable to parse string as a number)?", "must be a number"),
    (r"Input should be a finite number", "must be a finite number"),
    (r"Input should be a valid string", "must be text"),
    (r"Input should be a valid boolean(, unable to interpret input)?", "must be true or false"),
    (r"Input should be a valid (list|array)", "must be a list"),
    (r"Input should be a valid dictionary( or object to extract fields from)?", "must be a JSON object"),
    (r"Input should be ", "must be "),
    (r"String should have at most (\d+) characters?", r"must be at most \1 characters long"),
    (r"String should have at least (\d+) characters?", r"must be at least \1 characters long"),
    (r"String should match pattern '[^']*'", "is not in the expected form"),
    (r"List should have at most (\d+) items? after validation, not (\d+)", r"must have at most \1 items (it has \2)"),
    (r"List should have at least (\d+) items? after validation, not (\d+)", r"must have at least \1 items (it has \2)"),
    (r"Field required", "is required"),
    (r"Extra inputs are not permitted", "is not a field here"),
    (r"Value error, ", ""),
    (r"(\w[\w.]*): (must|is|has) ", r"\1 \2 "),   # "size_m: must be …" → "size_m must be …"
))

# errors about the value itself (its type or range): the message says what was sent
_SAYS_INPUT = ("less_than", "greater_than", "_type", "literal_error", "finite_number", "int_from_float", "pattern",
               "int_parsing", "float_parsing", "bool_parsing", "enum")
_LOCATION_PREFIXES = ("body", "query", "path", "header")
_VERBS = ("must ", "is ", "has ", "should ", "needs ")


def plain(message: str) -> str:
    """pydantic's wording in `message` replaced by plain words."""
    for pattern, words in _WORDS:
        message = pattern.sub(words, message)
    return message


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
