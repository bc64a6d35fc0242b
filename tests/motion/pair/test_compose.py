"""Composed two-person clips from the real single-person clips of the processed set, checked
with the project's own metrics (interplay.motion.metrics) and sphere body."""

import numpy as np
import pytest

from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips
from interplay.motion.kinematics import facing_angle
from interplay.motion.metrics import clip_metrics, frame_highlights
from interplay.motion.pair import compose as C
from interplay.motion.pair import placement as pl
from interplay.motion.pair.bases import NOT_AHEAD, standing_bases, walk_bases
from interplay.motion.pair.body import body_spheres, surface_gaps

N = 8        # samples per kind (seeds 0 … N-1)


@pytest.fixture(scope="module")
def real():
    return [c for c in default_clips() if not c.synthetic]


@pytest.fixture(scope="module")
def pool(real):
    return C.pool_of(real, "train")


@pytest.fixture(scope="module")
def composed(pool):
    return {k: [C.compose(k, s, pool=pool) for s in range(N)] for k in C.KINDS}


def _people(clip):
    return [p.astype(np.float64) for p in clip.people]


def _contact_share(clip) -> float:
    """Smallest share, over the clip's contact hands, of window frames where that hand
    touches the other person (frame_highlights)."""
    ct = clip.meta["contact"]
    hl = frame_highlights(_people(clip))["contacts"]
    shares = []
    for person, hand in ct["hands"]:
        j = sk.JOINT_INDEX[hand]
        shares.append(np.mean([[person, j] in hl[f] for f in range(ct["start"], ct["end"])]))
    return float(min(shares))


def _torso_overlap(clip) -> np.ndarray:
    """(T,) bool: some non-arm sphere of one person overlaps a non-arm sphere of the other."""
    a, b = (body_spheres(p) for p in _people(clip))
    keep = ~pl.ARM_SPHERES
    return (surface_gaps(a, b)[:, keep][:, :, keep] < 0).any(axis=(1, 2))


@pytest.mark.parametrize("kind", ["handshake", "high_five", "hug", "push"])
def test_contact_kinds_touch_in_their_window(composed, kind):
    shares = [_contact_share(c) for c in composed[kind]]
    assert np.mean(np.array(shares) >= 0.8) >= 0.8, shares


@pytest.mark.parametrize("kind", ["handshake", "high_five"])
def test_hands_are_apart_before_the_reach(composed, kind):
    wrists = (sk.LEFT_HAND, sk.RIGHT_HAND)
    for c in composed[kind]:
        ct = c.meta["contact"]
        before = ct["start"] - ct["ramp_in"]
        assert before > 0
        contacts = frame_highlights([p[:before] for p in _people(c)])["contacts"]
        assert not any(j in wrists for f in contacts for _, j in f), c.id


def test_bodies_do_not_interpenetrate_and_bones_keep_their_length(composed):
    for _kind, clips in composed.items():
        for c in clips:
            assert _torso_overlap(c).mean() <= 0.05, (c.id, _torso_overlap(c).mean())
            for p, off in zip(_people(c), c.offsets):
                want = np.linalg.norm(off[1:], axis=-1)
                assert np.abs(sk.bone_lengths(p) - want).max() < 1e-4, c.id
            m = clip_metrics(_people(c))
            assert m["ground_penetration"] < 0.02 and m["bone_deviation"] < 1e-4, (c.id, m)


def test_clips_are_labelled_synthetic_with_meta(composed, real):
    split_of = {c.id: c.split for c in real}
    for kind, clips in composed.items():
        for c in clips:
            assert c.synthetic and c.source == "composed" and c.split == "train"
            assert c.frames == 80 and len(c.people) == 2 and c.prompt.startswith(("two", "one", "a "))
            assert c.meta["kind"] == kind and len(c.meta["bases"]) == 2
            assert all(split_of[b["clip"]] == "train" for b in c.meta["bases"])
            assert ("HDM05" in c.licence) == any("HDM05" in b["licence"] for b in c.meta["bases"])
            # Canonical frame: the first person starts at the origin facing +Z.
            p0 = c.people[0][0].astype(np.float64)
            assert np.abs(p0[sk.PELVIS, [0, 2]]).max() < 1e-3 and abs(facing_angle(p0)) < 1e-3


def test_same_seed_same_clip_and_seeds_differ(pool):
    a, b = C.compose("hug", 3, pool=pool), C.compose("hug", 3, pool=pool)
    for x, y in zip(a.people, b.people):
        np.testing.assert_array_equal(x, y)
    c = C.compose("hug", 4, pool=pool)
    assert not np.array_equal(a.people[0], c.people[0])


def test_face_to_face_kinds_face_each_other(composed):
    for kind in ("handshake", "high_five", "hug", "push", "wave"):
        for c in composed[kind]:
            a, b = _people(c)
            dyaw = np.angle(np.exp(1j * (facing_angle(b) - facing_angle(a))))
            assert np.median(np.abs(dyaw)) > np.radians(150), c.id


def test_push_moves_the_partner_back_with_feet_planted(composed):
    for c in composed["push"]:
        a, b = _people(c)
        ct = c.meta["contact"]
        gap = np.linalg.norm((b[:, sk.PELVIS] - a[:, sk.PELVIS])[:, [0, 2]], axis=1)
        pushed = gap[-1] - gap[ct["start"]]
        assert pushed > 0.5 * c.meta["placement"]["push_distance"], (c.id, pushed)
        m = clip_metrics([b])
        assert m["skating_ratio"] < 0.05, (c.id, m)


def test_wave_waves_without_contact(composed):
    for c in composed["wave"]:
        people = _people(c)
        assert clip_metrics(people)["contact_frames"] == 0
        for w in c.meta["placement"]["waves"]:
            p = people[w["person"]]
            side = w["hand"].split("_")[0]
            hand, shoulder = p[:, sk.JOINT_INDEX[w["hand"]]], p[:, sk.JOINT_INDEX[f"{side}_shoulder"]]
            win = slice(w["start"], w["end"])
            assert np.all(hand[win, 1] > shoulder[win, 1])                 # raised
            lateral = hand[win] - shoulder[win]
            assert np.ptp(lateral[:, [0, 2]], axis=0).max() > 0.12         # swinging sideways


def test_walks_side_by_side_share_heading_and_speed(composed):
    held = []
    for c in composed["walk_side_by_side"]:
        a, b = _people(c)
        va, vb = (np.linalg.norm((p[-1, sk.PELVIS] - p[0, sk.PELVIS])[[0, 2]]) for p in (a, b))
        assert abs(va - vb) / va < 0.15, c.id
        dyaw = np.angle(np.exp(1j * (facing_angle(b) - facing_angle(a))))
        assert np.median(np.abs(dyaw)) < np.radians(25), c.id
        lateral = np.abs(b[:, sk.PELVIS, 0] - a[:, sk.PELVIS, 0])
        assert 0.45 < np.median(lateral) < 1.2, c.id
        if c.meta["placement"]["held"]:
            held.append(_contact_share(c))
            assert "holding hands" in c.prompt
    assert held and np.mean(np.array(held) >= 0.8) >= 0.5


def test_walk_bases_are_walks_ahead(real):
    bases = walk_bases(real)
    assert bases and not any(w in b.clip.prompt for b in bases for w in NOT_AHEAD)
    # Bandai Namco's backward, diagonal and turning walks are there, and none is a base.
    assert any("backwards" in c.prompt for c in real) and all("backwards" not in b.clip.prompt for b in bases)


def test_compose_set_skips_kinds_without_bases_and_checks_input(real):
    walks_only = [c for c in real if "walk" in c.prompt and c.split == "train"
                  and not standing_bases([c]) and walk_bases([c])][:4]
    got = C.compose_set(2, 0, clips=walks_only)
    assert {c.meta["kind"] for c in got} <= {"walk_side_by_side"} and len(got) == 2
    with pytest.raises(ValueError):
        C.compose("juggle", 0, clips=walks_only)
    with pytest.raises(ValueError):
        C.compose("hug", 0, clips=walks_only)
