"""VQ-VAE losses (CoMA eq. 4 + CODA's single-person commonsense losses, eq. 4–5).

Reconstruction is L1 on normalised features; commitment is the quantizers' β·MSE. The
geometric/commonsense terms are computed on joints taken from the decoded, denormalised
features: the `positions` and `root_height` blocks give every joint relative to the pelvis
(XZ) in the heading frame, with y absolute, differentiably (no FK needed):

  velocity   L1 of joint displacements between frames
  foot       predicted foot-joint displacement (`velocities` block) where the data has contact
  bone       L1 of bone lengths
  com        CODA eq. 4: (|COM − pelvis| error)² + (cos of the pelvis→COM elevation error)²,
             COM from `skeleton.SEGMENT_MASS` at segment centres (as `metrics.centre_of_mass`)
  ktraj      CODA eq. 5: L1 of the key joints (pelvis, wrists, toes) per frame
  fk         L1 of the joints posed by forward kinematics of the decoded 6D rotations on the
             rest skeleton (the path `features.decode` takes), so rotation errors are weighed
             by how far they move joints down the chain
"""

from __future__ import annotations

import numpy as np
import torch
import torch.nn.functional as F

from interplay.motion import metrics
from interplay.motion import skeleton as sk
from interplay.motion.features import ROT_JOINTS, SLICES, Normalizer

from .config import LossConfig

_CHILD = [c for c, _ in sk.BONES]
_PARENT = [p for _, p in sk.BONES]


def _com_weights() -> np.ndarray:
    """(22,) weights w with COM = Σ_j w_j · joint_j: metrics.centre_of_mass is linear in the
    joints, so evaluating it on one-hot joint sets reads its weights off exactly."""
    eye = np.repeat(np.eye(sk.NUM_JOINTS)[:, :, None], 3, axis=2)   # frame i: joint i at (1,1,1)
    return metrics.centre_of_mass(eye)[:, 0]


COM_WEIGHTS = _com_weights()


def sixd_to_matrix(d6: torch.Tensor) -> torch.Tensor:
    """6D (..., 6) → rotations (..., 3, 3) by Gram–Schmidt, as `rotations.sixd_to_matrix`."""
    b1 = F.normalize(d6[..., :3], dim=-1, eps=1e-8)
    a2 = d6[..., 3:]
    b2 = F.normalize(a2 - (b1 * a2).sum(-1, keepdim=True) * b1, dim=-1, eps=1e-8)
    return torch.stack([b1, b2, torch.cross(b1, b2, dim=-1)], dim=-1)


def fk_joints(feats: torch.Tensor, offsets: torch.Tensor) -> torch.Tensor:
    """Denormalised features (B, T, 239) → joints (B, T, 22, 3) by FK of the 6D rotations on
    offsets (22, 3), pelvis at (0, h, 0) in the heading frame."""
    b, t, _ = feats.shape
    rot = sixd_to_matrix(feats[..., SLICES["rotations"]].reshape(b, t, len(ROT_JOINTS), 6))
    local = dict(zip(ROT_JOINTS, rot.unbind(2)))
    eye = torch.eye(3, dtype=feats.dtype).expand(b, t, 3, 3)
    glob, pos = [], []
    for j, p in enumerate(sk.PARENTS):
        r = local.get(j, eye)
        if p < 0:
            glob.append(r)
            pos.append(F.pad(feats[..., SLICES["root_height"]], (1, 1)))
        else:
            glob.append(glob[p] @ r)
            pos.append(pos[p] + (glob[p] @ offsets[j]))
    return torch.stack(pos, 2)


class MotionLoss(torch.nn.Module):
    def __init__(self, cfg: LossConfig, normalizer: Normalizer):
        super().__init__()
        self.cfg = cfg
        self.register_buffer("mean", torch.from_numpy(normalizer.mean))
        self.register_buffer("std", torch.from_numpy(normalizer.std))
        self.register_buffer("com_w", torch.from_numpy(COM_WEIGHTS).float())
        self.register_buffer("offsets", torch.from_numpy(sk.REST_OFFSETS).float())

    def joints(self, feats: torch.Tensor) -> torch.Tensor:
        """Denormalised features (B, T, 239) → root-relative joints (B, T, 22, 3), metres."""
        b, t, _ = feats.shape
        pelvis = F.pad(feats[..., SLICES["root_height"]], (1, 1))      # (0, h, 0)
        rest = feats[..., SLICES["positions"]].reshape(b, t, sk.NUM_JOINTS - 1, 3)
        return torch.cat([pelvis[:, :, None], rest], 2)

    def com_terms(self, j: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
        """CODA eq. 4 quantities: pelvis→COM distance (B, T) and the cosine of its elevation."""
        v = torch.einsum("j,btjd->btd", self.com_w, j) - j[:, :, sk.PELVIS]
        dist = v.norm(dim=-1)
        cos = v[..., [0, 2]].norm(dim=-1) / (dist + 1e-6)
        return dist, cos

    def forward(self, pred: torch.Tensor, target: torch.Tensor, commit: torch.Tensor,
                beta: float) -> dict[str, torch.Tensor]:
        """pred, target: normalised features (B, T, 239). Returns the terms and their sum
        under "loss" (geometric terms only when cfg.geometric)."""
        out = {"recon": F.l1_loss(pred, target), "commit": commit}
        total = out["recon"] + beta * commit
        if self.cfg.geometric:
            c = self.cfg
            s = c.joint_scale
            fp, ft = pred * self.std + self.mean, target * self.std + self.mean
            jp, jt = self.joints(fp), self.joints(ft)
            out["velocity"] = F.l1_loss(jp[:, 1:] - jp[:, :-1], jt[:, 1:] - jt[:, :-1]) * s
            vel = fp[..., SLICES["velocities"]].reshape(*fp.shape[:2], sk.NUM_JOINTS, 3)
            foot_speed = vel[:, :, list(sk.FOOT_JOINTS)].norm(dim=-1)   # (B, T, 4) m/frame
            contact = (ft[..., SLICES["foot_contacts"]] > 0.5).float()
            out["foot"] = (foot_speed * contact).sum() / contact.sum().clamp_min(1.0) * s
            bp = (jp[:, :, _CHILD] - jp[:, :, _PARENT]).norm(dim=-1)
            bt = (jt[:, :, _CHILD] - jt[:, :, _PARENT]).norm(dim=-1)
            out["bone"] = F.l1_loss(bp, bt) * s
            (dp, cp), (dt, ct) = self.com_terms(jp), self.com_terms(jt)
            out["com"] = F.mse_loss(dp * s, dt * s) + F.mse_loss(cp, ct)
            key = list(sk.KEY_JOINTS)
            out["ktraj"] = F.l1_loss(jp[:, :, key], jt[:, :, key]) * s
            out["fk"] = F.l1_loss(fk_joints(fp, self.offsets), fk_joints(ft, self.offsets)) * s
            total = total + (c.w_velocity * out["velocity"] + c.w_foot * out["foot"]
                             + c.w_bone * out["bone"] + c.w_com * out["com"]
                             + c.w_ktraj * out["ktraj"] + c.w_fk * out["fk"])
        out["loss"] = total
        return out
