"""The CODA runtime and generator on a tiny export with the real contract (coda_tiny: a
nearest-neighbour VQ of real pair blocks, a random transformer): loading and contract checks,
shapes, seeding, fixed bones, the floor, sliding windows past the model's range, multi-segment
plans, and the generator's fallback with a reason."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest

pytest.importorskip("torch")

from interplay.generators.base import Request  # noqa: E402
from interplay.generators.coda import runtime as coda_mod  # noqa: E402
from interplay.generators.coda.generator import CodaGenerator  # noqa: E402
from interplay.generators.coda.runtime import CodaRuntime  # noqa: E402
from interplay.generators.router import load_coda  # noqa: E402
from interplay.motion import skeleton as sk  # noqa: E402
from interplay.motion.kinematics import facing_angle  # noqa: E402
from interplay.motion.metrics import bone_deviation  # noqa: E402
from tests.helpers.coda_tiny import export_tiny  # noqa: E402


class HashEncoder:
    """Stands in for MiniLM: a fixed random vector per text."""

    def encode(self, texts):
        return np.stack([np.random.default_rng(abs(hash(t)) % 2**32).normal(size=384)
                         .astype(np.float32) for t in texts])


@pytest.fixture(scope="module")
def tiny(tmp_path_factory):
    return export_tiny(tmp_path_factory.mktemp("coda") / "coda", k=64, max_tokens=20)


@pytest.fixture(scope="module")
def rt(tiny):
    return CodaRuntime.load(tiny, encoder=HashEncoder())


def test_generate_shapes_seed_bones_and_floor(rt):
    a = rt.generate("two people shake hands", 3.0, seed=4)
    assert a.shape == (2, 60, 22, 3) and np.all(np.isfinite(a))
    assert np.array_equal(a, rt.generate("two people shake hands", 3.0, seed=4))
    assert not np.allclose(a, rt.generate("two people shake hands", 3.0, seed=5))
    for p in a:                                    # bones on fixed lengths (IK → FK)
        assert bone_deviation(p).max() < 1e-6
    lowest = np.concatenate([p[..., 1].min(axis=1) for p in a])
    assert abs(np.percentile(lowest, 2)) < 0.01 and lowest.min() > -1e-9    # the floor at y = 0


def test_long_motions_go_window_by_window_with_reencoded_context(rt, monkeypatch):
    calls = []
    encode = rt.encode
    monkeypatch.setattr(rt, "encode", lambda pair: calls.append(pair) or encode(pair))
    # 20 tokens per window (the tiny export: max_tokens 20), 5 of context: 90 frames. The first
    # window keeps 18 tokens (72 frames: its first and last tokens, the decoder's edges, are
    # dropped), the second sees frames 52–72 as context and makes the last 18 frames
    out = rt.generate("two people walk side by side", 4.5, seed=1)
    assert out.shape == (2, 90, 22, 3)
    assert [c.shape for c in calls] == [(2, coda_mod.CONTEXT * 4, 22, 3)]
    # the context is re-encoded in its own canonical frame: the first person's pelvis at the
    # XZ origin facing +Z on the context's first frame (the frame the model was trained in)
    first = calls[0][0, 0]
    assert np.allclose(first[sk.PELVIS, [0, 2]], 0.0, atol=1e-9)
    assert abs(float(facing_angle(first))) < 1e-6
    # and it is the motion's own frames 52–72 moved rigidly (same pairwise distances)
    ctx = out[:, 52:72]
    assert np.allclose(np.linalg.norm(calls[0][0] - calls[0][1], axis=-1),
                       np.linalg.norm(ctx[0] - ctx[1], axis=-1), atol=1e-6)
    long = rt.generate("two people walk side by side", 20.0, seed=2)
    assert long.shape == (2, 400, 22, 3) and np.all(np.isfinite(long))


def test_stream_covers_multi_segment_plans_in_order(rt):
    segments = [("two people hug", 37), ("two people wave", 50), ("two people hug", 13)]
    starts, total = [], 0
    for start, people in rt.stream(segments, seed=3):
        assert start == total and people.shape[0] == 2 and 0 < people.shape[1] <= 40
        starts.append(start)
        total += people.shape[1]
    assert total == 100


def test_context_tokens_are_kept_fixed(rt):
    text = rt.text_embedding("two people shake hands")
    codes = np.zeros((2, 12), np.int64)
    codes[:, :5] = np.arange(10).reshape(2, 5)
    editable = np.zeros((2, 12), bool)
    editable[:, 5:] = True
    out = rt.fill(codes, editable, text, np.random.default_rng(0))
    assert np.array_equal(out[:, :5], codes[:, :5])
    assert out[:, 5:].min() >= 0 and out[:, 5:].max() < rt.config.codes


def test_contract_errors_are_clear(tiny, tmp_path):
    broken = tmp_path / "broken"
    shutil.copytree(tiny, broken)
    (broken / "cmt.onnx").write_bytes(b"not a graph")
    with pytest.raises(ValueError, match="cmt.onnx"):
        CodaRuntime.load(broken)
    (broken / "cmt.onnx").unlink()
    with pytest.raises(FileNotFoundError, match="cmt.onnx"):
        CodaRuntime.load(broken)
    bad = tmp_path / "bad"
    shutil.copytree(tiny, bad)
    cfg = json.loads((bad / "config.json").read_text())
    (bad / "config.json").write_text(json.dumps({**cfg, "dim": 63}))
    with pytest.raises(ValueError, match="66"):
        CodaRuntime.load(bad)


def test_generator_uses_coda_for_two_people_and_falls_back_with_a_reason(tiny, tmp_path):
    coda, reason = load_coda(tiny, encoder=HashEncoder())
    assert coda is not None and reason is None
    untrained = tmp_path / "untrained"
    shutil.copytree(tiny, untrained)
    cfg = json.loads((untrained / "config.json").read_text())
    (untrained / "config.json").write_text(json.dumps({**cfg, "trained": False}))
    none, why = load_coda(untrained)
    assert none is None and "untrained" in why
    none, why = load_coda(tmp_path / "empty")
    assert none is None and "did not load" in why

    gen = CodaGenerator(coda)
    req = Request("two people hug, then they wave", persons=2, seconds=5, seed=9)
    plan = gen.plan(req)
    assert plan.generator == "coda" and len(plan.segments) == 2
    chunks = list(gen.stream(req, plan))
    assert sum(c[1][0].shape[0] for c in chunks) == 100
    assert all(len(people) == 2 and people[0].dtype == np.float32 for _, people in chunks)
    again = list(gen.stream(req, plan))
    assert all(np.array_equal(x[1][1], y[1][1]) for x, y in zip(chunks, again))
    assert sk.NUM_JOINTS == chunks[0][1][0].shape[1]
