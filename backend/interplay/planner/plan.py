"""The planner: a prompt → a Plan of timed segments, each a base motion, part edits and an
optional trajectory (CoMA's task planner, section 3 and appendix C), offline by default.

    p = plan("two people shake hands, then one walks away in a circle", persons=2, seconds=8)
    [s.prompt for s in p.segments]
      → ["two people shake hands",
         "one person walks away in a circle while the other stands still"]
    p.segments[1].persons == [1]; p.segments[1].trajectory.shape == "circle"

Steps (each change is written to `reasons`): answer a question → drop motion-irrelevant
context → rewrite known gestures and poses (lexicon) → split into clauses (temporal) →
decompose each into base + part edits (held poses as "holds …" edits over the whole step) →
nearest data phrase (MiniLM) for clauses with no known motion → who does what (two people:
exchanges with roles and timing, `pair/roles.py`) → trajectories and directions of travel →
durations by what each step needs, fitted to `seconds`.
With INTERPLAY_LLM_BASE_URL and INTERPLAY_LLM_MODEL set, `plan()` asks that model first
(`llm.py`) and comes back here on any failure.
"""

from __future__ import annotations

import math

from interplay.catalogue import grammar as g
from interplay.catalogue.load import counted_once
from interplay.catalogue.phrases import tokens, unquoted
from interplay.catalogue.words import lists, words
from interplay.planner import lexicon, questions, temporal
from interplay.planner.context import strip_context
from interplay.planner.decompose import POSTURE_BASE, Action, decompose, plain, split_subject
from interplay.planner.manner.holds import continues_hold
from interplay.planner.manner.struck import onset_poses
from interplay.planner.manner.travel import direction, untangle
from interplay.planner.pair.actors import actors as who_acts
from interplay.planner.pair.named import plain_people, plain_person
from interplay.planner.pair.roles import exchange, exchange_steps
from interplay.planner.resolve import coverage_of, not_understood, resolve
from interplay.planner.schema import MAX_REPEAT, Plan
from interplay.planner.segments import MAX_SECONDS, Step, timed
from interplay.planner.trajectory_text import parse as parse_trajectory
from interplay.planner.trajectory_text import turns_at_clock
from interplay.planner.verbs import gerund
from interplay.text.encoder import get_encoder

MAX_PROMPT = 500
IDLE = {**POSTURE_BASE, "standing": "a person stands still"}
# A clause of one person doing something to the other: its subject, and the partner after it.
ONE_SUBJECT, FIRST_SUBJECT, OTHER_PERSON = words("pair_one"), words("pair_first"), words("pair_other")
MUTUAL = words("pair_mutual")          # "… each other": both act
# Postures a step can stay in ("kneels on one knee and stays there"): words.toml's
# `posed_verbs`; part verbs hold poses.


def _without_subject(text: str) -> str:
    """The text without a leading subject the verb table did not split off ("a person picks up
    …": no known verb)."""
    subject = words("leading_subject", ignore_case=True).starts(text)
    return text[subject.end:].lstrip() if subject and text[subject.end:subject.end + 1].isspace() else text


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


def _fold_holds(clauses: list[temporal.Clause], reasons: list[str]) -> list[temporal.Clause]:
    """"raise both arms, and keep them up" / "kneel and stay there": the second clause keeps
    the first one's pose, so they are one step whose pose is held to its end."""
    out: list[temporal.Clause] = []
    for c in clauses:
        if out and continues_hold(c.text):
            verb = decompose(out[-1].text).verb
            if verb is not None and (verb.kind == "part" or verb.base in lists()["posed_verbs"]):
                out[-1].hold = c.text
                reasons.append(f"holds: '{c.text}' keeps the pose of '{out[-1].text}' to its end")
                continue
        out.append(c)
    return out


# "a tuck jump", "one squat", "a karate front kick": a count of one that the rewrite to the
# data's words ("jumps", "kicks high forward …") would drop; "jumping jacks" count nothing.
# The actions the catalogue marks `once` (`temporal` keeps their count of one), and spins
# (retrieval counts their turns).
def _one_action(text: str):
    return g.one_action_rx(counted_once() | {"spin"}).search(text)


def _says_count(text: str) -> bool:
    """A count in the words: "once", "twice", "thrice", "times" or a number (any case)."""
    return any(t.text.lower() in ("once", "twice", "thrice", "times") or t.text.isdecimal() for t in tokens(text))


def _count_of_one(action: Action, clause: str, repeat: int, reasons: list[str]) -> None:
    """Keep a count of one the words asked for (`_one_action`) as "once" on the action."""
    said = _one_action(split_subject(clause)[1])      # not the subject's "a person"
    if repeat != 1 or said is None or _says_count(action.text) or _one_action(action.text):
        return
    action.text = f"{action.text} once"
    if action.verb is None or action.verb.kind != "part":     # a kick's base is the stand
        action.base = f"{action.base} once"
    reasons.append(f"count: '{said.group(0)}' is one, kept as 'once'")


# "punches with the left fist, then the right": the same action with the other side.


def _other_side(clause, before: Action, reasons: list[str]) -> None:
    """A clause that only names a side after an action with one: that action, on this side."""
    only = clause.text.strip()
    said = next((t for t in tokens(before.text) if t.text in ("left", "right")), None)
    if not words("side_only").whole(only) or said is None:
        return
    side = next(t.text for t in tokens(only) if t.text in ("left", "right"))
    text = before.text[:said.start] + side + before.text[said.end:]
    reasons.append(f"ellipsis: '{clause.text}' is '{text}' (the action before, on the {side})")
    clause.text = text


def _stop_words(action: Action, before: Action | None) -> None:
    """"walks, then stops" → "stops walking and stands still": what stops, and what follows."""
    if action.verb is not None and action.verb.base == "stop" and action.text == "stops" and \
            before is not None and before.verb is not None and before.verb.kind == "travel":
        action.text = f"stops {gerund(before.verb.base)} and stands still"
        action.base = f"a person {action.text}"


def _travel(step: Step, reasons: list[str]) -> None:
    """The step's direction of travel; a straight path that only restates it is dropped."""
    step.travel = direction(step.action.text, step.action.verb)
    kept, metres = untangle(step.trajectory, step.travel)
    if kept is not step.trajectory:
        reasons.append(f"travel: '{step.action.text}' goes {step.travel} while facing forward "
                       "(a direction of travel, not a path to turn round for)")
    step.trajectory, step.metres = kept, metres


def _going_on(last: dict[int, tuple[str, Action]], person: int) -> str | None:
    """A person's walk or run that has no end in its words, as their role while it goes on."""
    if person not in last:
        return None
    text, action = last[person]
    ongoing = action.verb is not None and action.verb.kind == "travel" and \
        parse_trajectory(action.text) is None and not words("bounded").search(action.text)
    return text if ongoing else None


def embedded_plan(prompt: str, persons: int = 1, seconds: float | None = None,
                  vocabulary=None) -> Plan:
    """The offline plan. `vocabulary`: a callable returning a `Vocabulary` (loaded on first
    need), or None to plan without similarity."""
    _check(prompt, persons, seconds)
    reasons: list[str] = []
    text = unquoted(" ".join(prompt.replace("’", "'").replace("“", '"').replace("”", '"').split()))
    if questions.is_question(text):
        sim = (lambda q, opts: vocabulary().similar(q, opts)) if vocabulary else None
        try:
            text, why = questions.answer(text, sim)
        except Exception as exc:
            text, why = questions.answer(text, None)
            reasons.append(f"similarity unavailable ({type(exc).__name__})")
        reasons.append(why)
    for step in (strip_context, onset_poses):
        text, notes = step(text)
        reasons.extend(notes)
    if persons == 2 and vocabulary is not None:     # "a waiter … a guest": one person … the other
        text, notes = plain_people(text, get_encoder())
        reasons.extend(notes)
    elif persons == 1 and vocabulary is not None:   # "a toddler wobbles …": a person wobbles …
        text, notes = plain_person(text, get_encoder())
        reasons.extend(notes)
    text, notes, named = lexicon.rewrite_named(text)
    reasons.extend(notes)
    clauses = temporal.split(temporal.normalize(text)) or [temporal.Clause(text.lower())]
    clauses = _fold_holds(clauses, reasons)
    steps: list[Step] = []
    postures = ["standing"] * persons
    names: dict[str, int] = {}
    prev: list[int] | None = None
    last_parts: list[str] = []
    last: dict[int, tuple[str, Action]] = {}           # each person's latest role and action

    def idle_of(person: int) -> str:
        return IDLE.get(postures[person], IDLE["standing"])

    for clause in clauses:
        if clause.repeat > MAX_REPEAT:           # a count the plan cannot hold: capped, said
            reasons.append(f"count: {clause.repeat} times is more than one segment holds; "
                           f"{MAX_REPEAT} are planned")
            clause.text = clause.text.replace(f"{clause.repeat} times", f"{MAX_REPEAT} times")
            clause.repeat = MAX_REPEAT
        if steps:
            _other_side(clause, steps[-1].action, reasons)
        if steps and turns_at_clock(clause.text) and steps[-1].action.verb is not None \
                and steps[-1].action.verb.kind == "travel":     # "walks 5 m and turns right at 3 o'clock"
            before = steps[-1]
            before.action.text = f"{before.action.text} and {clause.text}"
            before.trajectory = parse_trajectory(before.action.text)
            reasons.append(f"trajectory: '{clause.text}' turns the walk before it")
            continue
        ex = exchange(clause.text, names) if persons == 2 else None
        if ex is not None:
            new = exchange_steps(ex, clause, postures, idle_of, reasons)
            steps.extend(new)
            prev = new[-1].actors
            last.update({p: (f"a person {s.action.text}", s.action) for s in new for p in s.actors})
            continue
        other = g.WHILE_THE_OTHER.search(clause.text) if persons == 2 else None
        if other:                                  # "walks while the other waves": both act
            clause.text = clause.text[:other.start()]
        probe = decompose(clause.text, "standing")
        actors = who_acts(probe.subject, persons, prev, names, clause.text)
        if persons == 2 and probe.subject is None and len(actors) == 2 and _one_to_the_other(clause.text) == 0 \
                and not MUTUAL.search(clause.text):
            actors = [0]                  # "one person hands a menu to the other person"
            reasons.append("roles: person 0 does what the words say to the other, who stands by")
        action = decompose(clause.text, postures[actors[0]], last_parts, bool(clause.hold))
        if not action.known:
            action = resolve(action, clause.text, postures[actors[0]], last_parts, vocabulary, reasons)
            if action is None:
                continue
        _stop_words(action, last.get(actors[0], (None, None))[1])
        _count_of_one(action, clause.text, clause.repeat, reasons)
        if clause.hold:                     # "raises both arms and keeps them up", "kneels … and stays"
            action.text = f"{action.text} and {clause.hold}"
            if action.verb is not None and action.verb.kind != "part":
                action.base = f"{action.base} and {clause.hold}"
        traj = parse_trajectory(action.text)
        if traj is not None and clause.group and traj.shape == "circle":
            k, n = clause.group            # one circle shared by n clauses: n arcs of it
            traj = traj.model_copy(update={"shape": "arc", "turns": round((traj.turns or 1.0) / n, 4)})
        idle = {i: idle_of(i) for i in range(persons) if i not in actors}
        active = list(actors)
        if other and len(actors) == 1:
            idle[1 - actors[0]] = "a person " + decompose(other.group(1)).text
            active = [0, 1]
        for i in [i for i in idle if not other and _going_on(last, i)]:
            idle[i] = _going_on(last, i) or idle[i]          # "…, then one stops": the other walks on
            active = sorted(set(active) | {i})
            reasons.append(f"roles: person {i} goes on with '{idle[i]}'")
        for i in actors:
            postures[i] = action.posture
            last[i] = (f"a person {action.text}", action)
        prev, last_parts = actors, list(action.edits) or last_parts
        steps.append(Step(action, clause.repeat, actors, traj, clause.group, idle, active,
                          hold=bool(clause.hold), coverage=coverage_of(action, named)))
        _travel(steps[-1], reasons)
    if not steps:                                   # nothing recognisable: keep the words
        steps = _as_written(text, clauses, persons, reasons)
    return timed(prompt, persons, seconds, steps, reasons)


def _as_written(text: str, clauses: list[temporal.Clause], persons: int, reasons: list[str]) -> list[Step]:
    """No clause had a motion the planner knows: one segment with the prompt as written, or,
    when the prompt was split into clauses ("hammer a nail, then sip a coffee"), one per clause
    in their order, each shown as the nearest captures of its own words."""
    said = [temporal.normalize(text)] if len(clauses) < 2 else [c.text for c in clauses]
    steps = []
    for words_said in said:
        action = decompose("stands still")
        action.text = plain(_without_subject(split_subject(words_said)[1]))
        action.base = f"a person {action.text}"
        who = _one_to_the_other(words_said) if persons == 2 else None
        if who is not None:          # "one person hands a menu to the other person": 0 acts
            steps.append(Step(action, 1, [who], None, None, {1 - who: IDLE["standing"]}, [who],
                              coverage=not_understood()))
            reasons.append(f"roles: person {who} does what the words say to the other, who stands by")
            continue
        steps.append(Step(action, 1, list(range(persons)), None, None, {}, list(range(persons)),
                          coverage=not_understood()))
    reasons.append("no motion recognised: one segment with the prompt as written" if len(said) == 1 else
                   f"no motion recognised: {len(said)} segments, each clause as written")
    return steps


def _one_to_the_other(text: str) -> int | None:
    """Person 0 when a clause is one person's doing to the other ("one person serves the other
    person a cup of tea"), else None (both act as written)."""
    first = ONE_SUBJECT.starts(text) or FIRST_SUBJECT.starts(text)
    return 0 if first is not None and OTHER_PERSON.search(text[first.end:]) else None


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
