"""Numpy stand-ins for SPAM's four ONNX graphs (same names, inputs and shapes as the export
contract), so the runtime's loops can be tested on the token level without trained weights.

The stub VQ is part-local: a part's codes depend only on that part's feature dims, and decoding
writes each part's dims from its own codes. The stub transformers are small deterministic
functions of the text, the position and the unmasked neighbouring tokens, so masked decoding
has context to use. Every call is recorded in `calls`."""

from __future__ import annotations

import zlib

import numpy as np

from interplay.generators.spam.files import SpamConfig
from interplay.generators.spam.runtime import SpamRuntime
from interplay.motion import skeleton as sk
from interplay.motion.features import FEATURE_DIM, Normalizer, part_feature_mask

MASKS = np.stack([part_feature_mask(p) for p in sk.PART_NAMES])      # (4, 239)


class StubGraphs(dict):
    def __init__(self, config: SpamConfig, seed: int = 0):
        super().__init__()
        c, rng = config, np.random.default_rng(seed)
        self.config, self.calls = c, []
        self.proj = rng.normal(size=(4, FEATURE_DIM, c.Q))             # encoder projections
        self.book = rng.normal(size=(4, c.Q, c.K, FEATURE_DIM)) * 0.3   # decoder codebooks
        self.text_w = rng.normal(size=(384, c.K))
        self.pos_w = rng.normal(size=(c.max_tokens, c.K))
        self.next_w = rng.normal(size=(c.K + 1, c.K)) * 2.0              # neighbour → logits
        self.next_w[c.K] = 0.0                                           # [MASK] says nothing
        self.update(vq_encode=self.vq_encode, vq_decode=self.vq_decode, base=self.base,
                    residual=self.residual)

    def vq_encode(self, motion):
        self.calls.append(("vq_encode", motion.shape))
        b, t, _ = motion.shape
        blocks = motion.reshape(b, t // 4, 4, FEATURE_DIM).mean(axis=2)  # (B, n, 239)
        z = np.einsum("bnd,pdq->bpqn", blocks, self.proj * MASKS[:, :, None]) / 4
        codes = np.floor((np.tanh(z) + 1) / 2 * self.config.K)
        return np.clip(codes, 0, self.config.K - 1).astype(np.int64)

    def vq_decode(self, codes):
        self.calls.append(("vq_decode", codes.shape))
        b, _, q, n = codes.shape
        out = np.zeros((b, n, FEATURE_DIM))
        for p in range(4):
            for layer in range(q):
                out += self.book[p, layer][codes[:, p, layer]] * MASKS[p] / (layer + 1)
        return np.repeat(out, 4, axis=1).astype(np.float32)

    def _logits(self, tokens, text, cond):
        n = tokens.shape[-1]
        logits = cond[:, None, None, None] * (text @ self.text_w)[:, :, None, :]
        logits = logits + self.pos_w[:n][None, None]
        left = np.concatenate([np.full(tokens.shape[:-1] + (1,), self.config.K), tokens[..., :-1]], -1)
        right = np.concatenate([tokens[..., 1:], np.full(tokens.shape[:-1] + (1,), self.config.K)], -1)
        return (logits + self.next_w[left] + self.next_w[right]).astype(np.float32)

    def base(self, tokens, text, cond):
        self.calls.append(("base", tokens.shape))
        assert tokens.dtype == np.int64 and text.dtype == np.float32 and cond.dtype == np.float32
        return self._logits(tokens, text, cond)

    def residual(self, tokens, layer, text, cond):
        self.calls.append(("residual", tokens.shape, tuple(layer)))
        assert layer.dtype == np.int64 and (layer >= 1).all() and (layer < self.config.Q).all()
        prev = tokens[np.arange(len(layer)), :, layer - 1]               # (B, 4, n)
        assert (tokens[np.arange(len(layer)), :, layer] == 0).all()      # later layers zeroed
        return self._logits(prev, text, cond)


class StubEncoder:
    """Deterministic unit 'embeddings' per string (no model)."""

    def encode(self, texts):
        out = []
        for t in texts:
            v = np.random.default_rng(zlib.crc32(t.encode())).normal(size=384)
            out.append(v / np.linalg.norm(v))
        return np.array(out, dtype=np.float32)


def stub_runtime(normalizer: Normalizer, K: int = 32, Q: int = 3, max_tokens: int = 50
                 ) -> SpamRuntime:
    config = SpamConfig(K=K, Q=Q, d=16, max_tokens=max_tokens)
    return SpamRuntime(config, normalizer, StubGraphs(config), encoder=StubEncoder())
