"""CODA training smoke test on real pair windows with a tiny config: the CVQ-VAE loss (eq. 3 +
CCL) and the CMT's masked-token cross-entropy fall over a few steps, the three graphs export
to ONNX and match torch (both the ICS model and the single-codebook ablation), and masked
decoding yields valid codes that decode to a pair."""

from __future__ import annotations

import json

import numpy as np
import pytest

torch = pytest.importorskip("torch")

from models.arflow.data import fit_stats, pair_set  # noqa: E402
from models.coda.cmt import CMT  # noqa: E402
from models.coda.config import CMTConfig, CVQConfig, LossConfig, TrainConfig  # noqa: E402
from models.coda.data import tensors  # noqa: E402
from models.coda.export import export_all  # noqa: E402
from models.coda.sample import sample_codes  # noqa: E402
from models.coda.train import Joints, cvq_loss, encode_pairs, evaluate_cmt, train_cmt, train_cvq  # noqa: E402

TINY = CVQConfig(codes=32, interaction_codes=16, latent=32, width=32, depth=1, heads=2)
TINY_CMT = CMTConfig(codes=32, d=32, heads=2, blocks=1, ff=2, dropout=0.0, max_tokens=8)


class ConstEncoder:
    """Stands in for MiniLM (the smoke test checks training, not text)."""

    def encode(self, texts):
        return np.stack([np.full(384, len(t) / 100.0, np.float32) for t in texts])


@pytest.fixture(scope="module", autouse=True)
def one_thread():
    """One torch thread: tiny ops gain nothing from two, and lose a lot on a busy CPU."""
    before = torch.get_num_threads()
    torch.set_num_threads(1)
    yield
    torch.set_num_threads(before)


@pytest.fixture(scope="module")
def data():
    tr = pair_set("train", 16, 16, encoder=ConstEncoder())
    keep = np.random.default_rng(0).choice(len(tr), 192, replace=False)
    mean, std = fit_stats(tr)
    return tensors(tr, mean, std).take(keep), mean, std


@torch.no_grad()
def _eval_terms(model, joints, d) -> dict[str, float]:
    model.eval()
    return cvq_loss(model, LossConfig(), joints, d.a[:64], d.b[:64])[1]


@pytest.fixture(scope="module")
def trained(data):
    d, mean, std = data
    joints = Joints(mean, std)
    tc = TrainConfig(steps=40, seconds=1e6, batch=16, lr=2e-3, warmup=5, log_every=100)
    vq, hist = train_cvq(TINY, LossConfig(), tc, d, joints, log=lambda m: None)
    return vq, joints, hist


def test_cvq_loss_falls(data, trained):
    d, _, _ = data
    vq, joints, hist = trained
    first, after = hist.rows[0], _eval_terms(vq, joints, d)
    # The total falls, and so do the reconstruction and the key-joint trajectory error
    # (GDM's second term is not zero even for a perfect pair, so the total falls less).
    assert after["loss"] < 0.9 * first["loss"], (first, after)
    assert after["recon"] < 0.9 * first["recon"] and after["ktraj"] < 0.85 * first["ktraj"], (
        first, after)


def test_cmt_learns_and_exports_match_torch(data, trained, tmp_path):
    d, mean, std = data
    vq = trained[0]
    codes = encode_pairs(vq, d)
    assert codes.shape == (len(d), 2, 4) and codes.max() < TINY.codes
    torch.manual_seed(0)
    before = evaluate_cmt(CMT(TINY_CMT), codes, d.text)["ce"]
    cmt, _ = train_cmt(TINY_CMT, TrainConfig(steps=30, seconds=1e6, batch=32, lr=3e-3, warmup=5,
                                             log_every=100), codes, d.text, log=lambda m: None)
    after = evaluate_cmt(cmt, codes, d.text)["ce"]
    assert after < before - 0.3, (before, after)

    sampling = {"steps": 4, "cfg": 2.0, "temperature": 1.0, "topk": 8}
    err = export_all(vq, cmt, mean, std, tmp_path / "w", sampling, trained=False)
    assert err < 1e-3
    cfg = json.loads((tmp_path / "w" / "config.json").read_text())
    assert (cfg["codes"], cfg["mask_id"], cfg["downsample"], cfg["dim"]) == (32, 32, 4, 66)
    assert cfg["interaction_codes"] == 16 and cfg["trained"] is False
    stats = np.load(tmp_path / "w" / "normalizer.npz")
    assert stats["mean"].shape == stats["std"].shape == (66,)

    import onnxruntime as ort
    enc = ort.InferenceSession(str(tmp_path / "w" / "encode.onnx"))
    got = enc.run(None, {"x": d.a[:3, :12].numpy()})[0]
    assert got.dtype == np.int64 and got.shape == (3, 3)
    np.testing.assert_array_equal(got, vq.encode(d.a[:3, :12]).numpy())

    gen = torch.Generator().manual_seed(0)
    sampled = sample_codes(cmt, d.text[:2], 4, steps=4, topk=8, gen=gen)
    assert sampled.shape == (2, 2, 4) and int(sampled.max()) < TINY.codes
    xa, xb = vq.decode(sampled[:, 0], sampled[:, 1])
    assert xa.shape == xb.shape == (2, 16, 66) and torch.isfinite(xa).all()


def test_single_codebook_ablation_exports(data, tmp_path):
    d, mean, std = data
    cfg = CVQConfig(**{**TINY.__dict__, "ics": False})
    vq, _ = train_cvq(cfg, LossConfig(), TrainConfig(steps=3, batch=8, log_every=100), d,
                      Joints(mean, std), log=lambda m: None)
    assert not hasattr(vq, "inter_q")
    err = export_all(vq, CMT(TINY_CMT), mean, std, tmp_path / "n", {"steps": 2}, trained=False)
    assert err < 1e-3
    assert json.loads((tmp_path / "n" / "config.json").read_text())["interaction_codes"] == 0
