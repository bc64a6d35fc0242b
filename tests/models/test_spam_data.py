"""SPAM training data (mirroring, per-person texts, part prompts) and the geometric losses, on
real clips of the processed set."""

from __future__ import annotations

import numpy as np
import pytest

torch = pytest.importorskip("torch")

from interplay.motion import skeleton as sk  # noqa: E402
from interplay.motion.clip import Caption, default_clips  # noqa: E402
from interplay.motion.features import SLICES, decode, encode  # noqa: E402
from interplay.motion.metrics import centre_of_mass  # noqa: E402
from models.spam.config import LossConfig  # noqa: E402
from models.spam.data import (  # noqa: E402
    Track,
    build_tracks,
    fit_normalizer,
    mirror_joints,
    mirror_text,
    part_texts,
    person_captions,
    person_prompt,
)
from models.spam.losses import COM_WEIGHTS, MotionLoss, fk_joints  # noqa: E402


def _clip(prompt_part: str):
    return next(c for c in default_clips()
                if prompt_part in c.prompt and not c.synthetic and c.split == "train")


def test_mirror_is_an_involution_and_swaps_sides():
    clip = _clip("kicks forward with the left foot")
    j = clip.people[0]
    m = mirror_joints(j)
    np.testing.assert_allclose(mirror_joints(m), j, atol=1e-6)
    # the left foot of the mirror image is where the right foot was, reflected
    np.testing.assert_allclose(m[:, sk.LEFT_FOOT, 0], -j[:, sk.RIGHT_FOOT, 0], atol=1e-6)
    # the kicking (fastest) foot switches sides
    speed = lambda x, k: np.abs(np.diff(x[:, k, 2])).sum()  # noqa: E731
    assert (speed(j, sk.LEFT_FOOT) > speed(j, sk.RIGHT_FOOT)) == \
           (speed(m, sk.RIGHT_FOOT) > speed(m, sk.LEFT_FOOT))
    assert mirror_text("kicks with the Left foot, then right") == \
           "kicks with the Right foot, then left"
    assert mirror_text("brightly lit") == "brightly lit"


def test_mirrored_track_decodes_to_the_mirrored_motion():
    clip = _clip("kicks forward with the left foot")
    tracks = build_tracks([clip])
    assert [t.mirrored for t in tracks] == [False, True]
    plain, mirrored = tracks
    assert mirrored.prompt == "a person kicks forward with the right foot"
    assert {c.part for c in mirrored.captions} == {c.part for c in plain.captions}
    for a, b in zip(plain.captions, mirrored.captions):
        assert (a.part.startswith("left") and b.part.startswith("right")) or \
               (a.part.startswith("right") and b.part.startswith("left")) or a.part == b.part
    back = decode(mirrored.features, mirrored.offsets)
    want = mirror_joints(clip.people[0])
    want_rel = want - want[:1, :1] * np.array([1, 0, 1])
    back_rel = back - back[:1, :1] * np.array([1, 0, 1])
    assert np.abs(back_rel - want_rel).max() < 0.05   # heading/start differ only by float error


def test_salsa_tracks_are_single_person_with_their_own_captions():
    clip = next(c for c in default_clips() if c.source == "cmu-salsa")
    assert person_prompt(clip.prompt, 2) == "a person dances salsa"
    for i in range(2):
        caps = person_captions(clip.captions, i)
        assert caps and not any(c.text.startswith("person ") for c in caps)
    n0 = len(person_captions(clip.captions, 0))
    n1 = len(person_captions(clip.captions, 1))
    assert n0 + n1 == len(clip.captions)


def test_part_texts_take_the_caption_covering_most_of_the_window():
    t = Track(np.zeros((100, 239), np.float32), np.zeros((22, 3), np.float32), "a person waves",
              [Caption(0, 30, "left_upper", "the left arm rests"),
               Caption(30, 100, "left_upper", "the left arm waves"),
               Caption(0, 100, "body", "the person stands")])
    assert part_texts(t, 0, 40, False) == ["a person waves"] * 4
    assert part_texts(t, 0, 40, True) == ["the left arm rests"] + ["a person waves"] * 3
    assert part_texts(t, 20, 80, True)[0] == "the left arm waves"


def test_com_weights_reproduce_the_metric():
    j = _clip("squats").people[0][:30].astype(np.float64)
    np.testing.assert_allclose(np.einsum("j,tjd->td", COM_WEIGHTS, j), centre_of_mass(j),
                               atol=1e-9)
    assert COM_WEIGHTS.sum() == pytest.approx(1.0)


def test_geometric_losses_vanish_at_the_target_and_grow_with_error():
    clip = _clip("walks forward")
    feats = encode(clip.people[0][:64], clip.offsets[0])
    norm = fit_normalizer(build_tracks([clip]))
    x = torch.from_numpy(norm.normalize(feats))[None]
    crit = MotionLoss(LossConfig(), norm)
    same = crit(x, x, torch.zeros(()), 0.02)
    for k in ("recon", "velocity", "bone", "com", "ktraj", "fk"):
        assert float(same[k]) < 1e-5, k
    # joints from the features are root-relative: the pelvis sits at (0, h, 0)
    j = crit.joints(x * crit.std + crit.mean)
    assert torch.allclose(j[0, :, 0, [0, 2]], torch.zeros(len(feats), 2))
    np.testing.assert_allclose(j[0, :, 0, 1].numpy(), feats[:, SLICES["root_height"]][:, 0],
                               atol=1e-5)
    noisy = x + 0.3 * torch.randn_like(x)
    worse = crit(noisy, x, torch.zeros(()), 0.02)
    for k in ("recon", "velocity", "bone", "ktraj", "foot", "fk"):
        assert float(worse[k]) > float(same[k]), k
    off = crit.__class__(LossConfig(geometric=False), norm)(noisy, x, torch.zeros(()), 0.02)
    assert set(off) == {"recon", "commit", "loss"}


def test_torch_fk_matches_feature_decoding():
    clip = _clip("jumps")
    feats = encode(clip.people[0], clip.offsets[0])
    j = fk_joints(torch.from_numpy(feats)[None].double(), torch.from_numpy(sk.REST_OFFSETS))[0]
    ref = decode(feats)                      # world frame, rest skeleton
    j = j.numpy()
    # same pose up to the heading/root placement: equal heights and pairwise distances
    np.testing.assert_allclose(j[..., 1], ref[..., 1], atol=1e-6)
    pair = lambda x: np.linalg.norm(x[:, :, None] - x[:, None], axis=-1)  # noqa: E731
    np.testing.assert_allclose(pair(j), pair(ref), atol=1e-6)
