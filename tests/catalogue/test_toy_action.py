"""Adding an action is one catalogue entry: a toy pose and a toy counted verb, added to a
temporary copy of the catalogue, are planned, generated (by an existing family and the IK's
poses), reviewed with the checks their entries name, and pass them on the motion, with no code
changed."""

from __future__ import annotations

import pytest

from interplay.catalogue.load import PATH, catalogue, use_catalogue
from interplay.generators.base import Request
from interplay.motion.checks.named import run_check
from interplay.pipeline.orchestrator import asked_of, orchestrate
from interplay.planner.plan import plan

TOY = '''
[[action]]
name = "starfish"
kind = "pose"
descriptions = ["a person stands with both arms stretched out to the sides like a starfish"]
names = ["starfish"]
text = "raises both arms out to the sides"
hold = "with both arms stretched out to the sides"
[[action.checks]]
check = "pose_held"
pose = "t_pose"

[[action]]
name = "boing"
kind = "whole"
descriptions = ["a person bounces up into the air and lands"]
seconds = 1.2
ends_in = "standing"
counts = true
counts_as = "jump"
made_by = { families = ["jump"] }
[[action.checks]]
check = "jump_count"
count = "{count}"
'''


@pytest.fixture(scope="module")
def toy(tmp_path_factory):
    path = tmp_path_factory.mktemp("catalogue") / "actions.toml"
    text = PATH.read_text(encoding="utf-8")
    head, words = text.split("\n[words]", 1)           # entries before the [words] table
    path.write_text(head + TOY + "\n[words]" + words, encoding="utf-8")
    use_catalogue(path)
    try:
        yield catalogue()
    finally:
        use_catalogue(None)


@pytest.fixture(scope="module")
def router():
    from interplay.generators.router import load_generator
    return load_generator()


def _run(router, prompt: str, seconds: float, seed: int):
    events: list[dict] = []
    out = orchestrate(router, Request(prompt, 1, seconds, seed), events.append, lambda a, p: None)
    return out, events


def test_unknown_before_the_entry(router):
    p = plan("a person boings three times", seconds=6)
    assert p.segments[0].coverage.how == "nearest"
    assert catalogue().get("boing") is None


def test_a_toy_pose_is_planned_generated_reviewed_and_checked(toy, router):
    p = plan("a person holds the starfish", seconds=4)
    seg = p.segments[0]
    assert "arms stretched out to the sides" in seg.prompt and seg.coverage.entry == "starfish"
    out, events = _run(router, "a person holds the starfish", 4, 3)
    gseg = out.plan.segments[0]
    asked = asked_of(gseg)
    assert {"check": "pose_held", "pose": "t_pose"} in asked
    assert all(run_check(out.people, spec).passed for spec in asked if spec["check"] == "pose_held")
    assert any(e["type"] == "review" for e in events)


def test_a_toy_counted_verb_is_counted_by_its_family(toy, router):
    p = plan("a person boings three times", seconds=6)
    seg = p.segments[0]
    assert seg.coverage.entry == "boing" and seg.coverage.how == "capture"
    out, _ = _run(router, "a person boings three times", 6, 2)
    asked = asked_of(out.plan.segments[0])
    assert {"check": "jump_count", "count": 3} in asked
    assert run_check(out.people, {"check": "jump_count", "count": 3}).passed
