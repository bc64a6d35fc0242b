"""`interplay eval`: every row's metrics with 95% confidence intervals, physical plausibility and
part-edit fidelity, as JSON-able data and as a printed table.

Protocol (Guo et al. 2022 / MoMask, scaled to this small test set; see docs/eval.md):
  - test samples: every person of every test clip, in windows ≤ 10 s (`testset`), each with its
    prompt; real embeddings and text embeddings from the trained evaluator
  - generated rows: `rounds` motions per sample at the sample's length (and `mm_generations` for
    one sample per distinct text, which also give MultiModality); each of `repeats` repeats draws
    one of its motions per sample, new R-precision pools and new diversity pairs
  - real row: each repeat resamples the test set with replacement, so its FID is the noise
    floor of FID on this many samples; reconstruction rows: pools and pairs vary only
  - physical plausibility: `motion.metrics.clip_metrics` per motion, averaged per repeat
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np

from interplay.eval import metrics as M
from interplay.eval.edits import CASES, VAL_CASES, edit_fidelity
from interplay.eval.rows import ROW_NAMES, Row, Skip, load_row
from interplay.eval.testset import split_samples
from interplay.motion.metrics import clip_metrics

PHYSICAL = ("bone_deviation", "foot_skating", "ground_penetration", "floating", "com_angle")
TEXT_METRICS = ("top1", "top2", "top3", "fid", "mm_dist", "diversity", "multimodality")


@dataclass(frozen=True)
class EvalConfig:
    repeats: int = 10           # CI repeats (pools, pairs, which generation per sample)
    rounds: int = 2             # generated motions per test sample
    mm_generations: int = 10    # generations per text for MultiModality
    pool: int = 32              # R-precision: 1 true + 31 mismatched texts
    diversity_pairs: int = 300
    edit_seeds: int = 3
    seed: int = 0
    split: str = "test"         # "val" for choosing settings (never tune on test)
    sampling: tuple = ()        # ((key, value), …) passed to the model rows' generate/edit

    def __post_init__(self):
        if self.repeats < 2 or self.rounds < 1 or self.mm_generations < 2 or self.edit_seeds < 0:
            raise ValueError("need repeats >= 2, rounds >= 1, mm_generations >= 2, edit_seeds >= 0")
        if self.split not in ("test", "val"):
            raise ValueError(f"split must be 'test' or 'val', got {self.split!r}")


def _physical(motions: list[np.ndarray]) -> np.ndarray:
    """(N, len(PHYSICAL)) clip metrics of single-person motions."""
    return np.array([[clip_metrics([m])[k] for k in PHYSICAL] for m in motions])


def _generate_all(row: Row, samples, cfg: EvalConfig, log) -> list[list[np.ndarray]]:
    """Candidate motions per sample: mm_generations for the first sample of each distinct text,
    `rounds` for the others."""
    generate = row.generate
    assert generate is not None                   # only "generated" rows come here
    first: dict[str, int] = {}
    for i, s in enumerate(samples):
        first.setdefault(s.text, i)
    reps = set(first.values())
    out = []
    for i, s in enumerate(samples):
        n = cfg.mm_generations if i in reps else cfg.rounds
        out.append([generate(s.text, s.frames, cfg.seed * 1_000_003 + 101 * i + r)
                    for r in range(n)])
        if log and (i + 1) % 20 == 0:
            log(f"  {row.name}: generated for {i + 1}/{len(samples)} samples")
    return out


def evaluate_row(row: Row, samples, real_emb: np.ndarray, text_emb: np.ndarray, evaluator,
                 cfg: EvalConfig, log=None) -> dict:
    """Metric values per repeat, reduced to (mean, 95% half-width)."""
    labels = [s.text for s in samples]
    n = len(samples)
    if row.kind == "real":
        cands = [[s.joints] for s in samples]
    elif row.kind == "reconstruction":
        reconstruct = row.reconstruct
        assert reconstruct is not None            # load_row gives reconstruction rows one
        cands = [[reconstruct(s.joints)] for s in samples]
    else:
        cands = _generate_all(row, samples, cfg, log)
    flat = [m for c in cands for m in c]
    emb = evaluator.embed_motion(flat)
    phys = _physical(flat)
    start = np.cumsum([0] + [len(c) for c in cands])[:-1]
    groups = [emb[start[i]:start[i] + len(c)] for i, c in enumerate(cands) if len(c) >= 2]

    per_repeat: dict[str, list[float]] = {k: [] for k in TEXT_METRICS + PHYSICAL}
    for r in range(cfg.repeats):
        rng = np.random.default_rng([cfg.seed, r])
        if row.kind == "real":
            idx = rng.integers(0, n, size=n)                       # bootstrap the test set
            rows_ = idx
        else:
            idx = np.arange(n)
            rows_ = start + np.array([rng.integers(len(c)) for c in cands])
        m, t, lab = emb[rows_], text_emb[idx], [labels[i] for i in idx]
        rp = M.r_precision(m, t, lab, rng, cfg.pool)
        for k, v in zip(("top1", "top2", "top3"), rp):
            per_repeat[k].append(v)
        per_repeat["fid"].append(M.fid(m, real_emb))
        per_repeat["mm_dist"].append(M.mm_dist(m, t))
        per_repeat["diversity"].append(M.diversity(m, rng, cfg.diversity_pairs))
        if groups:
            pick = rng.integers(0, len(groups), size=len(groups))    # bootstrap the texts
            per_repeat["multimodality"].append(M.multimodality([groups[g] for g in pick]))
        for k, col in zip(PHYSICAL, phys[rows_].T):
            per_repeat[k].append(float(col.mean()))
    return {k: M.confidence(v) for k, v in per_repeat.items() if v} | {"motions": len(flat)}


def run_eval(rows=ROW_NAMES, cfg: EvalConfig = EvalConfig(), clips=None, evaluator=None,
             log=print) -> dict:
    """The whole report as plain data (see format_table)."""
    from interplay.motion.clip import default_clips
    from interplay.review.evaluator import load_evaluator
    t0 = time.time()
    clips = clips if clips is not None else default_clips()
    evaluator = evaluator or load_evaluator()
    samples = split_samples(clips, cfg.split, sources=evaluator.sources)
    real_emb = evaluator.embed_motion([s.joints for s in samples])
    text_emb = evaluator.embed_text([s.text for s in samples])
    report: dict[str, Any] = {
        "config": asdict(cfg), "rows": {}, "skipped": {}, "edits": {},
        "test_set": {"samples": len(samples), "texts": len({s.text for s in samples}),
                     "clips": len({s.clip for s in samples}),
                     "frames": int(sum(s.frames for s in samples)),
                     "sources": sorted({c.source for c in clips if c.id in {s.clip for s in samples}})}}
    for name in rows:
        t = time.time()
        try:
            row = load_row(name, clips, dict(cfg.sampling))
        except Skip as exc:
            report["skipped"][name] = str(exc)
            if log:
                log(f"{name}: skipped ({exc})")
            continue
        result = evaluate_row(row, samples, real_emb, text_emb, evaluator, cfg, log)
        if row.edit is not None and cfg.edit_seeds:
            report["edits"][name] = edit_fidelity(row.generate, row.edit, cfg.edit_seeds,
                                                  cases=VAL_CASES if cfg.split == "val" else CASES)
        report["rows"][name] = {"kind": row.kind, "source": row.source,
                                "seconds": round(time.time() - t, 1), **result}
        if log:
            log(f"{name}: done in {time.time() - t:.0f} s")
    report["seconds"] = round(time.time() - t0, 1)
    return report


def _cell(v, digits: int = 3, scale: float = 1.0) -> str:
    if v is None:
        return "-"
    mean, ci = v
    return f"{mean * scale:.{digits}f}±{ci * scale:.{digits}f}"


def format_table(report: dict) -> str:
    """Three plain-text tables: text–motion metrics, physical plausibility, part edits."""
    ts = report["test_set"]
    lines = [f"test set: {ts['samples']} windows of {ts['clips']} clips, {ts['texts']} distinct "
             f"texts; {report['config']['repeats']} repeats, mean ± 95% CI", ""]
    head = ["row", "R@1", "R@2", "R@3", "FID", "MM-Dist", "Diversity", "MModality"]
    body = [[name] + [_cell(r.get(k)) for k in TEXT_METRICS] for name, r in report["rows"].items()]
    lines += _grid(head, body) + [""]
    head = ["row", "bone dev (mm)", "foot skate (m/s)", "penetration (cm)", "floating (cm)",
            "COM angle (°)"]
    scales = {"bone_deviation": (1000, 2), "foot_skating": (1, 3), "ground_penetration": (100, 2),
              "floating": (100, 2), "com_angle": (1, 1)}
    body = [[name] + [_cell(r.get(k), scales[k][1], scales[k][0]) for k in PHYSICAL]
            for name, r in report["rows"].items()]
    lines += _grid(head, body)
    for name, cases in report["edits"].items():
        lines += ["", f"part edits ({name}, {cases[0]['seeds'] if cases else 0} seeds each):"]
        head = ["edit", "confirmed", "code after", "code before", "untouched (cm)"]
        body = [[c["prompt"] + f" ({c['base']})", f"{c['confirmed']:.2f}", f"{c['code_share']:.2f}",
                 f"{c['base_code_share']:.2f}", f"{c['untouched_cm']:.2f}"] for c in cases]
        lines += _grid(head, body)
    for name, why in report["skipped"].items():
        lines.append(f"skipped {name}: {why}")
    lines.append(f"({report['seconds']:.0f} s)")
    return "\n".join(lines)


def _grid(head: list[str], body: list[list[str]]) -> list[str]:
    widths = [max(len(str(r[i])) for r in [head] + body) for i in range(len(head))]
    fmt = lambda r: "  ".join(str(c).ljust(w) if i == 0 else str(c).rjust(w)  # noqa: E731
                              for i, (c, w) in enumerate(zip(r, widths)))
    return [fmt(head), fmt(["-" * w for w in widths])] + [fmt(r) for r in body]
