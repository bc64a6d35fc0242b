"""ARFlow training smoke test: a tiny model on a few hundred real pair windows learns (the
validation loss at fixed seeds falls), exports to ONNX that matches torch, and the runtime
samples a reactor from the exported graph."""

from __future__ import annotations

import json

import numpy as np
import pytest

torch = pytest.importorskip("torch")

from interplay.motion.skeleton import PARENTS  # noqa: E402
from models.arflow.config import ARFlowConfig, TrainConfig  # noqa: E402
from models.arflow.data import PairSet, fit_stats, pair_set  # noqa: E402
from models.arflow.export import check, check_step, export, load  # noqa: E402
from models.arflow.model import ARFlow  # noqa: E402
from models.arflow.train import evaluate, tensors, train  # noqa: E402


class ConstEncoder:
    """Stands in for MiniLM (the smoke test checks training, not text)."""

    def encode(self, texts):
        return np.stack([np.full(384, len(t) / 100.0, np.float32) for t in texts])


def _subset(ps: PairSet, n: int, seed: int) -> PairSet:
    keep = np.random.default_rng(seed).choice(len(ps), min(n, len(ps)), replace=False)
    return PairSet(ps.actor[keep], ps.reactor[keep], ps.text[keep], ps.synthetic[keep],
                   [ps.clip_ids[i] for i in keep])


@pytest.fixture(scope="module")
def data():
    cfg = ARFlowConfig(window=16, d_model=32, layers=1, heads=2, ff=64, dropout=0.0)
    tr = _subset(pair_set("train", 16, 8, encoder=ConstEncoder()), 256, 0)
    va = _subset(pair_set("val", 16, 16, mirror=False, encoder=ConstEncoder()), 64, 1)
    return cfg, tr, va


def test_loss_falls_and_onnx_matches(data, tmp_path):
    cfg, tr, va = data
    assert tr.actor.shape[1:] == (16, 66) and np.isfinite(tr.actor).all()
    torch.manual_seed(0)
    mean, std = fit_stats(tr)
    parents = torch.tensor([max(p, 0) for p in PARENTS])
    before = evaluate(ARFlow(cfg), cfg, tensors(va, mean, std), torch.from_numpy(mean),
                      torch.from_numpy(std), parents)
    tc = TrainConfig(steps=60, batch_size=16, lr=2e-3, warmup=5, eval_every=60, budget_s=120)
    summary = train(cfg, tc, tmp_path / "ck", tr, va, log=lambda m: None)
    assert summary["best_val"] < 0.8 * before, (before, summary["best_val"])
    out = export(tmp_path / "ck", tmp_path / "w")
    assert check(load(tmp_path / "ck"), out / "arflow.onnx") < 1e-3
    assert check_step(load(tmp_path / "ck"), out / "arflow_step.onnx") < 1e-3
    config = json.loads((out / "config.json").read_text())
    assert config["window"] == 16 and config["sampling"]["steps"] >= 1

    from interplay.reaction.session import ReactionModel, sample_windows
    m = ReactionModel(out)
    reactor = sample_windows(m, va.actor[:2].reshape(2, 16, 22, 3), seed=0, guidance=True)
    assert reactor.shape == (2, 16, 22, 3) and np.isfinite(reactor).all()
