"""A tiny CODA export with the real contract (encode/decode/cmt ONNX, config.json,
normalizer.npz), for testing the numpy runtime before (or besides) the trained weights.

The VQ is a nearest-neighbour codebook of K real 4-frame person blocks (normalised, canonical
pair windows of the train split), so encode → decode reconstructs real motion roughly; decode
adds a small residual of the other person's codes to each (the interaction codebook's place).
The masked transformer is random: embeddings of both rows + position + a projection of the
text → logits. Torch lives only here (tests/models)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import torch
from torch import nn

from interplay.motion.clip import default_clips
from interplay.motion.pair.windows import pair_windows

DS, DIM = 4, 66


class Encode(nn.Module):
    def __init__(self, book: torch.Tensor):
        super().__init__()
        self.book = nn.Parameter(book, requires_grad=False)          # (K, 4·66)

    def forward(self, x):                                            # (B, T, 66)
        b, t, _ = x.shape
        blocks = x.reshape(b, t // DS, DS * DIM)
        d = (blocks.unsqueeze(2) - self.book).pow(2).sum(-1)         # (B, n, K)
        return d.argmin(-1)


class Decode(nn.Module):
    def __init__(self, book: torch.Tensor, k: int):
        super().__init__()
        self.book = nn.Parameter(book, requires_grad=False)
        self.inter = nn.Embedding(k, DS * DIM)
        nn.init.normal_(self.inter.weight, std=0.01)

    def forward(self, codes_a, codes_b):
        b, n = codes_a.shape
        xa = self.book[codes_a] + self.inter(codes_b)
        xb = self.book[codes_b] + self.inter(codes_a)
        return xa.reshape(b, n * DS, DIM), xb.reshape(b, n * DS, DIM)


class Cmt(nn.Module):
    def __init__(self, k: int, max_tokens: int, d: int = 32):
        super().__init__()
        self.tok = nn.Embedding(k + 1, d)
        self.pos = nn.Embedding(max_tokens, d)
        self.person = nn.Embedding(2, d)
        self.text = nn.Linear(384, d)
        self.out = nn.Linear(d, k)

    def forward(self, codes, text):                                  # (B, 2, n), (B, 384)
        n = codes.shape[-1]
        h = self.tok(codes) + self.pos(torch.arange(n))[None, None] \
            + self.person(torch.arange(2))[None, :, None] + self.text(text)[:, None, None]
        # a little context: each position sees the mean of both rows
        h = h + torch.tanh(h.mean(dim=(1, 2), keepdim=True))
        return self.out(torch.tanh(h)) * 3.0


def export_tiny(out: Path, k: int = 64, max_tokens: int = 20, seed: int = 0,
                trained: bool = True) -> Path:
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    torch.manual_seed(seed)
    clips = [c for c in default_clips() if c.split == "train" and len(c.people) == 2]
    w = pair_windows(clips, 40, 40, roles="as_is", mirror=False).joints     # (N, 2, 40, 22, 3)
    flat = w.reshape(-1, DIM).astype(np.float64)
    mean, std = flat.mean(0), flat.std(0) + 1e-3
    blocks = ((w.reshape(-1, 40, DIM) - mean) / std).reshape(-1, DS * DIM)
    pick = np.random.default_rng(seed).choice(len(blocks), k, replace=False)
    book = torch.tensor(blocks[pick], dtype=torch.float32)
    np.savez(out / "normalizer.npz", mean=mean.astype(np.float32), std=std.astype(np.float32))
    n = 6
    kw = dict(opset_version=17, dynamo=False)
    torch.onnx.export(Encode(book).eval(), (torch.zeros(1, n * DS, DIM),), out / "encode.onnx",
                      input_names=["x"], output_names=["codes"],
                      dynamic_axes={"x": {0: "b", 1: "t"}, "codes": {0: "b", 1: "n"}}, **kw)
    torch.onnx.export(Decode(book, k).eval(), (torch.zeros(1, n, dtype=torch.long),
                                               torch.zeros(1, n, dtype=torch.long)),
                      out / "decode.onnx", input_names=["codes_a", "codes_b"],
                      output_names=["x_a", "x_b"],
                      dynamic_axes={"codes_a": {0: "b", 1: "n"}, "codes_b": {0: "b", 1: "n"},
                                    "x_a": {0: "b", 1: "t"}, "x_b": {0: "b", 1: "t"}}, **kw)
    torch.onnx.export(Cmt(k, max_tokens).eval(), (torch.zeros(1, 2, n, dtype=torch.long),
                                                  torch.zeros(1, 384)),
                      out / "cmt.onnx", input_names=["codes", "text"], output_names=["logits"],
                      dynamic_axes={"codes": {0: "b", 2: "n"}, "text": {0: "b"},
                                    "logits": {0: "b", 2: "n"}}, **kw)
    (out / "config.json").write_text(json.dumps({
        "trained": trained, "codes": k, "interaction_codes": k, "downsample": DS,
        "max_tokens": max_tokens, "mask_id": k, "fps": 20, "dim": DIM,
        "sampling": {"steps": 6, "cfg": 2.0, "temperature": 1.0, "topk": 0.5}}))
    (out / "MODEL_CARD.md").write_text("# CODA tiny test export (random transformer)\n")
    return out
