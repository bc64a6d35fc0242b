"""Measured numbers of trained SPAM models, for the model card: reconstruction error on the
test split in mm after decoding to joints, codebook usage and perplexity per part and layer,
and physical plausibility of the reconstructions (`interplay.motion.metrics.clip_metrics`).
"""

from __future__ import annotations

import numpy as np
import torch

from interplay.motion.features import SLICES, Normalizer, decode
from interplay.motion.kinematics import fit_to_skeleton
from interplay.motion.metrics import clip_metrics

from .config import PARTS
from .data import Track
from .vqvae import RVQVAE

PLAUSIBILITY = ("bone_deviation", "foot_skating", "ground_penetration", "com_angle")


@torch.no_grad()
def reconstruct_features(vq: RVQVAE, track: Track, normalizer: Normalizer):
    """(reference features, reconstructed features), both (T', 239) denormalised, T' = T cut
    to a multiple of 4."""
    frames = len(track.features) // vq.cfg.downsample * vq.cfg.downsample
    feats = track.features[:frames]
    x = torch.from_numpy(normalizer.normalize(feats))[None]
    return feats, normalizer.denormalize(vq(x)[0][0].numpy())


def position_joints(feats: np.ndarray) -> np.ndarray:
    """Root-relative joints (T, 22, 3) straight from the `positions`/`root_height` blocks
    (heading frame, pelvis at (0, h, 0)), without FK."""
    t = len(feats)
    out = np.zeros((t, 22, 3))
    out[:, 0, 1] = feats[:, SLICES["root_height"]][:, 0]
    out[:, 1:] = feats[:, SLICES["positions"]].reshape(t, 21, 3)
    return out


def vq_report(vq: RVQVAE, tracks: list[Track], normalizer: Normalizer) -> dict:
    """MPJPE in mm over tracks (frame-weighted means): global and root-relative after FK of
    the decoded rotations, of the `positions` block itself (no FK) and of those positions
    fitted to the skeleton (IK → FK, rigid bones); plausibility metrics
    of the FK joints, and the same metrics of the reference motion for comparison."""
    vq.eval()
    err, err_rel, err_pos, err_ik, frames, plaus, ref = [], [], [], [], [], [], []
    for t in tracks:
        if len(t.features) < 2 * vq.cfg.downsample:
            continue
        feats, recon = reconstruct_features(vq, t, normalizer)
        gt, pred = decode(feats, t.offsets), decode(recon, t.offsets)
        d = np.linalg.norm(pred - gt, axis=-1)
        dr = np.linalg.norm((pred - pred[:, :1]) - (gt - gt[:, :1]), axis=-1)
        pos_gt, pos = position_joints(feats), position_joints(recon)
        dp = np.linalg.norm(pos - pos_gt, axis=-1)
        dik = np.linalg.norm(fit_to_skeleton(pos, t.offsets)[0] - pos_gt, axis=-1)
        err.append(d.mean())
        err_rel.append(dr.mean())
        err_pos.append(dp.mean())
        err_ik.append(dik.mean())
        frames.append(len(gt))
        plaus.append(clip_metrics([pred]))
        ref.append(clip_metrics([gt]))
    w = np.array(frames, dtype=np.float64)
    w /= w.sum()
    out = {"tracks": len(frames), "frames": int(sum(frames)),
           "mpjpe_mm": float(np.dot(w, err) * 1000), "mpjpe_root_relative_mm":
           float(np.dot(w, err_rel) * 1000),
           "mpjpe_positions_mm": float(np.dot(w, err_pos) * 1000),
           "mpjpe_positions_ik_mm": float(np.dot(w, err_ik) * 1000)}
    for k in PLAUSIBILITY:
        out[k] = float(np.dot(w, [m[k] for m in plaus]))
        out[f"reference_{k}"] = float(np.dot(w, [m[k] for m in ref]))
    return out


def codebook_usage(codes: list[np.ndarray], k: int) -> dict:
    """Per stream (part) and layer: share of the K codes used and perplexity (exp of the code
    entropy) over all tokens of `codes` (each (S, Q, n))."""
    allc = np.concatenate([c for c in codes if c.shape[-1]], axis=-1)     # (S, Q, N)
    names = PARTS if allc.shape[0] == len(PARTS) else ("body",)
    out = {}
    for s, name in enumerate(names):
        rows = []
        for q in range(allc.shape[1]):
            p = np.bincount(allc[s, q], minlength=k) / allc.shape[-1]
            nz = p[p > 0]
            rows.append({"used": float((p > 0).mean()),
                         "perplexity": float(np.exp(-(nz * np.log(nz)).sum()))})
        out[name] = rows
    return out


def usage_summary(usage: dict) -> dict:
    """Per part: layer-0 usage/perplexity and the mean over layers."""
    return {name: {"base_used": rows[0]["used"], "base_perplexity": rows[0]["perplexity"],
                   "mean_used": float(np.mean([r["used"] for r in rows])),
                   "mean_perplexity": float(np.mean([r["perplexity"] for r in rows]))}
            for name, rows in usage.items()}
