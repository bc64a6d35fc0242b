import json

import numpy as np
import pytest

from interplay.motion.clip import default_clips
from interplay.motion.motion import Motion


@pytest.fixture(scope="module")
def salsa() -> list[np.ndarray]:
    """Both dancers of a real two-person capture (first 2 s)."""
    clip = next(c for c in default_clips() if len(c.people) == 2)
    return [p[:40] for p in clip.people]


def test_json_round_trip_keeps_joints_to_a_tenth_of_a_millimetre(salsa):
    m = Motion(people=salsa, plan={"segments": []}, metrics={"foot_skating": 0.1},
               highlights={"contacts": []}, prompt="two people dance salsa", seed=7)
    d = json.loads(json.dumps(m.to_json()))
    assert d["fps"] == 20 and d["skeleton"] == "smpl22"
    assert len(d["people"]) == 2 and np.asarray(d["people"][0]["joints"]).shape == (40, 22, 3)
    assert d["plan"] == {"segments": []} and d["metrics"] == {"foot_skating": 0.1}
    back = Motion.from_json(d)
    assert back.prompt == m.prompt and back.seed == 7 and back.highlights == {"contacts": []}
    for a, b in zip(back.people, salsa):
        assert a.dtype == np.float32 and a.shape == b.shape
        assert np.abs(a - b).max() <= 0.5e-4 + 1e-6
    # Rounded: no value carries more than 4 decimals.
    flat = np.asarray(d["people"][1]["joints"]).ravel()
    np.testing.assert_allclose(flat, np.round(flat, 4), atol=1e-12)


def test_minimal_json_loads_with_defaults(salsa):
    m = Motion.from_json({"people": [{"joints": salsa[0].tolist()}]})
    assert m.frames == 40 and m.fps == 20 and m.plan == {} and m.metrics == {} and m.seed is None
    assert "highlights" not in m.to_json() and "seed" not in m.to_json()


def _bad(salsa, kind):
    a = salsa[0].tolist()
    if kind == "joints":
        return {"people": [{"joints": [f[:21] for f in a]}]}
    if kind == "ragged":
        return {"people": [{"joints": a[:5] + [a[5][:-1]] + a[6:]}]}
    if kind == "nan":
        a[3][4][1] = float("nan")
        return {"people": [{"joints": a}]}
    if kind == "none":
        return {"people": []}
    if kind == "three":
        return {"people": [{"joints": a}] * 3}
    if kind == "lengths":
        return {"people": [{"joints": a}, {"joints": a[:-1]}]}
    if kind == "no_joints":
        return {"people": [{"pose": a}]}
    if kind == "fps":
        return {"fps": 30, "people": [{"joints": a}]}
    if kind == "skeleton":
        return {"skeleton": "h36m", "people": [{"joints": a}]}
    if kind == "empty":
        return {"people": [{"joints": []}]}
    raise AssertionError(kind)


@pytest.mark.parametrize("kind", ["joints", "ragged", "nan", "none", "three", "lengths", "no_joints",
                                  "fps", "skeleton", "empty"])
def test_malformed_json_raises_value_error(salsa, kind):
    with pytest.raises(ValueError):
        Motion.from_json(_bad(salsa, kind))


def test_constructor_validates_people(salsa):
    with pytest.raises(ValueError, match="1 or 2 people"):
        Motion(people=[])
    with pytest.raises(ValueError, match="different lengths"):
        Motion(people=[salsa[0], salsa[1][:-3]])


# --- Version 2: the skeleton and each person's rig beside the joints ------------------------

def test_version_2_carries_the_skeleton_and_round_trips(salsa):
    from interplay.motion import skeleton as sk
    from interplay.motion.kinematics import fit_to_skeleton
    from interplay.motion.rig import rig_from_json, rig_positions
    people = [fit_to_skeleton(p.astype(np.float64))[0] for p in salsa]   # on fixed bones
    m = Motion(people=people, prompt="two people dance salsa", seed=3)
    d = json.loads(json.dumps(m.to_json(rig=True)))
    assert d["schema"] == "interplay.motion/2"
    assert d["joint_names"] == list(sk.JOINT_NAMES) and d["parents"] == list(sk.PARENTS)
    assert "quaternion" in d["rig_convention"] and "(w, x, y, z)" in d["rig_convention"]
    for person, joints in zip(d["people"], people):
        rig = rig_from_json(person)
        assert rig.offsets.shape == (22, 3) and rig.root.shape == (40, 3)
        assert rig.rotations.shape == (40, 22, 4)
        np.testing.assert_allclose(np.linalg.norm(np.asarray(person["rig"]["rotations"]), axis=-1),
                                   1.0, atol=5e-6)
        # The positions from the rotations are the joints (and the joints in the file).
        assert np.abs(rig_positions(rig) - joints).max() < 1e-4
        assert np.abs(rig_positions(rig) - np.asarray(person["joints"])).max() < 1e-3
    back = Motion.from_json(d)                                  # version 2 reads back …
    for a, b in zip(back.people, people):
        assert np.abs(a - b).max() <= 0.5e-4 + 1e-6
    assert back.prompt == m.prompt and back.seed == 3
    v1 = json.loads(json.dumps(m.to_json()))                   # … and version 1 still does
    assert "schema" not in v1 and "rig" not in v1["people"][0]
    assert all(np.array_equal(a, b) for a, b in zip(Motion.from_json(v1).people, back.people))


def test_version_2_problems_are_named(salsa):
    from interplay.motion.rig import rig_from_json
    d = Motion(people=[salsa[0]]).to_json(rig=True)
    with pytest.raises(ValueError, match="schema"):
        Motion.from_json({**d, "schema": "interplay.motion/9"})
    with pytest.raises(ValueError, match="'rig'"):
        Motion.from_json({**d, "people": [{"joints": d["people"][0]["joints"]}]})
    with pytest.raises(ValueError, match="no 'rig'"):
        rig_from_json({"joints": []})
    bad = {"rig": {**d["people"][0]["rig"], "rotations": [[1, 0, 0, 0]]}}
    with pytest.raises(ValueError, match="shapes"):
        rig_from_json(bad)
