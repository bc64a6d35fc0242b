"""The evaluation samples cut from the processed test split."""

import numpy as np
import pytest

from interplay.eval.testset import MAX_FRAMES, person_prompt, split_samples
from interplay.motion.clip import default_clips


@pytest.fixture(scope="module")
def clips():
    return default_clips()


def test_test_samples_cover_every_test_person_frame_in_windows(clips):
    samples = split_samples(clips, "test")
    test = [c for c in clips if c.split == "test" and not c.synthetic]
    assert {s.clip for s in samples} == {c.id for c in test}
    assert sum(s.frames for s in samples) == sum(c.frames * len(c.people) for c in test)
    assert all(1 <= s.frames <= MAX_FRAMES and s.joints.shape == (s.frames, 22, 3) for s in samples)
    by_id = {c.id: c for c in test}
    s = max(samples, key=lambda s: s.start)                # a window cut from a long capture
    assert s.start > 0
    np.testing.assert_array_equal(s.joints, by_id[s.clip].people[s.person][s.start:s.end])


def test_salsa_people_are_single_samples_with_a_one_person_prompt(clips):
    salsa = [s for s in split_samples(clips, "test") if s.clip.startswith("salsa")]
    assert {s.person for s in salsa} == {0, 1}
    assert {s.text for s in salsa} == {"a person dances salsa"}
    pair = next(c for c in clips if len(c.people) == 2)
    assert person_prompt(pair).startswith("a person")


def test_bad_split_is_refused(clips):
    with pytest.raises(ValueError, match="split"):
        split_samples(clips, "dev")
