"""Uniform cubic B-splines with a smoothing penalty (P-splines, Eilers & Marx 1996), numpy only.

A spline over the parameter interval [0, 1] cut into `segments` equal pieces has
`segments + 3` coefficients (one per basis function; the knots run from -3h to 1 + 3h, so every
point of [0, 1] sees exactly four basis functions). Fitting minimises

    sum_i w_i |y_i - B(u_i) c|^2  +  penalty * (n / segments) * |D2 c|^2

where D2 takes second differences of neighbouring coefficients: the penalty pulls the curve
towards straight pieces (and keeps the fit defined where data are sparse), the segment count
sets the finest detail the curve can follow. `penalty` is per data point per segment, so the
same value smooths alike whatever the number of points.

Used by the trajectory editor to smooth curves before resampling them by arc length and to
split a pelvis path into travel and sway.
"""

from __future__ import annotations

import numpy as np

# Uniform cubic B-spline blending weights on one segment, local parameter t in [0, 1):
# rows are the powers (1, t, t², t³), columns the four basis functions touching the segment.
_BLEND = np.array([
    [1.0, 4.0, 1.0, 0.0],
    [-3.0, 0.0, 3.0, 0.0],
    [3.0, -6.0, 3.0, 0.0],
    [-1.0, 3.0, -3.0, 1.0],
]) / 6.0


# Up to this many elements (8 MB) the design matrix is built dense and multiplied as it always
# was (the results of every ordinary curve and walk stay bit-identical); beyond, fit and evaluate
# use only the four non-zero basis values per row, so their cost is linear in the samples.
DENSE_LIMIT = 1_000_000


def _local(u: np.ndarray, segments: int, derivative: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """For parameters u (N,): the first of the four basis functions touching each one (N,)
    and their values (or first/second derivatives with respect to u) there (N, 4)."""
    if segments < 1:
        raise ValueError(f"a spline needs at least one segment, got {segments}")
    if derivative not in (0, 1, 2):
        raise ValueError(f"derivative must be 0, 1 or 2, got {derivative}")
    x = np.clip(np.asarray(u, dtype=np.float64), 0.0, 1.0) * segments
    seg = np.minimum(np.floor(x).astype(int), segments - 1)          # (N,) segment index
    t = x - seg                                                      # (N,) local parameter
    one, zero = np.ones_like(t), np.zeros_like(t)
    if derivative == 0:
        powers = np.stack([one, t, t * t, t ** 3], axis=1)
    elif derivative == 1:
        powers = np.stack([zero, one, 2 * t, 3 * t * t], axis=1) * segments
    else:
        powers = np.stack([zero, zero, 2 * one, 6 * t], axis=1) * segments ** 2
    return seg, powers @ _BLEND                                       # (N,), (N, 4)


def basis(u: np.ndarray, segments: int, derivative: int = 0) -> np.ndarray:
    """Design matrix (N, segments + 3): basis functions (or their first/second derivative with
    respect to u) at parameters u (N,) in [0, 1] (values outside are clamped). Dense: fit and
    evaluate use it only while it is small (DENSE_LIMIT), then the four non-zero values per row."""
    seg, weights = _local(u, segments, derivative)
    out = np.zeros((len(seg), segments + 3))
    rows = np.arange(len(seg))[:, None]
    out[rows, seg[:, None] + np.arange(4)] = weights
    return out


def fit(u: np.ndarray, y: np.ndarray, segments: int, penalty: float = 1e-3,
        weights: np.ndarray | None = None) -> np.ndarray:
    """Coefficients (segments + 3, D) of the penalised least-squares spline through values
    y (N, D) (or (N,)) at parameters u (N,) in [0, 1]."""
    u = np.asarray(u, dtype=np.float64)
    y = np.asarray(y, dtype=np.float64)
    y2 = y.reshape(len(y), -1)
    if u.ndim != 1 or len(u) != len(y2) or len(u) < 2:
        raise ValueError(f"need matching parameters (N,) and values (N, D) with N >= 2, "
                         f"got {u.shape} and {y.shape}")
    if penalty < 0:
        raise ValueError(f"penalty must be >= 0, got {penalty}")
    w = np.ones(len(u)) if weights is None else np.asarray(weights, dtype=np.float64)
    n = segments + 3
    if len(u) * n <= DENSE_LIMIT:
        b = basis(u, segments)
        d2 = np.diff(np.eye(n), n=2, axis=0)                          # (segments + 1, n)
        lhs = b.T @ (w[:, None] * b) + penalty * len(u) / segments * (d2.T @ d2)
        rhs = b.T @ (w[:, None] * y2)
    else:
        # The normal equations B^T W B and B^T W y from the four non-zero basis values per
        # row: O(N) work and memory instead of a dense (N, n) design matrix.
        seg, vals = _local(u, segments)
        cols = seg[:, None] + np.arange(4)                            # (N, 4)
        wb = w[:, None] * vals
        pairs = (cols[:, :, None] * n + cols[:, None, :]).ravel()     # (N·16,) flat (i, j)
        gram = np.bincount(pairs, (wb[:, :, None] * vals[:, None, :]).ravel(),
                           minlength=n * n).reshape(n, n)
        rhs = np.stack([np.bincount(cols.ravel(), (wb * y2[:, d, None]).ravel(), minlength=n)
                        for d in range(y2.shape[1])], axis=1)
        lhs = gram + penalty * len(u) / segments * _second_difference_gram(n)
    # A tiny ridge keeps the system solvable when the data leave basis functions unseen.
    lhs += 1e-10 * np.trace(lhs) / len(lhs) * np.eye(len(lhs))
    coef = np.linalg.solve(lhs, rhs)
    return coef if y.ndim > 1 else coef[:, 0]


def _second_difference_gram(n: int) -> np.ndarray:
    """D2ᵀ D2 (n, n) for the second-difference matrix D2 (n - 2, n) (rows [1, -2, 1]), built
    from its five diagonals rather than by a dense product."""
    rows = np.arange(n - 2)[:, None] + np.arange(3)                   # (n - 2, 3)
    v = np.array([1.0, -2.0, 1.0])
    pairs = (rows[:, :, None] * n + rows[:, None, :]).ravel()
    return np.bincount(pairs, np.tile(np.outer(v, v).ravel(), n - 2), minlength=n * n).reshape(n, n)


def evaluate(coef: np.ndarray, u: np.ndarray, derivative: int = 0) -> np.ndarray:
    """Spline values (N, D) (or (N,)) at parameters u (N,), or a derivative with respect to u."""
    coef = np.asarray(coef, dtype=np.float64)
    if np.size(u) * len(coef) <= DENSE_LIMIT:
        return basis(u, len(coef) - 3, derivative) @ coef
    seg, b = _local(u, len(coef) - 3, derivative)
    c = coef.reshape(len(coef), -1)
    out = b[:, 0, None] * c[seg]
    for k in range(1, 4):
        out += b[:, k, None] * c[seg + k]
    return out.reshape((len(seg),) + coef.shape[1:])


def smooth(y: np.ndarray, segments: int, penalty: float = 1e-3) -> np.ndarray:
    """Values y (N, D) sampled at evenly spaced parameters, smoothed by a spline fit."""
    u = np.linspace(0.0, 1.0, len(y))
    return evaluate(fit(u, y, segments, penalty), u)
