"""Optional LLM planner: any OpenAI-compatible chat endpoint, prompted as CoMA's task planner
(appendix C: recaption → temporal segments → base motion + local edits), answering the plan
as JSON. The answer is parsed with json.loads and validated with pydantic — never executed.
On any error, timeout or invalid answer the embedded planner answers instead and
`fallback_reason` says why.

    settings = Settings(llm_base_url="http://localhost:11434/v1", llm_model="qwen2.5:7b")
    plan = llm_plan("a person does the wakanda salute", 1, 4.0, settings,
                    fallback=lambda: embedded_plan(...))

Bounded whatever the endpoint does: one deadline (INTERPLAY_LLM_TIMEOUT_S) for the whole call,
connecting, sending and every byte of the answer together (an endpoint dripping one byte a
second cannot hold the job past it); the body is streamed and the read stops past MAX_BODY
bytes; JSON is parsed without NaN or infinities, and deep nesting, huge numbers or wrong types
are reasons to fall back, like any other, never an error of the job.
"""

from __future__ import annotations

import asyncio
import json
import math
import threading
from typing import Annotated, Any, Callable, Coroutine, TypeVar

import httpx
from pydantic import BaseModel, ConfigDict, Field, Strict, ValidationError

from interplay.motion.skeleton import FPS
from interplay.planner.durations import fit, need_of_text
from interplay.planner.manner.travel import from_trajectory
from interplay.planner.schema import (
    MAX_SEGMENTS,
    PartEdits,
    Plan,
    RoleTiming,
    TrajectorySpec,
    Travel,
    readable,
)

MAX_ANSWER = 200_000     # characters of model output we are willing to parse
MAX_BODY = 1_000_000     # bytes of the endpoint's answer read before giving up on it
MAX_REASON = 300         # characters of a fallback reason kept in the plan
T = TypeVar("T")


class LLMSegment(BaseModel):
    """One step as the model writes it (frames are ours to compute)."""
    model_config = ConfigDict(extra="ignore")
    prompt: str = Field(min_length=1, max_length=500)
    base: str = Field(min_length=1, max_length=300)
    edits: PartEdits = Field(default_factory=PartEdits)
    trajectory: TrajectorySpec | None = None
    seconds: Annotated[float, Strict()] = Field(gt=0, le=30, allow_inf_nan=False)
    persons: list[Annotated[int, Strict()]] = Field(default_factory=lambda: [0], min_length=1,
                                                     max_length=2)
    roles: dict[str, Annotated[str, Field(max_length=500)]] | None = Field(default=None,
                                                                           max_length=2)
    repeat: Annotated[int, Strict()] = Field(default=1, ge=1, le=20)
    travel: Travel | None = None
    timing: RoleTiming | None = None


class LLMAnswer(BaseModel):
    model_config = ConfigDict(extra="ignore")
    rewritten: str = Field(min_length=1, max_length=2000)
    segments: list[LLMSegment] = Field(min_length=1, max_length=MAX_SEGMENTS)
    reasons: list[Annotated[str, Field(max_length=500)]] = Field(default_factory=list,
                                                                 max_length=50)


SYSTEM = """You are the task planner of a text-to-motion system. Plan the motion in three steps.
1. Recaption: accurately infer the posture and movement of the body from the description, \
with no information lost, using only plain motion words from motion-capture captions (walk, \
run, jump, sit down, raise the left arm, kick with the right foot, ...). Replace context-rich \
gestures and poses by what the body does ("wakanda forever salute" -> "crosses both arms in \
front of the chest") and drop context that does not change the motion (emotions, places, \
teams, dates, purposes). Answer questions with the motion that answers them.
2. Temporal segments: split the motion into consecutive steps, each one single, concrete \
movement (1 to 4 steps, at most 8; do not use more steps than the action needs). Simultaneous \
movements ("while", "with") stay in one step. A count ("three times") is `repeat`.
3. Decompose each step: `base` is the primary whole-body motion including head movement and \
the global path, without limb details ("a person walks in a circle"); `edits` gives for \
left_arm, right_arm, left_leg and right_leg what that limb does at the same time ("raises the \
left arm"), or null; `trajectory` is a path when the step asks for one (shape: line, arc, \
circle, zigzag, s_curve, heart, figure_eight, square, spiral, polyline, free; clockwise seen \
from above; size_m, distance_m, turns), else null. Walking or running backwards or sideways \
is not a path: set `travel` (forward|backward|left|right, the way the body moves relative to \
where it faces) and leave the trajectory null. A pose kept during the step ("with the arms \
crossed", "hands on hips", "hold a T-pose") is an edit per arm starting "holds" with its \
detail ("holds both arms crossed in front of the chest"). \
Estimate `seconds` for each step from how long the movement needs (a jump about 1.5 s, a walk \
of 5 m about 4 s, a sprint at least 2.5 s). With two people, `persons` lists who moves (0 \
and/or 1) and `roles` says what each does, e.g. {"0": "a person stands still", "1": "a person \
walks away"}; when one answers the other ("one pushes the other, who stumbles backwards"), \
use one step for the action and one for the answer, each with `timing` {"lead": who starts, \
"response": "contact"|"after"|"with", "phase": "lead"|"response"|"both"}.
Write every prompt as "a person ..." in the present tense. Do not include reasoning outside \
the JSON. Answer with one JSON object only, matching this JSON schema:
"""


def _messages(prompt: str, persons: int, seconds: float | None) -> list[dict]:
    schema = json.dumps(LLMAnswer.model_json_schema(), separators=(",", ":"))
    length = f"{seconds:g} seconds in total" if seconds else "choose the length"
    user = (f"People: {persons}. Length: {length}.\n<Input>\n{prompt}\n</Input>")
    return [{"role": "system", "content": SYSTEM + schema}, {"role": "user", "content": user}]


def _unfenced(text: str) -> str:
    """A model's answer without the ``` (or ```json) fence around it."""
    if text.startswith("```"):
        text = text[3:]
        text = (text[4:] if text.startswith("json") else text).lstrip()
    return text[:-3].rstrip() if text.endswith("```") else text


def extract_json(content: str) -> dict:
    """The JSON object in a model's answer (bare, or inside ``` fences / surrounding text)."""
    if not isinstance(content, str) or not content.strip():
        raise ValueError("the answer is empty")
    if len(content) > MAX_ANSWER:
        raise ValueError(f"the answer is longer than {MAX_ANSWER} characters")
    text = _unfenced(content.strip())
    start, end = text.find("{"), text.rfind("}")
    if start < 0 or end <= start:
        raise ValueError("the answer contains no JSON object")
    data = loads(text[start:end + 1], "the answer")
    if not isinstance(data, dict):
        raise ValueError("the answer is not a JSON object")
    return data


def _no_constant(name: str) -> float:
    raise ValueError(f"{name} is not a JSON number")


def _finite(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise ValueError(f"{text[:20]} is too large a number")
    return value


def loads(text: str | bytes, what: str) -> Any:
    """Strict JSON: no NaN or Infinity, no number that overflows a float; ValueError (never
    RecursionError) for whatever is not, naming `what`."""
    try:
        return json.loads(text, parse_constant=_no_constant, parse_float=_finite)
    except json.JSONDecodeError as exc:
        raise ValueError(f"{what} is not valid JSON ({exc.msg} at character {exc.pos})") from None
    except RecursionError:
        raise ValueError(f"{what} is nested too deeply") from None
    except ValueError as exc:          # NaN, 1e999, an integer of more than 4300 digits
        raise ValueError(f"{what} is not valid JSON ({str(exc)[:80]})") from None


def to_plan(answer: LLMAnswer, prompt: str, persons: int, seconds: float | None) -> Plan:
    """Frames for the model's steps (scaled to `seconds`), validated as a Plan."""
    est = [s.seconds for s in answer.segments]
    total = max(1, round((seconds if seconds else min(sum(est), 60.0)) * FPS))
    if len(est) > total // 10:
        raise ValueError(f"{len(est)} steps do not fit in {total / FPS:g} s")
    # The model's seconds as each step's want; what it needs at least and whether it may take
    # spare time from its base verb, as the embedded planner fits them (durations.fit).
    needs = [need_of_text(s.base, s.seconds, s.repeat) for s in answer.segments]
    frames, start = fit(needs, total), 0
    segments: list[dict[str, Any]] = []
    for i, (s, n) in enumerate(zip(answer.segments, frames)):
        if any(p >= persons or p < 0 for p in s.persons):
            raise ValueError(f"segment {i}: persons {s.persons} for a plan of {persons} person(s)")
        roles = ({k: v for k, v in s.roles.items() if k in ("0", "1")} or None) if s.roles and \
            persons == 2 else None
        trajectory, travel = from_trajectory(s.trajectory, s.travel)   # no backwards paths
        segments.append({**s.model_dump(exclude={"persons", "roles", "seconds", "trajectory",
                                                 "travel", "timing"}),
                         "index": i, "persons": sorted(set(s.persons)), "roles": roles,
                         "seconds": n / FPS, "start": start, "end": start + n,
                         "trajectory": trajectory, "travel": travel,
                         "timing": s.timing if persons == 2 else None})
        start += n
    # Validated from plain data: `persons` and the segments are checked by the Plan schema.
    return Plan.model_validate({"prompt": prompt, "rewritten": answer.rewritten, "persons": persons,
                                "seconds": total / FPS, "segments": segments,
                                "reasons": answer.reasons, "planner": "llm"})


class LLMTimeout(Exception):
    """The call went past its deadline."""


async def _post(url: str, body: dict, headers: dict[str, str], timeout: float,
                transport: httpx.AsyncBaseTransport | None) -> bytes:
    """The endpoint's answer body, read in chunks and abandoned past MAX_BODY bytes."""
    async with httpx.AsyncClient(timeout=timeout, transport=transport) as client:
        async with client.stream("POST", url, json=body, headers=headers) as r:
            if r.status_code != 200:
                raise ValueError(f"the endpoint answered HTTP {r.status_code}")
            encoding = r.headers.get("content-encoding", "identity").strip().lower()
            if encoding not in ("", "identity"):
                raise ValueError(f"the endpoint compressed its answer ({encoding}) although "
                                 "asked not to")
            declared = r.headers.get("content-length", "")
            if declared.isdigit() and int(declared) > MAX_BODY:
                raise ValueError(f"the endpoint's answer is {int(declared)} bytes long; the "
                                 f"limit is {MAX_BODY}")
            data = bytearray()
            async for chunk in r.aiter_bytes():      # identity: as they arrive
                data += chunk
                if len(data) > MAX_BODY:
                    raise ValueError(f"the endpoint's answer is longer than {MAX_BODY} bytes")
            return bytes(data)


def _run(coro: Coroutine[Any, Any, T], timeout: float) -> T:
    """Run `coro` on its own event loop, cancelled after `timeout` seconds (LLMTimeout); on a
    thread of its own if this one already runs a loop."""
    async def bounded() -> T:
        try:
            return await asyncio.wait_for(coro, timeout)
        except asyncio.TimeoutError:
            raise LLMTimeout() from None

    try:
        asyncio.get_running_loop()
    except RuntimeError:
        return asyncio.run(bounded())
    out: dict[str, Any] = {}

    def target() -> None:
        try:
            out["value"] = asyncio.run(bounded())
        except BaseException as exc:   # handed to the caller below
            out["error"] = exc
    thread = threading.Thread(target=target, name="llm-planner", daemon=True)
    thread.start()
    thread.join()
    if "error" in out:
        raise out["error"]
    return out["value"]


def ask(prompt: str, persons: int, seconds: float | None, settings,
        transport: httpx.AsyncBaseTransport | None = None) -> Plan:
    """The LLM's plan; raises ValueError / LLMTimeout / httpx errors when there is none."""
    url = settings.llm_base_url.rstrip("/") + "/chat/completions"
    headers = {"Content-Type": "application/json", "Accept-Encoding": "identity"}
    if settings.llm_api_key is not None:
        headers["Authorization"] = f"Bearer {settings.llm_api_key.get_secret_value()}"
    body = {"model": settings.llm_model, "messages": _messages(prompt, persons, seconds),
            "temperature": 0, "response_format": {"type": "json_object"}}
    raw = _run(_post(url, body, headers, settings.llm_timeout_s, transport), settings.llm_timeout_s)
    try:
        content = loads(raw, "the endpoint's answer")["choices"][0]["message"]["content"]
    except (ValueError, KeyError, IndexError, TypeError):
        raise ValueError("the endpoint's answer is not an OpenAI chat completion") from None
    try:
        answer = LLMAnswer.model_validate(extract_json(content))
        return to_plan(answer, prompt, persons, seconds)
    except ValidationError as exc:
        raise ValueError(f"the answer does not match the plan schema: {readable(exc)}") from None


def llm_plan(prompt: str, persons: int, seconds: float | None, settings,
             fallback: Callable[[], Plan],
             transport: httpx.AsyncBaseTransport | None = None) -> Plan:
    """The LLM's plan, or the fallback's with `fallback_reason` saying what went wrong: any
    failure of the endpoint or its answer falls back, none fails the caller."""
    try:
        plan = ask(prompt, persons, seconds, settings, transport)
        plan.reasons.insert(0, f"llm: planned by {settings.llm_model}")
        return plan
    except (LLMTimeout, httpx.TimeoutException):
        why = f"timed out after {settings.llm_timeout_s:g} s"
    except httpx.HTTPError as exc:
        why = f"request failed ({type(exc).__name__}: {exc})"
    except RecursionError:
        why = "the answer is nested too deeply"
    except ValueError as exc:
        why = str(exc)
    except Exception as exc:   # whatever else the answer provoked: still the embedded planner
        why = f"the answer could not be used ({type(exc).__name__}: {exc})"
    if len(why) > MAX_REASON:
        why = why[:MAX_REASON - 1] + "…"
    plan = fallback()
    plan.fallback_reason = f"LLM planner {settings.llm_model!r}: {why}; the embedded planner answered"
    return plan
