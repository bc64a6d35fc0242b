"""What the studio shows is what was saved (issue 26.1): frames changed after they were
streamed (a correction's re-draw, its seams and floor pass, the pair pass) go out again as
`replace` events, so a client that applies `frames` and `replace` in order holds exactly the
stored motion at `done`; `done` carries the stored frames' digests, which the browser computes
the same way (frontend/src/api/digest.test.ts checks the same fixture values)."""

from __future__ import annotations

import numpy as np
import pytest

from interplay.api.digest import frame_digests, motion_digest
from interplay.pipeline.sent import SentFrames
from tests.helpers.api import run_job

# The fixture motion both sides hash: 2 people, 3 frames, x = round(sin(7t + 3j + c + 11p) ·
# 1.2345, 4). digest.test.ts hard-codes the same values.
FIXTURE_FRAMES = ["3b12643e", "74d96d43", "47f804f3"]
FIXTURE_MOTION = "be7a39ef"


def fixture_people() -> list[np.ndarray]:
    t, j, c = np.meshgrid(np.arange(3), np.arange(22), np.arange(3), indexing="ij")
    return [np.round(np.sin(7 * t + 3 * j + c + 11 * p) * 1.2345, 4).astype(np.float32)
            for p in range(2)]


def test_digests_of_the_shared_fixture():
    frames = frame_digests(fixture_people())
    assert frames == FIXTURE_FRAMES
    assert motion_digest(frames) == FIXTURE_MOTION


def test_a_digest_sees_a_tenth_of_a_millimetre_and_nothing_less():
    people = fixture_people()
    moved = [p.copy() for p in people]
    moved[1][2, 5, 0] += 1e-4
    assert frame_digests(moved)[:2] == FIXTURE_FRAMES[:2] and frame_digests(moved)[2] != FIXTURE_FRAMES[2]
    moved[1][2, 5, 0] = people[1][2, 5, 0] + 1e-6      # below what the stream carries
    assert frame_digests(moved) == FIXTURE_FRAMES


def test_sent_frames_replace_only_what_changed_and_send_what_was_never_sent():
    calls: list[tuple] = []
    sent = SentFrames(lambda s, c: calls.append(("frames", s, len(c[0]))),
                      lambda s, c, cause, seg: calls.append((cause, s, len(c[0]), seg)))
    walk = np.arange(60 * 66, dtype=np.float64).reshape(60, 22, 3) / 1000
    sent(0, [walk[:40]])
    sent.by("pair_pass", 0)(30, [walk[30:50]])        # 10 frames again, 10 new
    assert calls == [("frames", 0, 40), ("pair_pass", 30, 10, 0), ("frames", 40, 10)]
    calls.clear()
    changed = walk.copy()
    changed[5:8] += 0.01
    assert sent.sync([changed[:60]], "correction", 1) == 3 + 10   # 3 changed, 50-59 never sent
    assert calls == [("correction", 5, 3, 1), ("frames", 50, 10)]
    calls.clear()
    assert sent.sync([changed[:60]], "sync") == 0 and calls == []


@pytest.mark.parametrize("settings", ["sqlite"], indirect=True)
def test_a_corrected_job_streams_exactly_the_stored_motion(real_client):
    """Seeds of a three-segment prompt whose reviews re-draw segments (the re-draw also moves
    frames past the segment, already streamed: seams, the floor pass): the frames and
    replacements applied in order are the stored motion, frame for frame, at `done`."""
    corrected = 0
    for seed in range(1, 9):
        _, events = run_job(real_client, prompt="a person walks forward, then jumps, then sits down",
                            seconds=6, seed=seed)
        done = events[-1]
        assert done["type"] == "done", done
        page: dict[int, list] = {}
        for e in events:
            if e["type"] in ("frames", "replace"):
                for i in range(len(e["people"][0])):
                    page[e["start"] + i] = [p[i] for p in e["people"]]
        stored = real_client.get(f"/api/motions/{done['motion_id']}").json()
        want = np.array([p["joints"] for p in stored["people"]])            # (P, T, 22, 3)
        have = np.array([page[t] for t in range(want.shape[1])]).swapaxes(0, 1)
        assert np.array_equal(have, want), f"seed {seed}: the stream differs from the stored motion"
        assert done["frame_digests"] == frame_digests(want)
        assert done["digest"] == motion_digest(done["frame_digests"])
        replaced = [e for e in events if e["type"] == "replace"]
        accepted = [e for e in events if e["type"] == "correction" and e["accepted"]]
        if accepted:
            corrected += 1
            assert {e["cause"] for e in replaced} == {"correction"}
            assert {e["segment"] for e in replaced} <= {c["segment"] for c in accepted}
    assert corrected >= 2, "the prompt no longer gets corrections: pick another"
