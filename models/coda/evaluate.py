"""Measured numbers of a CODA variant: reconstruction of the held-out pairs through the
CVQ-VAE (MPJPE; IV, IF, contact frames and CODA's chain penetration of the reconstructions
vs the real pairs), and generated pairs from the CMT for the sampling-default search.

Pair metrics are `interplay.motion.metrics.pair_geometry` per window: IV mean cm³ per frame,
IF share of frames with overlapping bodies, contact frames per window (a hand within 3 cm of
the other body), and `interaction` GDM error / chain penetration (eq. 6/7 vs the real pair).
"""

from __future__ import annotations

import numpy as np
import torch

from interplay.motion.metrics import DEFAULT, pair_geometry
from interplay.motion.pair import interaction as ia

from .cvq import CVQVAE
from .data import PairTensors


def to_joints(x: torch.Tensor | np.ndarray, mean: np.ndarray, std: np.ndarray) -> np.ndarray:
    """Normalised (N, T, 66) → metres (N, T, 22, 3)."""
    x = x.numpy() if isinstance(x, torch.Tensor) else x
    return (x * std + mean).reshape(*x.shape[:2], 22, 3).astype(np.float64)


def pair_numbers(a: np.ndarray, b: np.ndarray) -> dict[str, float]:
    """Mean IV, IF, contact frames per window over windows (N, T, 22, 3) of the two people."""
    rows = []
    for wa, wb in zip(a, b):
        g = pair_geometry(wa, wb)
        rows.append([g["volume"].mean(), g["overlap"].mean(),
                     (g["hand_gap"] <= DEFAULT.hand_contact).any(axis=(1, 2)).sum(),
                     g["min_distance"].min()])
    v = np.mean(rows, axis=0) if rows else np.full(4, np.nan)
    return {"iv_cm3": float(v[0]), "if": float(v[1]), "contact_frames": float(v[2]),
            "min_distance_m": float(v[3])}


def penetration_numbers(pa, pb, ta, tb, frame_stride: int = 4) -> dict[str, float]:
    """CODA eq. 6 and eq. 7 of the predicted pairs against the real ones (numpy versions)."""
    gdm, ppl = [], []
    for a, b, c, d in zip(pa, pb, ta, tb):
        s = slice(None, None, frame_stride)
        gdm.append(ia.gdm_error((a[s], b[s]), (c[s], d[s])))
        ppl.append(ia.penetration_penalty(ia.part_min_distance(a[s], b[s]),
                                          ia.part_min_distance(c[s], d[s]),
                                          ia.part_box_overlap(a[s], b[s])))
    return {"gdm_m": float(np.mean(gdm)), "ppl": float(np.mean(ppl))}


@torch.no_grad()
def reconstruct(vq: CVQVAE, data: PairTensors, batch: int = 64):
    """Encode both people and decode the pair: (x_a, x_b) normalised (N, T, 66)."""
    vq.eval()
    outs_a, outs_b = [], []
    for i in range(0, len(data), batch):
        ca, cb = vq.encode(data.a[i:i + batch]), vq.encode(data.b[i:i + batch])
        xa, xb = vq.decode(ca, cb)
        outs_a.append(xa)
        outs_b.append(xb)
    return torch.cat(outs_a), torch.cat(outs_b)


def recon_report(vq: CVQVAE, data: PairTensors, mean, std, real: dict | None = None) -> dict:
    """MPJPE (m) of the decoded test pairs and their pair metrics (`real`: the real pairs')."""
    xa, xb = reconstruct(vq, data)
    pa, pb = to_joints(xa, mean, std), to_joints(xb, mean, std)
    ta, tb = to_joints(data.a, mean, std), to_joints(data.b, mean, std)
    mpjpe = float(np.mean([np.linalg.norm(p - t, axis=-1).mean() for p, t in ((pa, ta), (pb, tb))]))
    key = list(ia.sk.KEY_JOINTS)
    out = {"mpjpe_m": mpjpe,
           "key_joint_error_m": float(np.linalg.norm(pa[:, :, key] - ta[:, :, key], axis=-1).mean()),
           "windows": len(data), **pair_numbers(pa, pb), **penetration_numbers(pa, pb, ta, tb)}
    if real is not None:
        out["real"] = real
    return out
