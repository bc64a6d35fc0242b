"""The plausibility checks every benchmark output gets, on real captures (which must pass)
and on the same captures broken the way generators break them (which must fail)."""

from __future__ import annotations

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.checks import measures as M
from interplay.motion.checks import named as N
from interplay.motion.clip import default_clips

LEVEL = {"hdm05": ("squat1Reps", "hopBothLegs1hops", "jogLeftCircle4StepsRstart",
                   "grabHighR", "sneak2StepsLStart", "rotateArmsBothBackward1Reps"),
         "cmu-bvh": ("jump", "forward jump", "run")}


def level_captures():
    """Captures on a level floor. Left out: CMU's uneven-terrain trials and its walks on tilted
    floors (they rise 5–8 cm over a few metres, so on the studio's level floor they float), and
    HDM05's front kicks and lie-downs (standing, their feet's joints sit 6–16 cm up in the
    processed data: the clip's floor was taken under its lowest frames)."""
    return [c for c in default_clips() if len(c.people) == 1 and c.label in LEVEL.get(c.source, ())]


def check(fn, j):
    j = np.asarray(j, np.float64)
    return fn(j, M.frame_of(j))[0]


def test_real_level_captures_pass_pops_and_ground():
    caps = level_captures()
    assert len(caps) > 100
    pops = [check(N.no_pops, c.people[0]) for c in caps]
    ground = [check(N.grounded, c.people[0]) for c in caps]
    assert np.mean(pops) == 1.0
    assert np.mean(ground) >= 0.95, [c.id for c, g in zip(caps, ground) if not g]


def test_a_captured_run_is_no_pop_though_it_moves_17_cm_a_frame():
    for c in [c for c in default_clips() if c.source == "cmu-bvh" and c.label == "run"]:
        step = np.linalg.norm(np.diff(c.people[0][:, sk.PELVIS], axis=0), axis=1)
        assert step.max() > 0.10
        assert check(N.no_pops, c.people[0])


def test_a_cut_in_the_pelvis_is_a_pop():
    j = next(c for c in default_clips() if c.label == "squat1Reps").people[0].astype(np.float64)
    cut = j.copy()
    cut[12:] += np.array([0.15, 0.0, 0.0])                  # the body jumps 15 cm at frame 12
    assert not check(N.no_pops, cut)
    first = j.copy()
    first[0] += np.array([0.0, 0.41, 0.0])                  # a 41 cm jump on the first frame
    assert not check(N.no_pops, first)
    last = j.copy()
    last[-1] += np.array([0.0, 0.0, 0.2])
    assert not check(N.no_pops, last)
    assert M.pelvis_pops(cut)[12] == np.float64(M.pelvis_pops(cut).max())


def test_floating_and_sinking_bodies_fail_and_a_real_jump_does_not():
    j = next(c for c in default_clips() if c.label == "squat1Reps").people[0].astype(np.float64)
    up, down, brief = j.copy(), j.copy(), j.copy()
    up[5:17, :, 1] += 0.10                                  # 10 cm up for 0.6 s
    down[5:17, :, 1] -= 0.10
    brief[5:10, :, 1] += 0.10                               # 0.25 s: under the bound
    assert not check(N.grounded, up)
    assert not check(N.grounded, down)
    assert check(N.grounded, brief)
    for c in [c for c in default_clips() if c.source == "cmu-bvh" and c.label == "jump"]:
        assert check(N.grounded, c.people[0])               # flight is not floating
    lie = next(c for c in default_clips() if c.label == "lieDownFloor").people[0]
    assert check(N.grounded, lie[-40:])                     # lying on the floor is on it
    assert not check(N.grounded, np.asarray(lie[-40:], np.float64) - np.array([0, 0.1, 0]))


def test_starts_standing_unless_the_prompt_starts_elsewhere():
    lie = next(c for c in default_clips() if c.label == "lieDownFloor").people[0].astype(np.float64)
    names = lambda res: {r.check: r.passed for r in res}   # noqa: E731
    assert names(N.plausibility([lie]))["starts_standing"]
    back = lie[::-1].copy()
    assert not names(N.plausibility([back]))["starts_standing"]
    assert names(N.plausibility([back], start="lying"))["starts_lying"]
    assert "starts_standing" not in names(N.plausibility([back], start="any"))


def test_real_salsa_passes_no_interpenetration_at_its_real_rate():
    salsa = [c for c in default_clips() if c.source == "cmu-salsa"]
    assert len(salsa) >= 10
    rates = [float(M.body_overlap(*c.people, N.OVERLAP_DEPTH_M, touching=True).mean()) for c in salsa]
    assert max(rates) <= N.OVERLAP_SHARE, rates             # captured: 0–6 % of frames
    assert all(N.no_interpenetration(*c.people, contact=True)[0] for c in salsa)
    # Counting the forearms that hold the partner, some captured pairs would "interpenetrate".
    with_arms = [float(M.body_overlap(*c.people, N.OVERLAP_DEPTH_M).mean()) for c in salsa]
    assert max(with_arms) > N.OVERLAP_SHARE


def test_a_partner_standing_inside_the_other_fails():
    a, b = next(c for c in default_clips() if c.source == "cmu-salsa").people
    inside = np.asarray(a, np.float64) + np.array([0.1, 0.0, 0.05])
    assert not N.no_interpenetration(a, inside, contact=True)[0]
    walks = [c for c in default_clips() if c.meta.get("kind") == "walk_side_by_side"]
    ok = [N.no_interpenetration(*c.people)[0] for c in walks]
    assert np.mean(ok) >= 0.9
    a, b = walks[0].people
    assert not N.no_interpenetration(a, np.asarray(a) + np.array([0.15, 0, 0]))[0]
