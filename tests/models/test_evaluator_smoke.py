"""Smoke test of the evaluator's training and export on a few real clips: the contrastive loss
falls, and the exported ONNX motion encoder + numpy text projection reproduce torch."""

import numpy as np
import pytest

torch = pytest.importorskip("torch")

from interplay.motion.clip import default_clips  # noqa: E402
from interplay.review.evaluator import EvaluatorRuntime as Runtime  # noqa: E402
from models.common.contrastive import info_nce  # noqa: E402
from models.evaluator.config import EvaluatorConfig  # noqa: E402
from models.evaluator.export import export, load_checkpoint, onnx_matches_torch  # noqa: E402
from models.evaluator.train import TINY, train  # noqa: E402


@pytest.fixture(scope="module")
def few_clips():
    """Short train clips of three actions plus a few val clips (real captures)."""
    clips = default_clips()
    out = []
    for prompt in ("a person squats down and stands back up", "a person hops on both legs",
                   "a person kicks forward with the left foot"):
        out += [c for c in clips if c.prompt == prompt and c.split == "train"][:4]
        out += [c for c in clips if c.prompt == prompt and c.split == "val"][:1]
    return out


@pytest.fixture(scope="module")
def trained(few_clips, tmp_path_factory):
    cfg = EvaluatorConfig(**{**TINY, "steps": 60, "eval_every": 30, "batch_size": 12,
                             "max_frames": 80, "seconds": 120.0})
    ckpt = train(cfg, few_clips, log=lambda *_: None)
    out = tmp_path_factory.mktemp("evaluator")
    torch.save(ckpt, out / "evaluator.pt")
    export(out / "evaluator.pt", out / "w")
    return ckpt, out


def test_loss_falls(trained):
    losses = trained[0]["losses"]
    assert len(losses) == 60
    assert np.mean(losses[-10:]) < 0.8 * np.mean(losses[:10])


def test_onnx_and_numpy_match_torch(trained, few_clips):
    ckpt, out = trained
    model, _ = load_checkpoint(out / "evaluator.pt")
    runtime = Runtime.load(out / "w")
    assert onnx_matches_torch(model, runtime) < 1e-4
    text = np.random.default_rng(0).normal(size=(5, 384)).astype(np.float32)
    with torch.no_grad():
        ref = model.text(torch.from_numpy(text)).numpy()
    assert np.abs(runtime.project_text(text) - ref).max() < 1e-5
    emb = runtime.embed_motion([few_clips[0].people[0]])
    assert emb.shape == (1, model.cfg.embed_dim)


def test_false_negatives_leave_the_softmax():
    """Pairs marked as false negatives drop out: with every off-diagonal pair marked, each
    softmax holds only its positive and the loss is 0 whatever the embeddings."""
    g = torch.Generator().manual_seed(0)
    m = torch.nn.functional.normalize(torch.randn(3, 8, generator=g), dim=-1)
    t = torch.nn.functional.normalize(torch.randn(3, 8, generator=g), dim=-1)
    none = torch.zeros(3, 3, dtype=torch.bool)
    assert float(info_nce(m, t, none, 0.07)) > 0.1
    assert float(info_nce(m, t, ~none, 0.07)) == pytest.approx(0.0, abs=1e-6)
    one = none.clone()
    one[0, 1] = True                  # drops text 1 from motion 0's softmax (and vice versa)
    assert float(info_nce(m, t, one, 0.07)) < float(info_nce(m, t, none, 0.07))
