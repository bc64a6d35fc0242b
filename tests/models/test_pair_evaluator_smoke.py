"""Smoke test of the pair evaluator's training and export on a few real pairs: the
contrastive loss falls, the exported ONNX encoder reproduces torch, and the runtime loads the
export and embeds pair windows."""

import numpy as np
import pytest

torch = pytest.importorskip("torch")

from interplay.motion.clip import default_clips  # noqa: E402
from interplay.review.pair_evaluator import PairEvaluator  # noqa: E402
from models.common.contrastive import info_nce  # noqa: E402
from models.evaluator.export import onnx_matches_torch  # noqa: E402
from models.pair_evaluator.config import PairEvaluatorConfig  # noqa: E402
from models.pair_evaluator.export import export, load_checkpoint  # noqa: E402
from models.pair_evaluator.train import TINY, train  # noqa: E402


@pytest.fixture(scope="module")
def few_clips():
    """Two captured salsa pairs and four composed pairs each of hug and wave (train), plus
    one val pair of each kind."""
    pairs = [c for c in default_clips() if len(c.people) == 2]
    out = [c for c in pairs if not c.synthetic and c.split == "train"][:2]
    out += [c for c in pairs if not c.synthetic and c.split == "val"][:1]
    for kind in ("hug", "wave"):
        out += [c for c in pairs if c.synthetic and c.meta.get("kind") == kind
                and c.split == "train"][:4]
        out += [c for c in pairs if c.synthetic and c.meta.get("kind") == kind
                and c.split == "val"][:1]
    return out


@pytest.fixture(scope="module")
def trained(few_clips, tmp_path_factory):
    cfg = PairEvaluatorConfig(**{**TINY, "steps": 60, "eval_every": 30, "stride": 10,
                                 "seconds": 120.0})
    ckpt = train(cfg, few_clips, log=lambda *_: None)
    out = tmp_path_factory.mktemp("pair_evaluator")
    torch.save(ckpt, out / "pair_evaluator.pt")
    export(out / "pair_evaluator.pt", out / "w")
    return ckpt, out


def test_loss_falls(trained):
    losses = trained[0]["losses"]
    assert len(losses) == 60
    assert np.mean(losses[-10:]) < 0.8 * np.mean(losses[:10])
    assert trained[0]["kinds"] == ["hug", "salsa", "wave"]


def test_export_matches_torch_and_runtime_embeds(trained, few_clips):
    _, out = trained
    model, _ = load_checkpoint(out / "pair_evaluator.pt")
    ev = PairEvaluator.load(out / "w")
    assert onnx_matches_torch(model, ev) < 1e-4
    text = np.random.default_rng(0).normal(size=(3, 384)).astype(np.float32)
    with torch.no_grad():
        ref = model.text(torch.from_numpy(text)).numpy()
    assert np.abs(ev.project_text(text) - ref).max() < 1e-5
    window = np.stack(few_clips[0].people)[None, :, :40]
    assert ev.embed(window).shape == (1, model.cfg.embed_dim)


def test_broken_pairs_are_negatives_of_every_text():
    """A text whose own window scores below a broken window gets a larger loss than one whose
    window beats every broken one."""
    m = torch.nn.functional.normalize(torch.tensor([[1.0, 0.0], [0.0, 1.0]]), dim=1)
    t = m.clone()
    same = torch.zeros(2, 2, dtype=torch.bool)
    far = info_nce(m, t, same, 0.1, text_negatives=-m)
    close = info_nce(m, t, same, 0.1, text_negatives=m * 0.99 + 0.01)
    assert close > far
