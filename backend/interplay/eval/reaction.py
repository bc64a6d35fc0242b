"""`interplay eval-react`: ARFlow reactions on held-out pairs against the captured reactions.

Test set: every 2 s window (40 frames, stride 20) of the test split's two-person clips, both
role orders (each person is once the actor), in the actor's first-frame heading frame. Real
(captured salsa) and composed (synthetic) pairs are reported separately.

Rows: real (the captured reactor), no_guidance (plain Euler x-prediction sampling),
guidance (penetration guidance on x̂₁, γ = 1: the plain Euler step from the guided x̂₁) and
guidance_reproject (guidance + ARFlow's reprojection towards the real start, γ < 1).

FID: the learned pair evaluator (`agents.pair_evaluator`, contrastive text ↔ pair windows
trained on the train split): each (actor, reactor) window is embedded as a pair and FID is the
Fréchet distance between the generated and the captured test windows' embeddings; the real
row compares the train split's windows of the same set (captured or composed) with the test
split's (a floor for the
set size and the split shift). `fid_stats` is the earlier statistics FID, kept as a second
column for continuity: each window embedded by statistics of the reactor and of the pair (the
reactor's joints in the actor's frame: mean and std over time; its mean joint speeds; the
relative root: mean and std; the mean pelvis/hands/feet distance map), standardised and
PCA-reduced to 16 dims, both fitted on the train split's windows.
IV (mean cm³ per frame), IF (share of frames), contact frames (hand within 3 cm of the other's
body) and foot skating (m/s of planted feet) are `motion.metrics.clip_metrics` on the pair.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.kinematics import fit_to_skeleton
from interplay.motion.metrics import clip_metrics, person_metrics
from interplay.motion.pair.windows import distance_map, pair_windows, relative_root
from interplay.reaction.session import (
    ReactionModel,
    SamplingConfig,
    get_reaction_model,
    sample_windows,
)
from interplay.review.pair_evaluator import PairEvaluator, load_pair_evaluator

WINDOW, STRIDE, PCA_DIMS = 40, 20, 16
ROWS = ("real", "no_guidance", "guidance", "guidance_reproject")


@dataclass
class TestPairs:
    actor: np.ndarray      # (N, L, 22, 3)
    reactor: np.ndarray    # (N, L, 22, 3) captured
    text: np.ndarray       # (N, 384)
    synthetic: np.ndarray  # (N,) bool
    kind: np.ndarray       # (N,) str: "salsa" or the composed clip's kind (hug, handshake, …)


def test_pairs(split: str = "test", stride: int = STRIDE, clips=None) -> TestPairs:
    from interplay.motion.clip import default_clips
    from interplay.reaction.session import prompt_embedding
    clips = [c for c in (clips or default_clips()) if c.split == split and len(c.people) == 2]
    w = pair_windows(clips, WINDOW, stride, roles="both", mirror=False)
    prompts = {c.id: c.prompt for c in clips}
    kinds = {c.id: (c.meta.get("kind", c.label) if c.synthetic else "salsa") for c in clips}
    table = {i: prompt_embedding(prompts[i]) for i in set(w.clip_ids)}
    text = np.stack([table[i] for i in w.clip_ids]) if len(w) else np.zeros((0, 384), np.float32)
    return TestPairs(w.joints[:, 0].astype(np.float64), w.joints[:, 1].astype(np.float64),
                     text, w.synthetic, np.array([kinds[i] for i in w.clip_ids], dtype=object))


def window_stats(actor: np.ndarray, reactor: np.ndarray) -> np.ndarray:
    """Raw embedding (N, 2·66 + 22 + 8 + 25) of pair windows (N, L, 22, 3) (see module doc)."""
    out = []
    for a, r in zip(actor, reactor):
        flat = r.reshape(len(r), -1)
        speed = np.linalg.norm(np.diff(r, axis=0), axis=-1).mean(axis=0) * sk.FPS
        rel = relative_root(a, r)
        dmap = distance_map(a, r, sk.KEY_JOINTS).mean(axis=0).ravel()
        out.append(np.concatenate([flat.mean(0), flat.std(0), speed, rel.mean(0), rel.std(0), dmap]))
    return np.asarray(out)


class Embedding:
    """Standardise + PCA (fitted on reference windows) → (N, dims)."""

    def __init__(self, reference: np.ndarray, dims: int = PCA_DIMS):
        self.mean, self.std = reference.mean(0), reference.std(0) + 1e-6
        z = (reference - self.mean) / self.std
        _, _, vt = np.linalg.svd(z - z.mean(0), full_matrices=False)
        self.basis = vt[:dims].T

    def __call__(self, stats: np.ndarray) -> np.ndarray:
        return ((stats - self.mean) / self.std) @ self.basis


def fid(a: np.ndarray, b: np.ndarray) -> float:
    """Fréchet distance between Gaussians fitted to embeddings a, b (N, D)."""
    mu1, mu2 = a.mean(0), b.mean(0)
    s1, s2 = np.cov(a, rowvar=False), np.cov(b, rowvar=False)
    # tr sqrt(s1 s2) from the eigenvalues of sqrt(s1) s2 sqrt(s1) (symmetric, PSD)
    w, v = np.linalg.eigh(s1)
    r1 = (v * np.sqrt(np.clip(w, 0, None))) @ v.T
    ev = np.linalg.eigvalsh(r1 @ s2 @ r1)
    return float(np.sum((mu1 - mu2) ** 2) + np.trace(s1) + np.trace(s2)
                 - 2 * np.sum(np.sqrt(np.clip(ev, 0, None))))


SCORES = ("iv_cm3", "if", "contact_frames", "foot_skating", "bone_deviation")


def window_scores(actor: np.ndarray, reactor: np.ndarray) -> np.ndarray:
    """Per window (N, 5): IV, IF, contact frames, reactor foot skating and bone deviation."""
    rows = []
    for a, r in zip(actor, reactor):
        m = clip_metrics([a, r])
        p = person_metrics(r)
        rows.append([m["intersection_volume"], m["intersection_frequency"], m["contact_frames"],
                     p["foot_skating"], p["bone_deviation"]])
    return np.asarray(rows, dtype=np.float64).reshape(-1, len(SCORES))


def pair_scores(actor: np.ndarray, reactor: np.ndarray, kinds: np.ndarray | None = None) -> dict:
    """Mean scores over the windows; with kinds (N,) also "per_kind": {kind: {iv_cm3, if}}."""
    rows = window_scores(actor, reactor)
    out: dict[str, Any] = dict(zip(SCORES, map(float, rows.mean(axis=0))))
    if kinds is not None:
        out["per_kind"] = {str(k): {"iv_cm3": float(rows[kinds == k, 0].mean()),
                                    "if": float(rows[kinds == k, 1].mean())}
                           for k in sorted(set(kinds))}
    return out


def generate(model: ReactionModel, pairs: TestPairs, row: str, seed: int,
             sampling: SamplingConfig | None = None) -> np.ndarray:
    """The row's reactors (N, L, 22, 3), put on fixed bone lengths (IK → FK per window)."""
    cfg = sampling or model.sampling
    if row == "no_guidance":
        raw = sample_windows(model, pairs.actor, pairs.text, seed, guidance=False, sampling=cfg)
    elif row == "guidance":
        raw = sample_windows(model, pairs.actor, pairs.text, seed, guidance=True, reproject=False,
                             sampling=cfg)
    elif row == "guidance_reproject":
        raw = sample_windows(model, pairs.actor, pairs.text, seed, guidance=True, reproject=True,
                             sampling=cfg)
    else:
        raise ValueError(f"unknown row {row!r}; expected one of {ROWS}")
    return np.stack([fit_to_skeleton(r)[0] for r in raw])


def pair_embedding(ev: PairEvaluator, actor: np.ndarray, reactor: np.ndarray) -> np.ndarray:
    """Pair evaluator embeddings (N, E) of windows with the actor as the first person."""
    return ev.embed(np.stack([actor, reactor], axis=1))


def run_eval_react(rows=ROWS, repeats: int = 2, seed: int = 0, model: ReactionModel | None = None,
                   sampling: SamplingConfig | None = None, split: str = "test", log=None,
                   evaluator: PairEvaluator | None = None) -> dict:
    model = model or get_reaction_model()
    ev = evaluator or load_pair_evaluator()
    train = test_pairs("train", stride=40)
    train_stats = window_stats(train.actor, train.reactor)
    train_emb = pair_embedding(ev, train.actor, train.reactor)
    emb = Embedding(train_stats)
    pairs = test_pairs(split)
    report: dict[str, Any] = {"split": split, "window": WINDOW, "stride": STRIDE, "repeats": repeats,
                              "sampling": vars(sampling or model.sampling), "sets": {}}
    for name, sel in (("real", ~pairs.synthetic), ("synthetic", pairs.synthetic)):
        sub = TestPairs(pairs.actor[sel], pairs.reactor[sel], pairs.text[sel], pairs.synthetic[sel],
                        pairs.kind[sel])
        kinds = sub.kind if name == "synthetic" else None
        if not len(sub.actor):
            continue
        ref_stats = emb(window_stats(sub.actor, sub.reactor))
        ref = pair_embedding(ev, sub.actor, sub.reactor)
        out: dict[str, Any] = {"windows": int(len(sub.actor))}
        for row in rows:
            t0 = time.perf_counter()
            if row == "real":
                same = train.synthetic == (name == "synthetic")
                res: dict[str, Any] = {"fid": fid(train_emb[same], ref),
                                       "fid_stats": fid(emb(train_stats[same]), ref_stats),
                                       **pair_scores(sub.actor, sub.reactor, kinds)}
            else:
                runs = []
                for r in range(repeats):
                    gen = generate(model, sub, row, seed + r, sampling)
                    runs.append({"fid": fid(pair_embedding(ev, sub.actor, gen), ref),
                                 "fid_stats": fid(emb(window_stats(sub.actor, gen)), ref_stats),
                                 **pair_scores(sub.actor, gen, kinds)})
                res = {k: float(np.mean([x[k] for x in runs])) for k in runs[0] if k != "per_kind"}
                if kinds is not None:
                    res["per_kind"] = {k: {c: float(np.mean([x["per_kind"][k][c] for x in runs]))
                                           for c in ("iv_cm3", "if")} for k in runs[0]["per_kind"]}
                res["fid_std"] = float(np.std([x["fid"] for x in runs]))
            out[row] = res
            if log:
                log(f"{name} {row}: {res} ({time.perf_counter() - t0:.1f} s)")
        report["sets"][name] = out
    return report


def format_table(report: dict) -> str:
    cols = ("fid", "fid_stats", "iv_cm3", "if", "contact_frames", "foot_skating", "bone_deviation")
    lines = []
    for name, rows in report["sets"].items():
        tag = " (composed, synthetic)" if name == "synthetic" else " (captured salsa)"
        lines.append(f"{name}{tag}: {rows['windows']} windows of {report['window']} frames")
        lines.append(f"  {'row':<20}" + "".join(f"{c:>15}" for c in cols))
        for row, res in rows.items():
            if row == "windows":
                continue
            cells = "".join(f"{res[c]:>15.4f}" for c in cols)
            lines.append(f"  {row:<20}{cells}")
        kinds = [k for k in rows.get("real", {}).get("per_kind", {})]
        if kinds:
            lines.append("  IF per kind: " + " ".join(f"{k:>18}" for k in kinds))
            for row, res in rows.items():
                if row != "windows" and "per_kind" in res:
                    cells = " ".join(f"{res['per_kind'][k]['if']:>18.3f}" for k in kinds)
                    lines.append(f"  {row:<13}{cells}")
    return "\n".join(lines)
