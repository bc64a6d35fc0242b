"""CODA's Commonsense Constraint Loss (Algorithm 1) and geometric losses in torch, on decoded
joints (B, T, 22, 3), metres, Y up. The two-person terms mirror the numpy definitions of
`interplay.motion.pair.interaction` exactly (tests/models/test_coda_losses.py checks equality):

  com     eq. 4: (|COM − pelvis| error)² + (error of the cosine of the pelvis→COM line's
          angle to the horizontal plane)², COM = mean of the joints (the paper: mass 1 each)
  ktraj   eq. 5: L1 of the key joints (pelvis, wrists, toes), averaged over frames
  gdm     eq. 6 between the two people's 22 × 22 joint distance maps, τ = 0.5 (`gdm_error`)
  ppl     eq. 7 per pair of body-part chains (4 × 4): AABB overlap of the predicted pair's
          part boxes × [max(0, 0.9 d_gt − d_pred) + (d_pred − d_gt)²] on the minimum
          bone-to-bone distance, averaged over the 16 chain pairs (`penetration_penalty`)
  velocity, foot (displacement of planted target feet), bone (L1 of bone lengths)
"""

from __future__ import annotations

import torch
import torch.nn.functional as F

from interplay.motion import skeleton as sk
from interplay.motion.pair.interaction import EPS, PART_BONES, TAU

from .config import LossConfig

_CHILD = [c for c, _ in sk.BONES]
_PARENT = [p for _, p in sk.BONES]
FOOT_HEIGHT = 0.06      # m: a target foot joint this low …
FOOT_SPEED = 0.01       # … moving less than this per frame (0.2 m/s) is planted


def com_terms(j: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
    """Pelvis→COM distance (...,) and cosine of its angle to the horizontal plane."""
    v = j.mean(-2) - j[..., sk.PELVIS, :]
    dist = v.norm(dim=-1)
    return dist, v[..., [0, 2]].norm(dim=-1) / (dist + 1e-6)


def joint_distance_map(a: torch.Tensor, b: torch.Tensor) -> torch.Tensor:
    """(..., 22, 3) each → (..., 22, 22) distances (rows a's joints); differentiable at 0."""
    return ((a[..., :, None, :] - b[..., None, :, :]).pow(2).sum(-1) + 1e-12).sqrt()


def gdm_loss(pa, pb, ta, tb, tau: float = TAU) -> torch.Tensor:
    """Eq. 6 per frame, averaged over frames (and batch): pred pair (pa, pb), target (ta, tb)."""
    d_pred, d_gt = joint_distance_map(pa, pb), joint_distance_map(ta, tb)
    w_pred = torch.exp(-d_pred.pow(2) / (2 * tau * tau))
    w_gt = torch.exp(-d_gt.pow(2) / (2 * tau * tau))
    first = (w_pred * (d_pred - d_gt).abs()).sum((-1, -2)) / (w_pred.sum((-1, -2)) + EPS)
    second = (w_gt * d_pred).sum((-1, -2)) / (w_gt.sum((-1, -2)) + EPS)
    return (first + second).mean()


def part_box_overlap(a: torch.Tensor, b: torch.Tensor) -> torch.Tensor:
    """(..., 22, 3) each → (..., 4, 4) bool: AABB of a's part i meets that of b's part j."""
    def boxes(j):
        lo = torch.stack([j[..., sk.PART_JOINTS[p], :].amin(-2) for p in sk.PART_NAMES], -2)
        hi = torch.stack([j[..., sk.PART_JOINTS[p], :].amax(-2) for p in sk.PART_NAMES], -2)
        return lo, hi
    (lo_a, hi_a), (lo_b, hi_b) = boxes(a), boxes(b)
    return ((lo_a[..., :, None, :] <= hi_b[..., None, :, :])
            & (lo_b[..., None, :, :] <= hi_a[..., :, None, :])).all(-1)


def segment_distances(p1, q1, p2, q2) -> torch.Tensor:
    """Shortest distances between segments p1–q1 and p2–q2 (..., 3) (Ericson §5.1.9, as the
    numpy `interaction.segment_distances`)."""
    d1, d2, r = q1 - p1, q2 - p2, p1 - p2
    a = (d1 * d1).sum(-1).clamp_min(1e-12)
    e = (d2 * d2).sum(-1).clamp_min(1e-12)
    b = (d1 * d2).sum(-1)
    c = (d1 * r).sum(-1)
    f = (d2 * r).sum(-1)
    denom = a * e - b * b
    s = torch.where(denom > 1e-12, ((b * f - c * e) / denom.clamp_min(1e-12)).clamp(0, 1),
                    torch.zeros_like(denom))
    t = (b * s + f) / e
    s = torch.where(t < 0, (-c / a).clamp(0, 1), torch.where(t > 1, ((b - c) / a).clamp(0, 1), s))
    t = t.clamp(0, 1)
    gap = (p1 + s[..., None] * d1) - (p2 + t[..., None] * d2)
    return (gap.pow(2).sum(-1) + 1e-12).sqrt()


def part_min_distance(a: torch.Tensor, b: torch.Tensor) -> torch.Tensor:
    """(..., 22, 3) each → (..., 4, 4) minimum bone-to-bone distance between part chains."""
    d = segment_distances(a[..., _PARENT, None, :], a[..., _CHILD, None, :],
                          b[..., None, _PARENT, :], b[..., None, _CHILD, :])   # (..., 21, 21)
    big = d.detach().max() + 1.0
    rows = []
    for i in range(4):
        cols = []
        for j in range(4):
            m = torch.from_numpy(PART_BONES[i][:, None] & PART_BONES[j][None, :]).to(d.device)
            cols.append(torch.where(m, d, big).amin((-1, -2)))
        rows.append(torch.stack(cols, -1))
    return torch.stack(rows, -2)


def ppl_loss(pa, pb, ta, tb) -> torch.Tensor:
    """Eq. 7: overlap of the predicted pair's part boxes gates the chain-distance penalty."""
    overlap = part_box_overlap(pa.detach(), pb.detach()).to(pa.dtype)
    d_pred, d_gt = part_min_distance(pa, pb), part_min_distance(ta, tb).detach()
    term = F.relu(0.9 * d_gt - d_pred) + (d_pred - d_gt).pow(2)
    return (overlap * term).mean()


def person_terms(p: torch.Tensor, t: torch.Tensor) -> dict[str, torch.Tensor]:
    """Single-person terms for joints (B, T, 22, 3): COM, KTraj, velocity, foot, bone."""
    (dp, cp), (dt, ct) = com_terms(p), com_terms(t)
    key = list(sk.KEY_JOINTS)
    vp, vt = p[:, 1:] - p[:, :-1], t[:, 1:] - t[:, :-1]
    feet = list(sk.FOOT_JOINTS)
    planted = ((t[:, 1:, feet, 1] < FOOT_HEIGHT)
               & (vt[:, :, feet].norm(dim=-1) < FOOT_SPEED)).to(p.dtype)
    foot = (vp[:, :, feet].norm(dim=-1) * planted).sum() / planted.sum().clamp_min(1.0)
    bp = (p[:, :, _CHILD] - p[:, :, _PARENT]).norm(dim=-1)
    bt = (t[:, :, _CHILD] - t[:, :, _PARENT]).norm(dim=-1)
    return {"com": F.mse_loss(dp, dt) + F.mse_loss(cp, ct),
            "ktraj": (p[:, :, key] - t[:, :, key]).abs().sum(-1).mean(),
            "velocity": F.l1_loss(vp, vt), "foot": foot, "bone": F.l1_loss(bp, bt)}


def ccl(pa, pb, ta, tb, cfg: LossConfig) -> tuple[torch.Tensor, dict[str, torch.Tensor]]:
    """Weighted CCL + geometric sum and its terms; joints (B, T, 22, 3) metres per person."""
    ra, rb = person_terms(pa, ta), person_terms(pb, tb)
    terms = {k: (ra[k] + rb[k]) / 2 for k in ra}
    g = slice(None, None, cfg.gdm_frame_stride)
    terms["gdm"] = (gdm_loss(pa[:, g], pb[:, g], ta[:, g], tb[:, g], cfg.tau) if cfg.w_gdm > 0
                    else pa.new_zeros(()))
    s = slice(None, None, cfg.ppl_frame_stride)
    terms["ppl"] = (ppl_loss(pa[:, s], pb[:, s], ta[:, s], tb[:, s]) if cfg.w_ppl > 0
                    else pa.new_zeros(()))
    total = (cfg.w_com * terms["com"] + cfg.w_ktraj * terms["ktraj"] + cfg.w_gdm * terms["gdm"]
             + cfg.w_ppl * terms["ppl"] + cfg.w_velocity * terms["velocity"]
             + cfg.w_foot * terms["foot"] + cfg.w_bone * terms["bone"])
    return total, terms
