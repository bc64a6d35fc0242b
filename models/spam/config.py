"""Frozen configs of SPAM (CoMA §4.2, appendix E): the body-part residual VQ-VAE and the two
masked transformers, plus the training budgets. Sizes are scaled down from the paper (6 × 512
codes of 128 dims, 9 layers × 512 wide) to ~30k training frames and a 2-core CPU.

Checkpoints store {"model": state_dict, "config": asdict(cfg)} (`models.common.checkpoint`).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

FEATURE_DIM = 239          # interplay.motion.features.FEATURE_DIM
TEXT_DIM = 384             # MiniLM sentence embedding
PARTS = ("left_upper", "right_upper", "left_lower", "right_lower")  # token order everywhere


@dataclass(frozen=True)
class VQConfig:
    parts: bool = True            # False: the single-codebook (whole-body) ablation, one stack
    codes: int = 512              # K codes per quantizer layer
    layers: int = 6               # Q residual layers (layer 0 = base)
    latent: int = 64              # code dimension per part
    width: int = 128              # conv channels
    depth: int = 2                # residual blocks per down/up stage
    downsample: int = 4           # frames per token (two stride-2 stages)
    beta: float = 0.02            # commitment weight (MoMask)
    ema_decay: float = 0.99
    dead_fraction: float = 0.7    # EMA usage below this share of the mean → code reset
    quantizer_dropout: float = 0.2

    @property
    def streams(self) -> int:
        """How many encoders/quantizer stacks: 4 parts, or 1 for the whole-body ablation."""
        return len(PARTS) if self.parts else 1


@dataclass(frozen=True)
class TransformerConfig:
    codes: int = 512              # K (must match the VQ); mask_id = K
    layers_q: int = 6             # Q of the VQ (the residual model predicts layers 1..Q-1)
    d: int = 256
    heads: int = 4
    blocks: int = 4               # factorised blocks (spatial + temporal attention + MLP)
    ff: int = 4                   # MLP width multiplier
    dropout: float = 0.1
    max_tokens: int = 50          # 10 s at 20 fps / 4
    text_dim: int = TEXT_DIM
    residual: bool = False        # False: base model; True: residual model

    @property
    def mask_id(self) -> int:
        return self.codes


@dataclass(frozen=True)
class LossConfig:
    geometric: bool = True        # velocity, foot contact, bone length, COM, key-joint trajectory
    w_velocity: float = 0.5       # on root-relative joint velocities, m
    w_foot: float = 0.5           # predicted foot displacement where the data has contact, m
    w_bone: float = 0.5           # bone length error, m
    w_com: float = 1.0            # CODA eq. 4 (distance in m, angle as a cosine)
    w_ktraj: float = 1.0          # CODA eq. 5 on KEY_JOINTS, m
    w_fk: float = 1.0             # joints by FK of the decoded rotations (rest skeleton), m
    joint_scale: float = 10.0     # metres → decimetres, so joint losses weigh like feature L1


@dataclass(frozen=True)
class TrainConfig:
    seconds: float = 600.0        # wall-clock budget of a stage (steps stop at whichever first)
    steps: int = 100_000
    batch: int = 64
    lr: float = 2e-4
    warmup: int = 200
    part_prompt_share: float = 0.5  # share of samples with per-part caption prompts
    cond_drop: float = 0.1        # classifier-free guidance dropout
    seed: int = 0
    log_every: int = 50


@dataclass(frozen=True)
class SamplingDefaults:
    """Written to config.json for the runtime loops (CoMA E.1: CFG 4 base, 5 residual, 10 steps;
    the base scale is 2.5 here: on the validation split it gave R@1 0.70 / FID 0.39 / foot
    skating 0.30 m/s against 0.55 / 0.48 / 0.39 at 4, `docs/eval.md`)."""
    cfg_base: float = 2.5
    cfg_residual: float = 5.0
    steps: int = 10
    temperature: float = 1.0
    topk_ratio: float = 0.9


def runtime_config(vq: VQConfig, base: TransformerConfig,
                   sampling: SamplingDefaults | None = None, trained: bool = True,
                   precision: str = "fp32") -> dict:
    """The config.json next to the ONNX graphs: what the numpy sampling loops need
    ("trained": false marks placeholder exports the runtime must not serve)."""
    sampling = sampling or SamplingDefaults()
    return {
        "trained": trained,
        "K": vq.codes, "Q": vq.layers, "d": base.d, "latent": vq.latent,
        "max_tokens": base.max_tokens, "mask_id": base.mask_id, "downsample": vq.downsample,
        "feature_dim": FEATURE_DIM, "text_dim": base.text_dim, "parts": list(PARTS),
        "cfg": asdict(sampling),
        "precision": precision,   # "int8": the runtime loads base/residual.int8.onnx
    }
