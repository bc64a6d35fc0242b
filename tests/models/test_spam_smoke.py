"""SPAM smoke tests: tiny configs trained for a few seconds on a few real clips; the ONNX
contract of the exported graphs; invariants of the masked and residual transformers."""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest

torch = pytest.importorskip("torch")
pytest.importorskip("onnx")
ort = pytest.importorskip("onnxruntime")

from interplay.motion.clip import default_clips  # noqa: E402
from models.bench_torch import bench, bench_onnx, graph_inputs  # noqa: E402
from models.spam import checkpoint  # noqa: E402
from models.spam.config import LossConfig, TrainConfig, TransformerConfig, VQConfig  # noqa: E402
from models.spam.data import TextBank, fit_normalizer, load_tracks  # noqa: E402
from models.spam.export import example_inputs, export_all  # noqa: E402
from models.spam.train import TokenBatches, encode_tracks, mask_tokens, train_transformer, train_vq  # noqa: E402
from models.spam.transformer import SPAMTransformer  # noqa: E402
from models.spam.vqvae import RVQVAE  # noqa: E402

TINY_VQ = VQConfig(codes=32, layers=3, latent=16, width=32, depth=1)
TINY_TR = TransformerConfig(codes=32, layers_q=3, d=32, heads=2, blocks=1, dropout=0.0)


@pytest.fixture(scope="module")
def tracks():
    """Tracks of six real train clips of different families (plus their mirror images)."""
    clips, seen = [], set()
    for c in default_clips():
        if c.split == "train" and not c.synthetic and c.frames >= 80 and c.prompt not in seen:
            clips.append(c)
            seen.add(c.prompt)
        if len(clips) == 6:
            break
    return load_tracks(clips=clips)


@pytest.fixture(scope="module")
def trained(tracks, tmp_path_factory):
    # Tiny models gain nothing from threads, and OpenMP's spinning threads are slow on a
    # shared CPU when torch was imported before models.spam could set OMP_WAIT_POLICY.
    threads = torch.get_num_threads()
    torch.set_num_threads(1)
    try:
        yield _train_tiny(tracks, tmp_path_factory)
    finally:
        torch.set_num_threads(threads)


def _train_tiny(tracks, tmp_path_factory):
    torch.manual_seed(0)
    norm = fit_normalizer(tracks)
    # Budgets by steps (the seconds are a generous cap), so the run is deterministic.
    vq, hist = train_vq(TINY_VQ, LossConfig(), TrainConfig(steps=60, seconds=300, batch=16,
                                                           lr=5e-3, warmup=5), tracks, norm,
                        log=None)
    bank = TextBank(tracks, cache_dir=tmp_path_factory.mktemp("text"))
    codes = encode_tracks(vq, tracks, norm)
    tc = TrainConfig(steps=40, seconds=300, batch=16, lr=2e-3, warmup=5)
    batches = TokenBatches(tracks, codes, bank, tc, TINY_TR.max_tokens, TINY_VQ.downsample)
    base, base_hist = train_transformer(TINY_TR, tc, batches, log=None)
    res, _ = train_transformer(replace(TINY_TR, residual=True), tc, batches, log=None)
    return {"vq": vq, "hist": hist, "norm": norm, "base": base, "base_hist": base_hist,
            "residual": res, "tracks": tracks}


def _mean(rows, key, sl):
    return float(np.mean([r[key] for r in rows[sl]]))


def test_vq_loss_falls_on_real_clips(trained):
    rows = trained["hist"].rows
    assert len(rows) == 60
    assert _mean(rows, "loss", slice(-10, None)) < 0.85 * _mean(rows, "loss", slice(0, 10))
    assert _mean(rows, "recon", slice(-10, None)) < _mean(rows, "recon", slice(0, 10)) - 0.03
    for key in ("velocity", "foot", "bone", "com", "ktraj"):   # geometric terms are on
        assert np.isfinite(rows[-1][key])


def test_base_transformer_loss_falls(trained):
    rows = trained["base_hist"].rows
    assert _mean(rows, "ce", slice(-8, None)) < _mean(rows, "ce", slice(0, 8)) - 0.2


def test_decode_of_encode_is_the_quantised_reconstruction(trained):
    vq, norm, track = trained["vq"], trained["norm"], trained["tracks"][0]
    x = torch.from_numpy(norm.normalize(track.features[:64]))[None]
    with torch.no_grad():
        codes = vq.encode(x)
        y = vq.decode(codes)
        recon, _, fwd_codes = vq(x)
    assert codes.shape == (1, 4, TINY_VQ.layers, 16) and codes.dtype == torch.int64
    assert y.shape == x.shape
    assert torch.equal(codes, fwd_codes)
    assert torch.allclose(y, recon, atol=1e-5)


def test_masking_hits_exactly_the_masked_positions():
    gen = torch.Generator().manual_seed(0)
    tokens = torch.randint(0, 32, (64, 4, 12), generator=gen)
    inputs, mask = mask_tokens(tokens, 32, 32, gen)
    assert torch.equal(inputs[~mask], tokens[~mask])          # unmasked: untouched
    assert (inputs[mask] == 32).float().mean() > 0.6          # ~80% of masked → mask id
    assert mask.flatten(1).any(1).all()                       # every sample predicts something
    assert 0.2 < mask.float().mean() < 0.9                    # cosine schedule, mean ≈ 2/π


def test_greedy_fill_changes_only_masked_positions(trained):
    base = trained["base"]
    gen = torch.Generator().manual_seed(1)
    tokens = torch.randint(0, 32, (2, 4, 10), generator=gen)
    mask = torch.rand(2, 4, 10, generator=gen) < 0.5
    inputs = tokens.masked_fill(mask, TINY_TR.mask_id)
    with torch.no_grad():
        logits = base(inputs, torch.randn(2, 4, 384), torch.ones(2))
    filled = torch.where(mask, logits.argmax(-1), inputs)
    assert logits.shape == (2, 4, 10, 32)
    assert torch.equal(filled[~mask], tokens[~mask])
    assert (filled < TINY_TR.codes).all()


def test_unconditional_ignores_text_and_residual_ignores_upper_layers(trained):
    base, res = trained["base"], trained["residual"]
    gen = torch.Generator().manual_seed(2)
    tok = torch.randint(0, 32, (2, 4, 7), generator=gen)
    t1, t2 = torch.randn(2, 4, 384, generator=gen), torch.randn(2, 4, 384, generator=gen)
    zero, one = torch.zeros(2), torch.ones(2)
    with torch.no_grad():
        assert torch.allclose(base(tok, t1, zero), base(tok, t2, zero))
        assert not torch.allclose(base(tok, t1, one), base(tok, t2, one))
        rtok = torch.randint(0, 32, (2, 4, 3, 7), generator=gen)
        layer = torch.tensor([1, 2])
        other = rtok.clone()
        other[0, :, 1:] = 32           # layers ≥ 1 of sample 0, ≥ 2 of sample 1: anything
        other[1, :, 2:] = 5
        assert torch.allclose(res(rtok, t1, one, layer), res(other, t1, one, layer))


def test_onnx_export_matches_torch(trained, tmp_path):
    out = export_all(trained["vq"], trained["base"], trained["residual"], trained["norm"],
                     tmp_path / "spam")
    cfg = json.loads((out / "config.json").read_text())
    assert (cfg["K"], cfg["Q"], cfg["mask_id"], cfg["downsample"]) == (32, 3, 32, 4)
    inputs = example_inputs(trained["vq"], n=9, batch=3)      # other B and n than exported
    torch_fns = {
        "vq_encode": trained["vq"].encode, "vq_decode": trained["vq"].decode,
        "base": trained["base"],
        "residual": lambda tok, layer, text, cond: trained["residual"](tok, text, cond, layer),
    }
    expected_io = {"vq_encode": (["motion"], "codes"), "vq_decode": (["codes"], "motion"),
                   "base": (["tokens", "text", "cond"], "logits"),
                   "residual": (["tokens", "layer", "text", "cond"], "logits")}
    for name, fn in torch_fns.items():
        sess = ort.InferenceSession(str(out / f"{name}.onnx"), providers=["CPUExecutionProvider"])
        names, output = expected_io[name]
        assert [i.name for i in sess.get_inputs()] == names
        assert [o.name for o in sess.get_outputs()] == [output]
        got = sess.run(None, {n: a.numpy() for n, a in zip(names, inputs[name])})[0]
        with torch.no_grad():
            ref = fn(*inputs[name]).numpy()
        assert got.shape == ref.shape and got.dtype == ref.dtype
        if got.dtype == np.int64:
            assert (got == ref).mean() > 0.99      # argmin ties may differ in the last ulp
        else:
            np.testing.assert_allclose(got, ref, atol=1e-4, rtol=0)
    # decode(encode(x)) through onnxruntime on a real clip
    enc = ort.InferenceSession(str(out / "vq_encode.onnx"), providers=["CPUExecutionProvider"])
    dec = ort.InferenceSession(str(out / "vq_decode.onnx"), providers=["CPUExecutionProvider"])
    x = trained["norm"].normalize(trained["tracks"][1].features[:40])[None]
    codes = enc.run(None, {"motion": x})[0]
    y = dec.run(None, {"codes": codes})[0]
    assert codes.shape == (1, 4, 3, 10) and y.shape == x.shape
    # the int8 transformers the export ships next to the float ones, and the config says so
    assert cfg["precision"] == "int8"
    for name in ("base", "residual"):
        sess = ort.InferenceSession(str(out / f"{name}.int8.onnx"),
                                    providers=["CPUExecutionProvider"])
        got = sess.run(None, {n: a.numpy() for n, a in zip(expected_io[name][0], inputs[name])})[0]
        with torch.no_grad():
            ref = torch_fns[name](*inputs[name]).numpy()
        assert got.shape == ref.shape and np.abs(got - ref).mean() < 0.1 * np.abs(ref).mean()
    # torch eager vs onnxruntime timing covers every graph in both precisions
    ms = bench_onnx(out, graph_inputs(trained["vq"], 5), runs=1, warmup=0, threads=1)
    assert set(ms["fp32"]) == set(ms["int8"]) == set(torch_fns)
    assert set(bench(trained["vq"], trained["base"], trained["residual"], 5, runs=1,
                     warmup=0)) == set(torch_fns)


def test_checkpoint_round_trip(trained, tmp_path):
    for name in ("vq", "base", "residual"):
        checkpoint.save(trained[name], tmp_path / f"{name}.pt")
        back = checkpoint.load(tmp_path / f"{name}.pt")
        assert type(back) is type(trained[name]) and back.cfg == trained[name].cfg
        for (k, a), (_, b) in zip(trained[name].state_dict().items(), back.state_dict().items()):
            assert torch.equal(a, b), k
    assert isinstance(checkpoint.load(tmp_path / "base.pt"), SPAMTransformer)
    assert isinstance(checkpoint.load(tmp_path / "vq.pt"), RVQVAE)
