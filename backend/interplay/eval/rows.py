"""The rows `interplay eval` compares. Each row turns the test samples into motions:

  real       the captured test motions themselves
  retrieval  the retrieval generator (`agents.generator`) over the TRAIN clips only, so it
             cannot return a test capture
  spam       SPAM (`agents.spam.SpamRuntime`), models/weights/spam, as shipped (int8 transformers)
  spam_fp32  the same weights with the float transformers (what the int8 graphs quantize)
  spam_nolock  the shipped SPAM without holding planted feet (`footlock.lock_feet`)
  spam_nocs  SPAM trained without the commonsense losses, models/weights/spam_nocs
  spam_vq    reconstruction: test motions encoded and decoded by SPAM's part RVQ-VAE
  single_vq  reconstruction: the same through the single-codebook (whole-body) VQ ablation

A row whose weights are missing (or are the untrained placeholder) is skipped with the reason.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

from interplay.motion import features as F
from interplay.motion.kinematics import fit_offsets
from interplay.motion.skeleton import FPS

WEIGHTS = Path(__file__).resolve().parents[3] / "models" / "weights"
ROW_NAMES = ("real", "retrieval", "spam", "spam_fp32", "spam_nolock", "spam_nocs", "spam_vq",
             "single_vq")
# Directories the single-codebook ablation may be exported to (first found wins).
SINGLE_VQ_DIRS = ("spam_single", "single_vq", "vq_single")

Generate = Callable[[str, int, int], np.ndarray]          # (text, frames, seed) → (frames, 22, 3)
Reconstruct = Callable[[np.ndarray], np.ndarray]          # joints (T, 22, 3) → joints (T, 22, 3)
# (joints, parts, prompt, seed, context) → joints; context = the base motion's prompt, which
# the parts left alone keep (SpamRuntime.edit's `context`)
Edit = Callable[[np.ndarray, list, str, int, str], np.ndarray]


@dataclass(frozen=True)
class Row:
    name: str
    kind: str                            # "real" | "generated" | "reconstruction"
    generate: Generate | None = None
    reconstruct: Reconstruct | None = None
    edit: Edit | None = None
    source: str = ""                     # where the weights/data came from


class Skip(Exception):
    """A row that cannot run here; the message says why."""


def _trained(weights: Path) -> None:
    """Raise Skip unless `weights` holds trained SPAM-style graphs."""
    if not (weights / "config.json").is_file():
        raise Skip(f"no weights in {weights.relative_to(WEIGHTS.parents[1])}")
    card = weights / "MODEL_CARD.md"
    text = card.read_text().lower() if card.is_file() else ""
    if "untrained" in text or "placeholder" in text:
        raise Skip(f"{weights.relative_to(WEIGHTS.parents[1])} holds untrained placeholder graphs")


def _retrieval(clips) -> Row:
    from interplay.generators.base import Request
    from interplay.generators.retrieval.generator import RetrievalGenerator
    from interplay.generators.retrieval.index import RetrievalIndex
    from interplay.text.encoder import get_encoder
    gen = RetrievalGenerator(RetrievalIndex([c for c in clips if c.split == "train"], get_encoder()))

    def generate(text: str, frames: int, seed: int) -> np.ndarray:
        req = Request(text, persons=1, seconds=frames / FPS, seed=seed)
        out = np.concatenate([c[0] for _, c in gen.stream(req, gen.plan(req))])
        return out[:frames].astype(np.float64)
    return Row("retrieval", "generated", generate=generate, source="train-split captures")


def _spam(name: str, weights: Path, precision: str | None = None, sampling=None,
          foot_lock: bool = True) -> Row:
    """SPAM's runtime; `sampling` overrides generation/edit settings (cfg, steps, temperature,
    and for edits mode) — for `interplay eval --split val --sampling …`."""
    sampling = dict(sampling or {})
    edit_kw = {k: sampling.pop(k) for k in ("mode", "keep_noise") if k in sampling}
    _trained(weights)
    from interplay.generators.spam.runtime import SpamRuntime
    try:
        rt = SpamRuntime.load(weights, threads=1, precision=precision, foot_lock=foot_lock)
    except FileNotFoundError as exc:
        raise Skip(str(exc)) from None

    def edit(joints, parts, prompt, seed, context):
        return rt.edit_parts(joints, parts, prompt, seed, context=context, **sampling, **edit_kw)
    return Row(name, "generated",
               generate=lambda text, frames, seed: rt.generate(text, frames, seed, **sampling),
               edit=edit, source=str(weights.relative_to(WEIGHTS.parents[1])))


def _vq(name: str, weights: Path) -> Row:
    """Encode → decode through a VQ-VAE's exported graphs (vq_encode/vq_decode.onnx)."""
    _trained(weights)
    for f in ("vq_encode.onnx", "vq_decode.onnx", "normalizer.npz"):
        if not (weights / f).is_file():
            raise Skip(f"{weights.name}: {f} missing")
    import onnxruntime as ort
    opts = ort.SessionOptions()
    opts.intra_op_num_threads, opts.inter_op_num_threads = 1, 1
    enc, dec = (ort.InferenceSession(str(weights / f), sess_options=opts,
                                     providers=["CPUExecutionProvider"])
                for f in ("vq_encode.onnx", "vq_decode.onnx"))
    norm = F.Normalizer.load(weights / "normalizer.npz")
    ds = 4

    def reconstruct(joints: np.ndarray) -> np.ndarray:
        t = len(joints)
        offsets = fit_offsets(joints)
        feats = F.encode(joints, offsets)
        pad = -t % ds
        x = norm.normalize(np.concatenate([feats, np.repeat(feats[-1:], pad, axis=0)]))
        (codes,) = enc.run(None, {"motion": x[None].astype(np.float32)})
        (out,) = dec.run(None, {"codes": codes})
        return F.decode(norm.denormalize(out[0])[:t], offsets, F.start_of(joints))
    return Row(name, "reconstruction", reconstruct=reconstruct,
               source=str(weights.relative_to(WEIGHTS.parents[1])))


def load_row(name: str, clips, sampling: dict | None = None) -> Row:
    """The row called `name`; raises Skip when its weights are not here. `sampling` goes to
    the SPAM rows (see `_spam`)."""
    if name == "real":
        return Row("real", "real", source="test split captures")
    if name == "retrieval":
        return _retrieval(clips)
    if name in ("spam", "spam_nocs"):
        return _spam(name, WEIGHTS / name, sampling=sampling)
    if name == "spam_fp32":
        return _spam(name, WEIGHTS / "spam", precision="fp32", sampling=sampling)
    if name == "spam_nolock":
        return _spam(name, WEIGHTS / "spam", sampling=sampling, foot_lock=False)
    if name == "spam_vq":
        return _vq(name, WEIGHTS / "spam")
    if name == "single_vq":
        found = [WEIGHTS / d for d in SINGLE_VQ_DIRS if (WEIGHTS / d).is_dir()]
        if not found:
            raise Skip("the single-codebook VQ ablation is not exported "
                       f"(looked for models/weights/{{{','.join(SINGLE_VQ_DIRS)}}})")
        return _vq(name, found[0])
    raise ValueError(f"unknown row {name!r}; expected some of {', '.join(ROW_NAMES)}")
