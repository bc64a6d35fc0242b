"""Frozen configs of CODA, scaled from the paper's (d' = 512, |C| = |P| = 1024, 6 blocks × 384)
to ~3k training pair windows and a shared 2-core CPU. Checkpoints store asdict(cfg)
(`models.common.checkpoint`).

Shapes: a person is (B, T, 66) joints (22 × xyz, metres) in the pair's canonical frame
(first person's pelvis at the XZ origin facing +Z at frame 0), normalised by one mean/std
shared by both people; T = 4n frames ↔ n pose tokens per person.
"""

from __future__ import annotations

from dataclasses import dataclass

POSE_DIM = 66          # 22 joints × 3
TEXT_DIM = 384         # MiniLM sentence embedding
WINDOW = 80            # frames per training window (4 s at 20 fps) → 20 tokens per person
FPS = 20


@dataclass(frozen=True)
class CVQConfig:
    ics: bool = True              # False: the single-codebook ablation (decoder reads t only)
    codes: int = 512              # |C| pose codes
    interaction_codes: int = 256  # |P| interaction codes
    latent: int = 64              # d' code dimension
    width: int = 64               # conv channels of φ and the decoders
    depth: int = 2                # residual blocks per down/up stage
    downsample: int = 4           # frames per token (two stride-2 stages)
    heads: int = 4                # ICS attention heads
    rel_range: int = 8            # relative time offsets ±rel_range get their own bias
    alpha: float = 0.02           # commitment weight of the pose codebook (eq. 3)
    beta: float = 0.02            # commitment weight of the interaction codebook (eq. 3)
    ema_decay: float = 0.99
    dead_fraction: float = 0.7    # EMA usage below this share of the mean → code reset


@dataclass(frozen=True)
class LossConfig:
    """CCL weights (Algorithm 1; the paper's λ as the starting point) and the geometric terms.
    Every joint term is in metres on de-normalised joints (foot/velocity in m per frame)."""
    w_com: float = 1.0            # eq. 4
    w_ktraj: float = 1.0          # eq. 5 (pelvis, wrists, toes)
    w_gdm: float = 0.5            # eq. 6, τ = 0.5
    w_ppl: float = 0.01           # eq. 7
    w_velocity: float = 1.0       # L1 of joint displacements between frames
    w_foot: float = 1.0           # foot displacement where the target foot is planted
    w_bone: float = 1.0           # L1 of bone lengths
    w_common: float = 1.0         # the commonsense decoder's reconstruction (eq. 3, 3rd term)
    tau: float = 0.5
    gdm_frame_stride: int = 2     # GDM on every 2nd frame (22×22 distances per frame)
    ppl_frame_stride: int = 8     # PPL on every 8th frame (21×21 segment pairs per frame: the
                                  # costliest term, 1.8 s a step on every 2nd frame)


@dataclass(frozen=True)
class CMTConfig:
    codes: int = 512              # K (= |C|); mask id = K
    d: int = 128
    heads: int = 4
    blocks: int = 4
    ff: int = 2
    dropout: float = 0.1
    max_tokens: int = 50          # n per person the position tables allow (10 s)
    rel_range: int = 16           # relative time buckets (same person / across people)
    text_dim: int = TEXT_DIM

    @property
    def mask_id(self) -> int:
        return self.codes


@dataclass(frozen=True)
class TrainConfig:
    seconds: float = 300.0        # wall-clock budget (steps stop at whichever comes first)
    steps: int = 100_000
    batch: int = 32               # pair windows per step
    lr: float = 1e-3
    warmup: int = 50
    cond_drop: float = 0.1        # CMT: text dropped to zeros (classifier-free guidance)
    seed: int = 0
    log_every: int = 50

