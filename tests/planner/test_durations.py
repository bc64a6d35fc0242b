"""Time by what each step needs (issue 14, item 7): every action of a sequence gets the time it
needs at least, spare time goes to what can last (a free walk, a wave, a held pose), and counts
get enough time per repetition — on the eval-prompts suite's dev prompts."""

import pytest

from interplay.planner.durations import Need, fit, need
from interplay.planner.plan import embedded_plan
from interplay.planner.verbs import VERBS
from interplay.planner.vocabulary import load_vocabulary
from tests.planner.suite import plan_of


def _plan(prompt, seconds):
    return embedded_plan(prompt, 1, seconds, load_vocabulary)


def _verb(seg):
    return next(w for w in seg.prompt.split()[2:])


@pytest.mark.parametrize("prompt_id,least", [
    ("sequences-05", {"walks": 1.5, "waves": 1.5}),               # walk a few steps and wave
    ("sequences-07", {"walks": 2.0, "stops": 1.5, "jumps": 1.2}),  # walk, stop, then jump
    ("sequences-11", {"squats": 1.5, "stands": 1.5, "walks": 2.0}),  # squat down, stand up, walk away
    ("sequences-01", {"walks": 2.0, "sits": 1.8}),                # walk forward, then sit down
    ("down_up-07", {"sits": 1.8, "stands": 1.5}),                 # sit down, then stand back up
])
def test_each_action_of_a_sequence_gets_the_time_it_needs(prompt_id, least):
    p = plan_of(prompt_id)
    got = {_verb(s): s.seconds for s in p.segments}
    assert list(got) == list(least), [s.prompt for s in p.segments]
    for verb, seconds in least.items():
        assert got[verb] >= seconds - 0.05, (verb, got)


def test_a_few_steps_are_a_few_steps_and_the_wave_takes_the_rest():
    walk, wave = plan_of("sequences-05").segments
    assert walk.seconds < 3.0 < wave.seconds


def test_a_sprint_keeps_its_time_beside_a_long_walk():
    # proportional scaling gave a sprint barely more than a second next to long walks
    for prompt in ("walk in a circle, then sprint", "walk 10 metres, then sprint, then sit down"):
        segs = _plan(prompt, 8.0).segments
        sprint = next(s for s in segs if "sprints" in s.prompt)
        assert sprint.seconds >= 2.4, [(s.prompt, s.seconds) for s in segs]


def test_counts_get_enough_time_per_repetition():
    jumps, sit = _plan("jump three times, then sit down", 6.0).segments
    assert jumps.repeat == 3 and jumps.seconds >= 3 * 1.2 and sit.seconds >= 1.8
    (thrice,) = plan_of("counts-01").segments                      # jump three times, 6 s
    assert thrice.repeat == 3 and thrice.seconds == 6.0


def test_need_and_fit():
    assert need(VERBS["jump"], repeat=3) == Need(6.0, pytest.approx(3.6), False)
    assert need(VERBS["walk"]).elastic and not need(VERBS["walk"], text="walks a few steps").elastic
    assert need(VERBS["stand"], text="stands up").elastic is False
    walk, jump = need(VERBS["walk"]), need(VERBS["jump"])
    assert fit([walk, jump], 160) == [120, 40]          # spare time to the free walk
    assert fit([walk, jump], 80) == [51, 29]            # least + a share of the rest
    assert sum(fit([walk, jump, jump], 30)) == 30       # less than they need: in proportion


@pytest.mark.parametrize("prompt", ["a couple dances salsa and the man twirls the woman",
                                    "they dance salsa and she turns under his arm"])
def test_a_partner_spun_under_an_arm_gets_the_time_a_captured_one_takes(prompt):
    plan = embedded_plan(prompt, 2, 6.0, load_vocabulary)
    assert len(plan.segments) == 2
    assert plan.segments[1].seconds >= 2.5, [(s.prompt, s.seconds) for s in plan.segments]
