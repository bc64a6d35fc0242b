"""The planner: a prompt → a Plan of timed segments, each a base motion, part edits and an
optional trajectory (CoMA's task planner, section 3 and appendix C), offline by default.

    p = plan("two people shake hands, then one walks away in a circle", persons=2, seconds=8)
    [s.prompt for s in p.segments]
      → ["two people shake hands",
         "one person walks away in a circle while the other stands still"]
    p.segments[1].persons == [1]; p.segments[1].trajectory.shape == "circle"

Steps (each change is written to `reasons`): answer a question → drop motion-irrelevant
context → rewrite known gestures and poses (lexicon) → split into clauses (temporal) →
decompose each into base + part edits → nearest data phrase (MiniLM) for clauses with no known
motion → who does what (two people) → trajectories → durations, scaled to `seconds`.
With INTERPLAY_LLM_BASE_URL and INTERPLAY_LLM_MODEL set, `plan()` asks that model first
(`llm.py`) and comes back here on any failure.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any

from interplay.motion.skeleton import FPS
from interplay.planner import lexicon, questions, temporal
from interplay.planner.context import strip_context
from interplay.planner.decompose import POSTURE_BASE, Action, decompose, plain, split_subject
from interplay.planner.durations import allocate, estimate, fits
from interplay.planner.schema import Plan, TrajectorySpec
from interplay.planner.trajectory_text import parse as parse_trajectory
from interplay.planner.verbs import VERBS, is_verb, lookup, noun_verb

MAX_PROMPT = 500
MAX_SECONDS = 60.0
_OTHER = re.compile(r",?\s+while\s+the\s+other(?:\s+(?:one|person))?\s+(.+)$")
_CLOCK_TURN = re.compile(r"^(?:(?:he|she|they|it)\s+)?turns?\b.*\bo'?\s*clock\b")
_FILLER = {"a", "an", "the", "it", "up", "down", "some", "something", "again", "too", "also"}
IDLE = {**POSTURE_BASE, "standing": "a person stands still"}
# A leading subject the verb table did not split off ("a person picks up …": no known verb).
_SUBJECT = re.compile(r"^(?:(?:a|an|the|one|two|this|that)\s+)?(?:person|man|woman|boy|girl|guy|"
                      r"lady|kid|child|people|persons|men|women|figure|someone|somebody|he|she|"
                      r"they|both)\s+", re.I)
SIMILARITY = 0.7      # cosine above which an unknown clause takes the nearest known phrase
_ONSET = re.compile(r"\s+while\s+(?:striking|assuming|getting\s+into|moving\s+into)\s+([^,.;]+)",
                    re.IGNORECASE)
_BOTH = re.compile(r"^(?:two\s+(?:people|persons|men|women|boys|girls|friends|dancers|players)|they|"
                   r"both(?:\s+of\s+them)?|the\s+(?:two|couple|pair|dancers|players|partners|friends)"
                   r"(?:\s+\w+)?|everyone|each\s+(?:person|of\s+them)|we)$")
_MUTUAL = re.compile(r"\b(?:each\s+other|one\s+another|together|shake\s+hands|shakes\s+hands|hug|"
                     r"hugs|high[\s-]five|salsa|tango|waltz|partner)\b")


@dataclass
class _Step:
    action: Action
    repeat: int
    actors: list[int]
    trajectory: TrajectorySpec | None
    group: tuple[int, int] | None
    idle: dict[int, str]
    active: list[int]          # everyone who moves (actors, and "the other" when told what to do)


def _check(prompt, persons, seconds) -> None:
    if not isinstance(prompt, str) or not prompt.strip():
        raise ValueError("the prompt is empty")
    if len(prompt) > MAX_PROMPT:
        raise ValueError(f"the prompt is longer than {MAX_PROMPT} characters")
    if persons not in (1, 2):
        raise ValueError(f"persons must be 1 or 2, got {persons!r}")
    if seconds is not None and (not isinstance(seconds, (int, float)) or not math.isfinite(seconds)
                                or not 0 < seconds <= MAX_SECONDS):
        raise ValueError(f"seconds must be in (0, {MAX_SECONDS:g}], got {seconds!r}")


def _onset_poses(text: str) -> tuple[str, list[str]]:
    """"runs in a zigzag while striking <pose>" → "runs in a zigzag, then runs in a zigzag holding
    <pose>": a pose struck during travel is a second step (the pose is then held)."""
    m = _ONSET.search(text)
    entry = lexicon.find(m.group(1)) if m else None
    if m is None or entry is None or entry.hold is None:
        return text, []
    head = text[:m.start()]
    start = max(head.rfind(c) for c in ",.;") + 1
    clause = head[start:]
    words = temporal.normalize(clause).split()
    if not any((h := lookup(w)) and h[0].kind == "travel" for w in words):
        return text, []
    again = split_subject(" ".join(words))[1]
    new = f"{head}, then {again} holding {m.group(1)}{text[m.end():]}"
    return new, [f"temporal: '{m.group(0).strip()}' during travel → the pose is struck, then held "
                 f"while travelling ('{again}' twice)"]


def _actors(subject: str | None, persons: int, prev: list[int] | None, names: dict,
            text: str) -> list[int]:
    """Who acts in a clause: indices into the people (0-based). `names` maps the nouns seen
    so far ("man", "woman") to people; `prev` is who acted in the clause before."""
    if persons == 1:
        return [0]
    s = re.sub(r"\s+", " ", (subject or "").strip())
    if _MUTUAL.search(text) or _BOTH.match(s):
        return [0, 1]
    if not s:
        return prev or [0, 1]
    pair = re.match(r"^(?:a|an|the)?\s*(\w+) and (?:a|an|the)?\s*(\w+)$", s)
    if pair:
        names.update({pair.group(1): 0, pair.group(2): 1})
        return [0, 1]
    if re.match(r"^(?:the\s+)?(?:first(?:\s+(?:person|one))?|person\s+(?:1|one|a)|leader)$", s):
        return [0]
    if re.match(r"^(?:the\s+)?(?:second(?:\s+(?:person|one))?|person\s+(?:2|two|b)|follower|partner)$", s):
        return [1]
    if re.match(r"^(?:the\s+)?other(?:\s+(?:one|person))?$", s):
        return [1 - prev[0]] if prev and len(prev) == 1 else [0]
    if re.match(r"^(?:one|one\s+(?:of\s+them|person)|someone|a\s+person)$", s):
        # "one walks away": the second person moves, so the first (who anchors the shared
        # frame: their start pelvis is the origin) stays where they are.
        return [1]
    noun = s.split()[-1]
    if noun not in names:
        names[noun] = 0 if 0 not in names.values() else 1
    return [names[noun]]


def _prompt(step: _Step, persons: int) -> str:
    text = step.action.text
    if persons == 1:
        return f"a person {text}"
    if step.actors == [0, 1]:
        first = text.split(" ", 1)
        hit = lookup(first[0])
        verb = hit[0].base if hit else first[0]
        return f"two people {verb} {first[1] if len(first) > 1 else ''}".strip()
    idle = step.idle[1 - step.actors[0]]
    return f"one person {text} while the other {idle.removeprefix('a person ')}"


def _resolve(action: Action, clause: str, posture: str, last_parts, vocab, reasons):
    """A clause the decomposer did not understand: the nearest vocabulary phrase when close
    enough; None when the clause has no motion at all (it is dropped)."""
    words = re.findall(r"[a-z-]+", action.text)
    if all(is_verb(w, ("light",)) or w in _FILLER for w in words):
        reasons.append(f"dropped '{clause}': no motion in it")       # "gets (tired)"
        return None
    if vocab is not None:
        try:
            match = vocab().nearest(f"a person {action.text}")
        except Exception as exc:                     # no encoder installed: say so, go on
            reasons.append(f"similarity unavailable ({type(exc).__name__}: {exc})")
            vocab = None
        else:
            if match.score >= SIMILARITY:
                target = match.target.removeprefix("a person ")
                reasons.append(f"similarity: '{action.text}' → '{target}' (nearest {match.source} "
                               f"phrase '{match.phrase}', cosine {match.score:.2f})")
                new = decompose(target, posture, last_parts)
                if not new.known:                # a data phrase with a verb we lack ("high-five")
                    new.text = split_subject(target)[1] if split_subject(target)[0] else \
                        re.sub(r"^(?:two people|a person)\s+", "", target)
                    new.base, new.verb = f"a person {new.text}", VERBS["pose"]
                new.subject = action.subject
                return new
    if not any(lookup(w) or noun_verb(w) for w in words):
        reasons.append(f"dropped '{clause}': no motion in it")
        return None
    action.text = re.sub(r"^(?:two people|a person|the person|they|both)\s+", "", action.text)
    reasons.append(f"unknown motion '{action.text}': kept as written")
    action.base, action.verb = f"a person {action.text}", VERBS["pose"]
    return action


def embedded_plan(prompt: str, persons: int = 1, seconds: float | None = None,
                  vocabulary=None) -> Plan:
    """The offline plan. `vocabulary`: a callable returning a `Vocabulary` (loaded on first
    need), or None to plan without similarity."""
    _check(prompt, persons, seconds)
    reasons: list[str] = []
    text = re.sub(r"\s+", " ", prompt.replace("’", "'").replace("“", '"').replace("”", '"')).strip()
    text = re.sub(r"(?<![A-Za-z])'|'(?![A-Za-z])|\"", "", text)
    if questions.is_question(text):
        sim = (lambda q, opts: vocabulary().similar(q, opts)) if vocabulary else None
        try:
            text, why = questions.answer(text, sim)
        except Exception as exc:
            text, why = questions.answer(text, None)
            reasons.append(f"similarity unavailable ({type(exc).__name__})")
        reasons.append(why)
    for step in (strip_context, _onset_poses, lexicon.rewrite):
        text, notes = step(text)
        reasons.extend(notes)
    clauses = temporal.split(temporal.normalize(text)) or [temporal.Clause(text.lower())]
    steps: list[_Step] = []
    postures = ["standing"] * persons
    names: dict[str, int] = {}
    prev: list[int] | None = None
    last_parts: list[str] = []
    for clause in clauses:
        other = _OTHER.search(clause.text) if persons == 2 else None
        if other:                                  # "… while the other waves": both act
            clause.text = clause.text[:other.start()]
        if steps and _CLOCK_TURN.match(clause.text) and steps[-1].action.verb is not None \
                and steps[-1].action.verb.kind == "travel":     # "walks 5 m and turns right at 3 o'clock"
            last = steps[-1]
            last.action.text = f"{last.action.text} and {clause.text}"
            last.trajectory = parse_trajectory(last.action.text)
            reasons.append(f"trajectory: '{clause.text}' turns the walk before it")
            continue
        probe = decompose(clause.text, "standing")
        actors = _actors(probe.subject, persons, prev, names, clause.text)
        action = decompose(clause.text, postures[actors[0]], last_parts)
        if not action.known:
            action = _resolve(action, clause.text, postures[actors[0]], last_parts, vocabulary, reasons)
            if action is None:
                continue
        traj = parse_trajectory(action.text)
        if traj is not None and clause.group and traj.shape == "circle":
            k, n = clause.group            # one circle shared by n clauses: n arcs of it
            traj = traj.model_copy(update={"shape": "arc", "turns": round((traj.turns or 1.0) / n, 4)})
        idle = {i: IDLE.get(postures[i], IDLE["standing"]) for i in range(persons) if i not in actors}
        if other and len(actors) == 1:
            idle[1 - actors[0]] = "a person " + decompose(other.group(1)).text
        for i in actors:
            postures[i] = action.posture
        prev, last_parts = actors, list(action.edits) or last_parts
        active = [0, 1] if other and len(actors) == 1 else actors
        steps.append(_Step(action, clause.repeat, actors, traj, clause.group, idle, active))
    if not steps:                                   # nothing recognisable: keep the words
        action = decompose("stands still")
        action.text = plain(_SUBJECT.sub("", split_subject(temporal.normalize(text))[1]))
        action.base = f"a person {action.text}"
        steps = [_Step(action, 1, list(range(persons)), None, None, {}, list(range(persons)))]
        reasons.append("no motion recognised: one segment with the prompt as written")
    return _timed(prompt, persons, seconds, steps, reasons)


def _timed(prompt, persons, seconds, steps: list[_Step], reasons) -> Plan:
    est = [estimate(s.action.verb, s.trajectory, s.repeat, s.action.text) for s in steps]
    total = round((seconds if seconds is not None else min(sum(est), MAX_SECONDS)) * FPS)
    total = max(total, 1)
    if len(steps) > fits(total):                   # too short for every step: fold the tail
        keep = fits(total)
        reasons.append(f"durations: {len(steps)} steps do not fit in {total / FPS:g} s at "
                       f"≥ 0.5 s each; the last {len(steps) - keep + 1} are one segment")
        tail = steps[keep - 1:]
        merged = tail[0]
        merged.action.text = ", then ".join(s.action.text for s in tail)
        steps, est = steps[:keep - 1] + [merged], est[:keep - 1] + [sum(est[keep - 1:])]
    frames = allocate(est, total)
    if seconds is not None:
        reasons.append(f"durations: estimated {sum(est):.1f} s, scaled to {total / FPS:g} s")
    segments: list[dict[str, Any]] = []
    start = 0
    for i, (s, n) in enumerate(zip(steps, frames)):
        roles = None
        if persons == 2:
            roles = {str(p): (f"a person {s.action.text}" if p in s.actors else s.idle[p])
                     for p in range(2)}
        segments.append({
            "index": i, "prompt": _prompt(s, persons), "base": s.action.base,
            "edits": s.action.edits, "trajectory": s.trajectory, "seconds": n / FPS,
            "start": start, "end": start + n, "persons": s.active, "roles": roles,
            "repeat": s.repeat})
        start += n
    rewritten = ", then ".join(seg["prompt"] for seg in segments)
    # Validated from plain data: `persons` and the segments are checked by the Plan schema.
    return Plan.model_validate({"prompt": prompt, "rewritten": rewritten, "persons": persons,
                                "seconds": total / FPS, "segments": segments,
                                "reasons": reasons, "planner": "embedded"})


def plan(prompt: str, persons: int = 1, seconds: float | None = None, settings=None) -> Plan:
    """The plan for a prompt: the configured LLM when there is one (falling back to the
    embedded planner on any failure), else the embedded planner."""
    from interplay.planner.vocabulary import load_vocabulary
    from interplay.settings import get_settings

    _check(prompt, persons, seconds)
    settings = settings or get_settings()
    data_dir = str(settings.data_dir) if settings.data_dir else None

    def vocab():
        return load_vocabulary(data_dir)

    if settings.llm_base_url and settings.llm_model:
        from interplay.planner.llm import llm_plan
        return llm_plan(prompt, persons, seconds, settings, fallback=lambda: embedded_plan(
            prompt, persons, seconds, vocab))
    return embedded_plan(prompt, persons, seconds, vocab)


def plan_json(prompt: str, persons: int = 1, seconds: float | None = None, settings=None) -> dict:
    """`plan()` as the plain JSON the API streams (`{"type": "plan", "plan": …}`)."""
    return plan(prompt, persons, seconds, settings).to_json()
