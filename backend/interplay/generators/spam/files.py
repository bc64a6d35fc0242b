"""SPAM's exported files: `config.json`, `normalizer.npz` and four ONNX graphs, checked against
the contract the training code exports (models/spam/export.py):

    vq_encode.onnx  motion (B, T, 239) float32 normalised      → codes (B, 4, Q, T/4) int64
    vq_decode.onnx  codes (B, 4, Q, n) int64                    → motion (B, 4n, 239) float32
    base.onnx       tokens (B, 4, n) int64, text (B, 4, 384) float32, cond (B,) float32
                                                                → logits (B, 4, n, K)
    residual.onnx   tokens (B, 4, Q, n) int64, layer (B,) int64, text, cond → logits (B, 4, n, K)

base.int8.onnx / residual.int8.onnx: the same transformers with int8 weights, loaded instead
when config.json says "precision": "int8" (or the caller asks for it).
Sessions are built once, two intra-op threads each (this is a 2-core CPU).
"""

from __future__ import annotations

import json
from dataclasses import dataclass, fields
from pathlib import Path

import numpy as np

from interplay.motion.features import FEATURE_DIM

PRECISIONS = ("fp32", "int8")
INT8_GRAPHS = ("base", "residual")   # the transformers; the VQ graphs stay float
GRAPH_INPUTS: dict[str, tuple[str, ...]] = {
    "vq_encode": ("motion",),
    "vq_decode": ("codes",),
    "base": ("tokens", "text", "cond"),
    "residual": ("tokens", "layer", "text", "cond"),
}


@dataclass(frozen=True)
class SpamConfig:
    K: int                       # codes per part codebook
    Q: int                       # quantizer layers (base + Q−1 residual)
    d: int                       # model width (informational here)
    max_tokens: int = 50         # positional range of the transformers (50 tokens = 10 s)
    mask_id: int = -1            # the [MASK] token id (= K)
    downsample: int = 4          # frames per token
    feature_dim: int = FEATURE_DIM
    text_dim: int = 384
    cfg: float = 4.0             # base-layer guidance scale
    cfg_residual: float = 5.0    # residual-layer guidance scale
    steps: int = 10              # masked decoding steps
    temperature: float = 1.0
    topk_ratio: float = 0.9      # sample from the top (1 − ratio)·K codes only (MoMask)
    precision: str = "fp32"      # "int8": base/residual from <graph>.int8.onnx (quantized)

    def __post_init__(self):
        if self.mask_id == -1:
            object.__setattr__(self, "mask_id", self.K)
        if self.K < 2 or self.Q < 1 or self.max_tokens < 1 or self.downsample < 1:
            raise ValueError(f"implausible SPAM config: {self}")
        if self.precision not in PRECISIONS:
            raise ValueError(f"precision must be one of {PRECISIONS}, got {self.precision!r}")
        if self.feature_dim != FEATURE_DIM:
            raise ValueError(f"SPAM weights are for {self.feature_dim}-d features; this code "
                             f"encodes {FEATURE_DIM}-d features")

    @property
    def max_frames(self) -> int:
        return self.max_tokens * self.downsample

    @classmethod
    def from_json(cls, d: dict) -> "SpamConfig":
        """From config.json (models/spam/config.py `runtime_config`): sampling defaults sit
        under "cfg" ({"cfg_base", "cfg_residual", "steps", "temperature", "topk_ratio"});
        unknown keys are ignored."""
        if not isinstance(d, dict) or not {"K", "Q"} <= set(d):
            raise ValueError("SPAM config.json needs at least K and Q")
        known = {f.name for f in fields(cls)}
        kw = {k: v for k, v in d.items() if k in known and k != "cfg"}
        sampling = d.get("cfg") or {}
        if isinstance(sampling, (int, float)):
            sampling = {"cfg_base": sampling}
        renames = {"cfg_base": "cfg", "cfg_residual": "cfg_residual", "steps": "steps",
                   "temperature": "temperature", "topk_ratio": "topk_ratio"}
        for src, dst in renames.items():
            if src in sampling:
                kw[dst] = sampling[src]
        kw.setdefault("d", 0)
        return cls(**kw)


class OnnxGraph:
    """One ONNX session: `graph(**inputs) -> first output`, inputs checked by name."""

    def __init__(self, path: Path, expected: tuple[str, ...], threads: int = 2, spin: bool = False):
        import onnxruntime as ort

        opts = ort.SessionOptions()
        opts.intra_op_num_threads = threads
        opts.inter_op_num_threads = 1
        opts.graph_optimization_level = ort.GraphOptimizationLevel.ORT_ENABLE_ALL
        # Idle worker threads spin by default; on a 2-core machine they then take the core the
        # sampling loop needs between graph calls.
        opts.add_session_config_entry("session.intra_op.allow_spinning", "1" if spin else "0")
        self.path = Path(path)
        self.session = ort.InferenceSession(str(path), sess_options=opts,
                                            providers=["CPUExecutionProvider"])
        names = {i.name for i in self.session.get_inputs()}
        if not set(expected) <= names:
            raise ValueError(f"{path.name}: inputs {sorted(names)} do not match the contract "
                             f"{list(expected)}")
        self.inputs = tuple(i.name for i in self.session.get_inputs())
        self.output = self.session.get_outputs()[0].name

    def __call__(self, **feeds: np.ndarray) -> np.ndarray:
        return self.session.run([self.output], {k: feeds[k] for k in self.inputs})[0]


def graph_file(name: str, precision: str) -> str:
    return f"{name}.int8.onnx" if precision == "int8" and name in INT8_GRAPHS else f"{name}.onnx"


def load_files(weights_dir: str | Path, threads: int = 2, precision: str | None = None):
    """(SpamConfig, Normalizer, {graph name: OnnxGraph}) from a weights directory, with the
    transformers of `precision` (None: config.json's); ValueError (FileNotFoundError for a
    missing file) saying what is wrong."""
    from interplay.motion.features import Normalizer

    root = Path(weights_dir)
    if not root.is_dir():
        raise FileNotFoundError(f"{root}: no SPAM weights directory")
    if not (root / "config.json").is_file():
        raise FileNotFoundError(f"{root}: missing config.json")
    try:
        raw = json.loads((root / "config.json").read_text())
        config = SpamConfig.from_json({**raw, "precision": precision or raw.get("precision", "fp32")}
                                      if isinstance(raw, dict) else raw)
    except (json.JSONDecodeError, TypeError) as exc:
        raise ValueError(f"{root / 'config.json'}: {exc}") from None
    files = {g: graph_file(g, config.precision) for g in GRAPH_INPUTS}
    missing = [n for n in ["normalizer.npz", *files.values()] if not (root / n).is_file()]
    if missing:
        raise FileNotFoundError(f"{root}: missing {', '.join(missing)}")
    normalizer = Normalizer.load(root / "normalizer.npz")
    graphs = {}
    for name, inputs in GRAPH_INPUTS.items():
        try:
            graphs[name] = OnnxGraph(root / files[name], inputs, threads)
        except ValueError:
            raise
        except Exception as exc:  # onnxruntime's own errors: a broken or foreign file
            raise ValueError(f"{root / files[name]}: cannot load ({exc})") from None
    return config, normalizer, graphs
