"""The text-to-motion metrics of Guo et al. 2022 (as MoMask reports them), over evaluator
embeddings. numpy only; every function takes plain arrays so tests can check the maths.

Embeddings are the evaluator's unit vectors, so distances lie in [0, 2] (Guo's evaluator is
unnormalised: absolute values are not comparable with the papers', rankings are).

  R-precision   for each motion: its own text and 31 texts of other samples whose text differs
                (Guo draws a batch of 32; a distractor identical to the true text would be an
                unresolvable tie, and this test set has few distinct prompts); top-k accuracy of
                the true text ranked by Euclidean distance
  FID           Fréchet distance between Gaussians fit to generated and real embeddings
  MM-Dist       mean distance between each motion and its own text
  Diversity     mean distance between random pairs of motions (300 pairs, fewer if the set is small)
  MultiModality mean pairwise distance among motions generated for the same text
  95% CI        1.96 · std / sqrt(repeats) over repeated runs (Guo's formula, np.std)
"""

from __future__ import annotations

import numpy as np


def _check_pairs(motion: np.ndarray, text: np.ndarray) -> None:
    if motion.ndim != 2 or motion.shape != text.shape:
        raise ValueError(f"motion and text embeddings must both be (N, E), got "
                         f"{motion.shape} and {text.shape}")


def r_precision(motion: np.ndarray, text: np.ndarray, labels: list[str],
                rng: np.random.Generator, pool: int = 32, top_k: int = 3) -> np.ndarray:
    """Top-1..top_k accuracy (top_k,) of retrieving each motion's own text among `pool`
    texts: its own and pool - 1 texts of samples with a different label (drawn without
    replacement while there are enough such samples, with replacement otherwise)."""
    motion, text = np.asarray(motion, np.float64), np.asarray(text, np.float64)
    _check_pairs(motion, text)
    label_arr = np.asarray(labels, dtype=object)
    if len(label_arr) != len(motion):
        raise ValueError(f"{len(label_arr)} labels for {len(motion)} samples")
    hits = np.zeros(top_k)
    for i in range(len(motion)):
        others = np.flatnonzero(label_arr != label_arr[i])
        if len(others) == 0:
            raise ValueError("R-precision needs samples with at least two different texts")
        pick = rng.choice(others, size=pool - 1, replace=len(others) < pool - 1)
        d_true = np.linalg.norm(motion[i] - text[i])
        d_other = np.linalg.norm(motion[i] - text[pick], axis=1)
        rank = 1 + np.count_nonzero(d_other < d_true)
        hits += rank <= np.arange(1, top_k + 1)
    return hits / len(motion)


def mm_dist(motion: np.ndarray, text: np.ndarray) -> float:
    """Mean Euclidean distance between each motion embedding and its text's."""
    _check_pairs(motion, text)
    return float(np.linalg.norm(np.asarray(motion, np.float64) - text, axis=1).mean())


def gaussian(emb: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Mean (E,) and covariance (E, E) of embeddings (N, E), N ≥ 2."""
    emb = np.asarray(emb, dtype=np.float64)
    if emb.ndim != 2 or len(emb) < 2:
        raise ValueError(f"need (N >= 2, E) embeddings, got {emb.shape}")
    return emb.mean(axis=0), np.cov(emb, rowvar=False)


def frechet(mu1: np.ndarray, cov1: np.ndarray, mu2: np.ndarray, cov2: np.ndarray) -> float:
    """|mu1 - mu2|² + tr(C1 + C2 - 2 (C1 C2)^½). The trace of the matrix square root is taken
    as Σ sqrt(eig(C1^½ C2 C1^½)) (a symmetric PSD matrix with the same eigenvalues as C1 C2),
    so no scipy and no complex parts from rank-deficient covariances."""
    w, v = np.linalg.eigh(cov1)
    root1 = (v * np.sqrt(np.clip(w, 0.0, None))) @ v.T
    inner = root1 @ cov2 @ root1
    ev = np.linalg.eigvalsh(0.5 * (inner + inner.T))
    diff = np.asarray(mu1) - np.asarray(mu2)
    value = diff @ diff + np.trace(cov1) + np.trace(cov2) - 2.0 * np.sqrt(np.clip(ev, 0.0, None)).sum()
    return float(max(value, 0.0))


def fid(generated: np.ndarray, real: np.ndarray) -> float:
    """Fréchet distance between the embeddings' Gaussians."""
    return frechet(*gaussian(generated), *gaussian(real))


def diversity(emb: np.ndarray, rng: np.random.Generator, pairs: int = 300) -> float:
    """Mean distance over `pairs` random pairs of different samples (all pairs if fewer exist)."""
    emb = np.asarray(emb, dtype=np.float64)
    n = len(emb)
    if n < 2:
        raise ValueError("diversity needs at least 2 motions")
    i, j = np.triu_indices(n, k=1)
    if len(i) > pairs:
        keep = rng.choice(len(i), size=pairs, replace=False)
        i, j = i[keep], j[keep]
    return float(np.linalg.norm(emb[i] - emb[j], axis=1).mean())


def multimodality(groups: list[np.ndarray]) -> float:
    """Mean over texts of the mean pairwise distance among that text's generations (G, E)."""
    per_text = []
    for g in groups:
        g = np.asarray(g, dtype=np.float64)
        if len(g) < 2:
            raise ValueError("multimodality needs at least 2 generations per text")
        i, j = np.triu_indices(len(g), k=1)
        per_text.append(np.linalg.norm(g[i] - g[j], axis=1).mean())
    if not per_text:
        raise ValueError("multimodality needs at least one text")
    return float(np.mean(per_text))


def confidence(values) -> tuple[float, float]:
    """(mean, 95% half-width) over repeats: 1.96 · std / sqrt(n) (Guo et al.'s formula)."""
    v = np.asarray(values, dtype=np.float64)
    if v.size == 0:
        raise ValueError("confidence needs at least one value")
    return float(v.mean()), float(1.96 * v.std() / np.sqrt(v.size))
