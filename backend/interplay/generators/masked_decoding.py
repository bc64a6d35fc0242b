"""MaskGIT/MoMask decoding loops over part tokens, numpy only.

Tokens are laid out as in SPAM: base layer (4, n) — one row per body part in `PART_NAMES` order,
one column per 4 frames — and residual layers (4, Q, n) with the base in layer 0. A `LogitsFn`
maps the current tokens to logits (4, n, K); the runtime builds it from the ONNX graphs with
classifier-free guidance folded in (`guided`), so these loops never see the batch of two.

    base = fill_base(tokens, editable, logits_fn, mask_id, steps=10, rng=rng)
    codes = fill_residual(codes, redo, residual_fn)

Only `editable` positions are ever written: a test checks that every other token survives.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

LogitsFn = Callable[[np.ndarray], np.ndarray]          # tokens → logits (4, n, K)
ResidualFn = Callable[[np.ndarray, int], np.ndarray]   # (codes (4, Q, n), layer) → (4, n, K)


def guided(cond: np.ndarray, uncond: np.ndarray, scale: float) -> np.ndarray:
    """Classifier-free guidance: uncond + s·(cond − uncond) (s = 1 is the conditional model)."""
    return uncond + scale * (cond - uncond)


def cosine_schedule(total: int, steps: int) -> np.ndarray:
    """How many of `total` masked positions stay masked after each of `steps` steps:
    ⌊total·cos(π/2 · s/steps)⌋ for s = 1..steps (MoMask's γ), strictly decreasing to 0 so every
    step commits at least one token."""
    steps = max(1, min(int(steps), total)) if total else 1
    left = np.floor(total * np.cos(np.pi / 2 * np.arange(1, steps + 1) / steps)).astype(int)
    left[-1] = 0
    # Each step must commit ≥ 1 token: cap by what is still masked minus one.
    for s in range(steps):
        before = total if s == 0 else left[s - 1]
        left[s] = min(left[s], max(before - 1, 0))
    return left


def log_softmax(logits: np.ndarray) -> np.ndarray:
    z = logits - logits.max(axis=-1, keepdims=True)
    return z - np.log(np.exp(z).sum(axis=-1, keepdims=True))


def top_k(logits: np.ndarray, ratio: float) -> np.ndarray:
    """Logits with all but the top ⌈(1 − ratio)·K⌉ per position set to −inf (MoMask's filter;
    ratio 0 keeps everything)."""
    k = max(1, int(np.ceil((1.0 - ratio) * logits.shape[-1])))
    if k >= logits.shape[-1]:
        return logits
    kth = np.partition(logits, -k, axis=-1)[..., -k][..., None]
    return np.where(logits >= kth, logits, -np.inf)


def sample(logits: np.ndarray, rng: np.random.Generator, temperature: float = 1.0,
           topk_ratio: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Tokens (...,) drawn by the Gumbel-max trick at `temperature` (0 = greedy) among the top-k
    codes, and their probability under the unfiltered softmax (...,), the confidence MaskGIT
    ranks by."""
    logp = log_softmax(np.asarray(logits, dtype=np.float64))
    if temperature > 0:
        gumbel = -np.log(-np.log(rng.uniform(1e-12, 1.0, size=logp.shape)))
        picked = np.argmax(top_k(logp, topk_ratio) / temperature + gumbel, axis=-1)
    else:
        picked = np.argmax(logp, axis=-1)
    conf = np.exp(np.take_along_axis(logp, picked[..., None], axis=-1)[..., 0])
    return picked.astype(np.int64), conf


def fill_base(tokens: np.ndarray, editable: np.ndarray, logits_fn: LogitsFn, mask_id: int,
              steps: int = 10, rng: np.random.Generator | None = None,
              temperature: float = 1.0, topk_ratio: float = 0.0) -> np.ndarray:
    """Iterative masked decoding of the base layer.

    tokens (4, n) int64, editable (4, n) bool: those positions start as [MASK]; each step
    predicts every still-masked position, commits them, and re-masks the least confident ones
    per the cosine schedule (committed tokens are never re-masked, as in MoMask). Positions
    outside `editable` are passed to the model as given and returned unchanged."""
    tokens = np.asarray(tokens, dtype=np.int64)
    editable = np.asarray(editable, dtype=bool)
    if tokens.shape != editable.shape or tokens.ndim != 2:
        raise ValueError(f"tokens {tokens.shape} and editable {editable.shape} must both be (4, n)")
    rng = rng or np.random.default_rng(0)
    out = tokens.copy()
    out[editable] = mask_id
    masked = editable.copy()
    for left in cosine_schedule(int(editable.sum()), steps):
        if not masked.any():
            break
        # Sample only where still masked (fewer positions every step).
        picked, conf = sample(logits_fn(out)[masked], rng, temperature, topk_ratio)
        out[masked] = picked
        # Re-mask the `left` least confident of the positions just filled.
        flat = np.zeros(out.size, dtype=bool)
        flat[np.flatnonzero(masked)[np.argsort(conf, kind="stable")[:left]]] = True
        masked = flat.reshape(out.shape)
        out[masked] = mask_id
    return out


def fill_residual(codes: np.ndarray, redo: np.ndarray, residual_fn: ResidualFn) -> np.ndarray:
    """Residual layers 1..Q−1 one by one, greedy: codes (4, Q, n) int64, redo (4, n) bool marks
    where the residual tokens are predicted again (elsewhere they are kept). Layers ≥ the one
    being predicted are zeroed in the model's input (the graph ignores them anyway)."""
    out = np.asarray(codes, dtype=np.int64).copy()
    redo = np.asarray(redo, dtype=bool)
    if not redo.any():
        return out
    for layer in range(1, out.shape[1]):
        view = out.copy()
        view[:, layer:] = 0
        pred = np.argmax(residual_fn(view, layer), axis=-1)
        out[:, layer] = np.where(redo, pred, out[:, layer])
    return out


def token_windows(editable: np.ndarray, max_tokens: int, context: int = 5
                  ) -> list[tuple[int, int, int, int]]:
    """Windows (lo, edit_lo, edit_hi, hi) of at most `max_tokens` columns covering every column
    with an editable token: edit spans of ≤ max_tokens − 2·context columns, each with up to
    `context` columns either side (more on one side when the other hits the sequence end).
    Windows are decoded in order, so a later one sees earlier results as context."""
    cols = np.flatnonzero(np.asarray(editable, dtype=bool).any(axis=0))
    n = np.asarray(editable).shape[-1]
    if cols.size == 0:
        return []
    if n <= max_tokens:
        return [(0, int(cols[0]), int(cols[-1]) + 1, n)]
    span = max(1, max_tokens - 2 * context)
    out, start = [], int(cols[0])
    last = int(cols[-1]) + 1
    while start < last:
        stop = min(start + span, last)
        lo = max(0, start - context)
        hi = min(n, lo + max_tokens)
        lo = max(0, hi - max_tokens)
        out.append((lo, start, stop, hi))
        nxt = cols[cols >= stop]
        start = int(nxt[0]) if nxt.size else last
    return out
