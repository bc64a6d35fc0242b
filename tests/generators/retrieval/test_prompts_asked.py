"""Retrieval does what the words ask beyond the nearest captures, on real prompts over the real
processed captures, judged by the benchmark's own checks (`interplay eval-prompts`, dev split
prompts and a few more of the same kinds): directions of travel, the named side, exact counts,
postures at the start and the end. Several seeds each."""

import numpy as np
import pytest

from interplay.generators.base import Request
from interplay.generators.router import load_generator
from interplay.motion.checks.named import plausibility, run_check

SEEDS = (0, 1, 2)
ASKED = [
    # prompt, seconds, the checks that must pass, the posture it starts in
    ("walk backwards", 6, [{"check": "travel_direction", "direction": "backward", "min_m": 1.0}], "standing"),
    ("run backwards", 5, [{"check": "travel_direction", "direction": "backward", "min_m": 2.0}], "standing"),
    ("step sideways to the left", 5, [{"check": "travel_direction", "direction": "left"}], "any"),
    ("side-step to the right", 5, [{"check": "travel_direction", "direction": "right"}], "any"),
    ("kick with the right leg", 4, [{"check": "kick", "leg": "right", "at_least": 1}], "standing"),
    ("kick twice with your right leg", 6, [{"check": "kick", "leg": "right", "count": 2}], "standing"),
    ("kick once with the left foot", 4, [{"check": "kick", "leg": "left", "count": 1}], "standing"),
    ("punch with the left fist", 4, [{"check": "punch", "hand": "left", "at_least": 1}], "standing"),
    ("jump three times", 6, [{"check": "jump_count", "count": 3}], "standing"),
    ("jump twice", 5, [{"check": "jump_count", "count": 2}], "standing"),
    ("squat twice", 6, [{"check": "squat_count", "count": 2}], "standing"),
    ("take three steps forward", 5, [{"check": "step_count", "count": 3},
                                     {"check": "travel_direction", "direction": "forward"}], "standing"),
    ("get up from lying on the floor", 6, [{"check": "posture_at_start", "posture": "lying"},
                                           {"check": "posture_at_end", "posture": "standing"}], "lying"),
    ("stand up from sitting on the floor", 6, [{"check": "posture_at_start", "posture": "sitting"},
                                               {"check": "posture_at_end", "posture": "standing"}], "sitting"),
    ("sit down on the ground", 6, [{"check": "posture_at_end", "posture": "sitting"}], "standing"),
    ("sit down, then stand back up", 8, [{"check": "sequence", "steps": ["sit", "stand"]},
                                         {"check": "posture_at_end", "posture": "standing"}], "standing"),
    ("shuffle along like a tired old man", 6, [{"check": "speed_band", "band": "slow"}], "any"),
    ("jog forward", 6, [{"check": "speed_band", "band": "jog"}], "any"),
    ("sprint as fast as you can", 5, [{"check": "speed_band", "band": "sprint"}], "any"),
    ("turn to the left", 4, [{"check": "turn", "degrees": 90, "direction": "left"}], "standing"),
    ("walk forward, then stop and stand still", 7, [{"check": "sequence", "steps": ["walk", "stop"]}],
     "standing"),
    ("jump on the spot", 4, [{"check": "jump_count", "at_least": 1}, {"check": "stays_in_place"}], "standing"),
    ("lie down, then sit up", 9, [{"check": "sequence", "steps": ["lie", "sit"]},
                                  {"check": "posture_at_end", "posture": "sitting"}], "standing"),
]


@pytest.fixture(scope="module")
def gen():
    return load_generator(use_spam=False)


@pytest.mark.parametrize("prompt,seconds,checks,start", ASKED, ids=[a[0] for a in ASKED])
def test_the_motion_does_what_the_prompt_asks(gen, prompt, seconds, checks, start):
    for seed in SEEDS:
        m = gen.generate(Request(prompt, 1, float(seconds), seed=seed))
        (joints,) = m.people
        assert joints.shape == (round(seconds * 20), 22, 3)
        for spec in checks:
            r = run_check([joints], spec)
            assert r.passed, (seed, spec, r.value, m.plan["segments"][0]["retrieval"])
        if start != "any":      # it starts where it is asked to (standing unless said)
            first = next(p for p in plausibility([joints], start=start) if p.check.startswith("starts_"))
            assert first.passed, (seed, first)


def test_a_sprint_says_how_fast_the_captures_go(gen):
    m = gen.generate(Request("sprint as fast as you can", 1, 5.0, seed=0))
    assert any(r.startswith("speed: segment 0 asks for a sprint") and "4 m/s" in r
               for r in m.plan["reasons"])


def test_backwards_keeps_facing_forward(gen):
    from interplay.motion.kinematics import facing_direction
    for seed in SEEDS:
        (joints,) = gen.generate(Request("walk backwards", 1, 6.0, seed=seed)).people
        face = facing_direction(joints)[:, [0, 2]].mean(axis=0)
        went = joints[-1, 0, [0, 2]] - joints[0, 0, [0, 2]]
        assert np.linalg.norm(went) >= 1.0 and went @ face < -0.8 * np.linalg.norm(went) * np.linalg.norm(face)


def test_a_posture_reached_is_held_to_the_end(gen):
    m = gen.generate(Request("sit down on the ground", 1, 6.0, seed=0))
    (track,) = m.plan["segments"][0]["retrieval"]["tracks"]
    played = sum(p["end"] - p["start"] for p in track)
    assert played < 120                                   # the rest is the seated pose, held
    tail = m.people[0][played:]
    assert np.abs(tail - tail[:1]).max() < 1e-6


def test_a_counted_segment_continues_in_the_next_one(gen):
    m = gen.generate(Request("jump twice, then walk forward", 1, 10.0, seed=0))
    (joints,) = m.people
    assert len(m.plan["segments"]) == 2
    assert run_check([joints], {"check": "sequence", "steps": [{"event": "jump", "count": 2}, "walk"]}).passed
    pops = next(p for p in plausibility([joints]) if p.check == "no_pops")
    assert pops.passed, pops.value


@pytest.mark.parametrize("prompt", ["run", "dance around happily", "jog across the room",
                                    "walk slowly"])
def test_a_motion_that_asks_nothing_more_still_starts_standing(gen, prompt):
    # captured runs, dances and boxing start mid-stride or mid-step; the first segment is
    # drawn again until its first frame stands (issue 14: a start from standing). Not yet:
    # "shadow box on the spot" (every captured bout starts in a crouched guard), "sprint"
    # (the captured sprints start mid-run)
    for seed in SEEDS:
        (joints,) = gen.generate(Request(prompt, 1, 5.0, seed=seed)).people
        first = next(p for p in plausibility([joints]) if p.check == "starts_standing")
        assert first.passed, (prompt, seed)
