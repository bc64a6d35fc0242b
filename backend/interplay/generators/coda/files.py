"""CODA's exported files (models/coda → models/weights/coda), checked against the contract:

    encode.onnx  x (B, T, 66) float32 normalised joints of one person → codes (B, T/4) int64
    decode.onnx  codes_a, codes_b (B, n) int64 → x_a, x_b (B, 4n, 66) float32 normalised
                 (the interaction-codebook residual is inside the graph)
    cmt.onnx     codes (B, 2, n) int64 (K = [MASK]), text (B, 384) float32 (zeros =
                 unconditional) → logits (B, 2, n, K)
    config.json  {"trained", "codes": K, "interaction_codes", "downsample": 4, "max_tokens",
                  "mask_id", "fps": 20, "dim": 66,
                  "sampling": {"steps", "cfg", "temperature", "topk"}}
    normalizer.npz  mean, std (66,)

Joints are in the pair's canonical frame: the first person's pelvis at the XZ origin facing +Z
on frame 0, 22 SMPL joints, Y up, metres.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, fields
from pathlib import Path

import numpy as np

from interplay.generators.spam.files import OnnxGraph
from interplay.motion import skeleton as sk
from interplay.settings import REPO_ROOT

DEFAULT_DIR = REPO_ROOT / "models" / "weights" / "coda"
GRAPHS: dict[str, tuple[str, ...]] = {
    "encode": ("x",),
    "decode": ("codes_a", "codes_b"),
    "cmt": ("codes", "text"),
}
FILES = ("config.json", "normalizer.npz") + tuple(f"{g}.onnx" for g in GRAPHS)


@dataclass(frozen=True)
class CodaConfig:
    codes: int                       # K: motion codebook size (the [MASK] id is K)
    max_tokens: int                  # the transformer's positional range
    interaction_codes: int = 0       # informational: the interaction codebook inside decode
    downsample: int = 4              # frames per token
    mask_id: int = -1                # -1: K
    fps: int = sk.FPS
    dim: int = sk.NUM_JOINTS * 3
    trained: bool = True
    steps: int = 10                  # masked decoding steps
    cfg: float = 3.0                 # classifier-free guidance scale
    temperature: float = 1.0
    topk: float = 0.9                # < 1: MoMask's filter ratio; ≥ 1: a number of codes kept
    # Tokens per generated window: the length the transformer was trained at (80-frame pair
    # windows = 20 tokens in models/coda), although its relative-time bias runs up to
    # max_tokens. config.json "window_tokens" overrides.
    window_tokens: int = 20

    def __post_init__(self):
        if self.mask_id == -1:
            object.__setattr__(self, "mask_id", self.codes)
        if self.codes < 2 or self.max_tokens < 2 or self.downsample < 1 or self.steps < 1:
            raise ValueError(f"implausible CODA config: {self}")
        object.__setattr__(self, "window_tokens", max(2, min(self.window_tokens, self.max_tokens)))
        if self.dim != sk.NUM_JOINTS * 3:
            raise ValueError(f"CODA weights are for {self.dim}-d frames; this code uses 66")
        if self.fps != sk.FPS:
            raise ValueError(f"CODA weights are for {self.fps} fps; this code uses {sk.FPS}")

    @property
    def topk_ratio(self) -> float:
        """The filter as masked_decoding.top_k takes it (share of codes dropped)."""
        if self.topk < 1:
            return float(self.topk)
        return max(0.0, 1.0 - float(self.topk) / self.codes)

    @property
    def max_frames(self) -> int:
        """Frames of one generated window."""
        return self.window_tokens * self.downsample

    @classmethod
    def from_json(cls, d: dict) -> "CodaConfig":
        if not isinstance(d, dict) or not {"codes", "max_tokens"} <= set(d):
            raise ValueError("CODA config.json needs at least codes and max_tokens")
        known = {f.name for f in fields(cls)}
        kw = {k: v for k, v in d.items() if k in known}
        for k, v in (d.get("sampling") or {}).items():
            if k in ("steps", "cfg", "temperature", "topk"):
                kw[k] = v
        return cls(**kw)


class Normalizer:
    """Per-dimension mean/std of the 66-d joint frames."""

    def __init__(self, mean: np.ndarray, std: np.ndarray):
        self.mean = np.asarray(mean, np.float64).reshape(-1)
        self.std = np.asarray(std, np.float64).reshape(-1)
        if self.mean.shape != (sk.NUM_JOINTS * 3,) or self.std.shape != self.mean.shape:
            raise ValueError(f"normalizer is not for 22 × 3 joints: {self.mean.shape}")

    def normalize(self, joints: np.ndarray) -> np.ndarray:
        """(..., 22, 3) metres → (..., 66) float32."""
        flat = np.asarray(joints).reshape(*np.shape(joints)[:-2], -1)
        return ((flat - self.mean) / self.std).astype(np.float32)

    def denormalize(self, x: np.ndarray) -> np.ndarray:
        """(..., 66) → (..., 22, 3) float64 metres."""
        out = np.asarray(x, np.float64) * self.std + self.mean
        return out.reshape(*out.shape[:-1], sk.NUM_JOINTS, 3)


def load_files(weights_dir: str | Path, threads: int = 2):
    """(CodaConfig, Normalizer, {name: OnnxGraph}); FileNotFoundError / ValueError saying what
    is wrong."""
    root = Path(weights_dir)
    if not root.is_dir():
        raise FileNotFoundError(f"{root}: no CODA weights directory")
    missing = [n for n in FILES if not (root / n).is_file()]
    if missing:
        raise FileNotFoundError(f"{root}: missing {', '.join(missing)}")
    try:
        config = CodaConfig.from_json(json.loads((root / "config.json").read_text()))
    except (json.JSONDecodeError, TypeError) as exc:
        raise ValueError(f"{root / 'config.json'}: {exc}") from None
    with np.load(root / "normalizer.npz") as z:
        normalizer = Normalizer(z["mean"], z["std"])
    graphs = {}
    for name, inputs in GRAPHS.items():
        try:
            graphs[name] = OnnxGraph(root / f"{name}.onnx", inputs, threads)
        except ValueError:
            raise
        except Exception as exc:  # onnxruntime's own errors: a broken or foreign file
            raise ValueError(f"{root / (name + '.onnx')}: cannot load ({exc})") from None
    return config, normalizer, graphs
