"""Calibrating the reviewer's judges on held-out real motion (`interplay review-calibrate`,
or `python -m interplay.eval.calibrate`): writes `calibration.json` beside each evaluator's
weights (`interplay.review.calibration` reads it).

One person: every person-window of the test split's clips (`eval.testset.split_samples`, ≤ 10 s,
the evaluator's own sources) scored against its own caption (a positive) and against every test
caption of another action family (`motion.labels.label_family`; negatives). Two people: the
test split's two-person clips (captured salsa and composed pairs) cut into 80-frame windows
every 40 (a composed pair whole), both role orders, scored against every prompt the pair evaluator was trained with:
its own kind's prompts are positives, the other kinds' negatives.

The threshold: the feasible band is [lowest threshold with FPR ≤ 10 %, highest with TPR ≥
95 %]; when it is not empty the threshold is its midpoint (a margin on both sides), else the
highest threshold with TPR ≥ 95 % (and the FPR it gives is reported). P(match | score) is a
logistic fit with the two classes weighted equally (a prior of one half), by Newton's method.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
from pathlib import Path

import numpy as np

from interplay.eval.testset import person_prompt, split_samples
from interplay.motion.clip import DATA_DIR, default_clips
from interplay.motion.labels import label_family
from interplay.motion.pair.windows import pair_windows
from interplay.review.calibration import EVALUATOR_DIR, FILE, PAIR_EVALUATOR_DIR, weights_sha256

MIN_TPR, MAX_FPR = 0.95, 0.10
PAIR_WINDOW, PAIR_STRIDE = 80, 40     # the composed test pairs are 80 frames (4 s) long
# The calibration holds for a text whose MiniLM cosine to the nearest training text is at least
# this: about the 5th percentile (0.81) of the one-person test captions' own (`domain_quantile`).
DOMAIN = 0.8
COMMAND = "interplay review-calibrate"


def rates(pos: np.ndarray, neg: np.ndarray, t: float) -> tuple[float, float]:
    """(TPR, FPR) of the rule `score ≥ t`."""
    return float(np.mean(pos >= t)), float(np.mean(neg >= t))


def choose(pos: np.ndarray, neg: np.ndarray, min_tpr: float = MIN_TPR,
           max_fpr: float = MAX_FPR) -> dict:
    """The threshold by the module's rule, with its TPR/FPR and whether both targets hold."""
    pos, neg = np.sort(pos), np.sort(neg)
    hi = float(pos[int(np.floor((1 - min_tpr) * len(pos)))])        # TPR ≥ min_tpr up to here
    k = int(np.ceil((1 - max_fpr) * len(neg)))                      # FPR ≤ max_fpr from here
    lo = float(np.nextafter(neg[k - 1], np.inf)) if k > 0 else float(neg[0])
    met = lo <= hi
    t = (lo + hi) / 2 if met else hi
    tpr, fpr = rates(pos, neg, t)
    return {"threshold": round(t, 4), "tpr": tpr, "fpr": fpr, "both_targets_met": met,
            "band": [round(lo, 4), round(hi, 4)],
            "rule": ("midpoint of [lowest threshold with FPR ≤ 10 %, highest with TPR ≥ 95 %]" if met
                     else "no threshold meets both: the highest with TPR ≥ 95 %")}


def fit_logistic(pos: np.ndarray, neg: np.ndarray, iters: int = 50) -> dict:
    """P(match | s) = σ(a s + b), classes weighted equally, Newton's method (a little ridge)."""
    s = np.concatenate([pos, neg]).astype(np.float64)
    y = np.concatenate([np.ones(len(pos)), np.zeros(len(neg))])
    w = np.concatenate([np.full(len(pos), 0.5 / len(pos)), np.full(len(neg), 0.5 / len(neg))])
    x = np.stack([s, np.ones_like(s)], axis=1)
    theta = np.zeros(2)
    for _ in range(iters):
        p = 1 / (1 + np.exp(-(x @ theta)))
        grad = x.T @ (w * (p - y)) + 1e-6 * theta
        hess = (x * (w * p * (1 - p))[:, None]).T @ x + 1e-6 * np.eye(2)
        step = np.linalg.solve(hess, grad)
        theta -= step
        if np.abs(step).max() < 1e-10:
            break
    p = 1 / (1 + np.exp(-(x @ theta)))
    ll = float(-(w * (y * np.log(p + 1e-12) + (1 - y) * np.log(1 - p + 1e-12))).sum())
    return {"a": round(float(theta[0]), 5), "b": round(float(theta[1]), 5),
            "weighting": "classes weighted equally (prior 0.5)", "log_loss": round(ll, 4)}


def roc_points(pos: np.ndarray, neg: np.ndarray, steps: int = 21) -> list[dict]:
    lo, hi = float(min(pos.min(), neg.min())), float(max(pos.max(), neg.max()))
    grid = np.round(np.linspace(np.floor(lo * 20) / 20, np.ceil(hi * 20) / 20, steps), 3)
    return [{"threshold": float(t), "tpr": round(r[0], 4), "fpr": round(r[1], 4)}
            for t in grid for r in [rates(pos, neg, float(t))]]


def auc(pos: np.ndarray, neg: np.ndarray) -> float:
    """P(a positive scores above a negative), ties half."""
    both = np.concatenate([pos, neg])
    ranks = np.argsort(np.argsort(both, kind="stable"), kind="stable").astype(np.float64) + 1
    for v in np.unique(both):                                       # average ties
        m = both == v
        if m.sum() > 1:
            ranks[m] = ranks[m].mean()
    return float((ranks[:len(pos)].sum() - len(pos) * (len(pos) + 1) / 2) / (len(pos) * len(neg)))


def _report(kind: str, directory: Path, pos: np.ndarray, neg: np.ndarray, counts: dict,
            data_dir: Path, extra: dict | None = None) -> dict:
    index = Path(data_dir) / "index.json"
    return {"kind": kind, **choose(pos, neg), "targets": {"min_tpr": MIN_TPR, "max_fpr": MAX_FPR},
            "logistic": fit_logistic(pos, neg), "auc": round(auc(pos, neg), 4),
            "positives": {"mean": round(float(pos.mean()), 4), "p05": round(float(np.quantile(pos, 0.05)), 4)},
            "negatives": {"mean": round(float(neg.mean()), 4), "p90": round(float(np.quantile(neg, 0.9)), 4)},
            "roc": roc_points(pos, neg), "counts": counts, "split": "test",
            "weights": str(directory.relative_to(directory.parents[2])) if len(directory.parents) > 2
            else str(directory),
            "weights_sha256": weights_sha256(directory),
            "data_index_sha256": hashlib.sha256(index.read_bytes()).hexdigest() if index.is_file() else None,
            "command": COMMAND, **(extra or {})}


def single_scores(ev, clips) -> tuple[np.ndarray, np.ndarray, dict]:
    """(positive scores, negative scores, counts) of the one-person evaluator."""
    samples = split_samples(clips, "test", sources=ev.sources)
    texts = sorted({s.text for s in samples})
    fam = {t: label_family(t) for t in texts}
    sim = ev.embed_motion([s.joints for s in samples]) @ ev.embed_text(texts).T   # (N, texts)
    col = {t: j for j, t in enumerate(texts)}
    pos = np.array([sim[i, col[s.text]] for i, s in enumerate(samples)])
    other = np.array([[fam[t] != fam[s.text] for t in texts] for s in samples])
    neg = sim[other]
    counts = {"windows": len(samples), "clips": len({s.clip for s in samples}), "texts": len(texts),
              "families": len(set(fam.values())), "positives": int(len(pos)), "negatives": int(len(neg))}
    return pos, neg, counts


def training_texts(ev, clips) -> list[str]:
    """The captured clips' prompts the one-person evaluator was trained with (its train split)."""
    return sorted({person_prompt(c) for c in clips if c.split == "train" and not c.synthetic
                   and (ev.sources is None or c.source in ev.sources)})


def domain_quantile(ev, clips, q: float = 0.05) -> float:
    """The q-quantile over the test captions of their MiniLM cosine to the nearest training text."""
    from interplay.text.encoder import get_encoder
    enc = get_encoder()
    test = sorted({s.text for s in split_samples(clips, "test", sources=ev.sources)})
    sims = np.asarray(enc.encode(test)) @ np.asarray(enc.encode(training_texts(ev, clips))).T
    return float(np.quantile(sims.max(axis=1), q))


def pair_kind(clip) -> str:
    """A two-person clip's interaction kind, as the pair evaluator was trained (models/pair_evaluator)."""
    if clip.synthetic:
        return str(clip.meta.get("kind", clip.label))
    return "salsa" if clip.id.startswith("salsa") else str(clip.label)


def pair_scores(ev, clips) -> tuple[np.ndarray, np.ndarray, dict]:
    """(positive scores, negative scores, counts) of the pair evaluator."""
    prompts: dict[str, list[str]] = ev.config["prompts"]
    pairs = [c for c in clips if c.split == "test" and len(c.people) == 2 and pair_kind(c) in prompts]
    w = pair_windows(pairs, PAIR_WINDOW, PAIR_STRIDE, roles="both", mirror=False, canonical=False)
    by_id = {c.id: c for c in pairs}
    kinds = [pair_kind(by_id[i]) for i in w.clip_ids]
    texts = [(k, p) for k, ps in prompts.items() for p in ps]
    sim = ev.embed(w.joints) @ ev.embed_text([p for _, p in texts]).T
    own = np.array([[tk == k for tk, _ in texts] for k in kinds])
    captured = np.array([not by_id[i].synthetic for i in w.clip_ids])
    counts = {"windows": len(kinds), "captured_windows": int(captured.sum()),
              "composed_windows": int((~captured).sum()), "clips": len(set(w.clip_ids)),
              "kinds": sorted(set(kinds)), "texts": len(texts), "positives": int(own.sum()),
              "negatives": int((~own).sum()), "window_frames": PAIR_WINDOW, "stride": PAIR_STRIDE}
    return sim[own], sim[~own], counts


def calibrate(data_dir: Path | None = None, write: bool = True, log=lambda m: None) -> dict:
    from interplay.review.evaluator import EvaluatorRuntime
    from interplay.review.pair_evaluator import PairEvaluator
    data_dir = Path(data_dir or DATA_DIR)
    clips = default_clips(str(data_dir))
    out = {}
    ev = EvaluatorRuntime.load(EVALUATOR_DIR)
    pos, neg, counts = single_scores(ev, clips)
    domain = {"texts": training_texts(ev, clips), "min_similarity": DOMAIN,
              "test_captions_p05": round(domain_quantile(ev, clips), 4)}
    out["evaluator"] = _report("evaluator", EVALUATOR_DIR, pos, neg, counts, data_dir,
                               {"domain": domain})
    log(f"evaluator: {counts['windows']} windows, threshold {out['evaluator']['threshold']}")
    pev = PairEvaluator.load(PAIR_EVALUATOR_DIR)
    pos, neg, counts = pair_scores(pev, clips)
    out["pair_evaluator"] = _report("pair_evaluator", PAIR_EVALUATOR_DIR, pos, neg, counts, data_dir,
                                    {"domain": {"texts": [p for ps in pev.config["prompts"].values()
                                                          for p in ps], "min_similarity": DOMAIN}})
    log(f"pair evaluator: {counts['windows']} windows, threshold {out['pair_evaluator']['threshold']}")
    if write:
        for key, d in (("evaluator", EVALUATOR_DIR), ("pair_evaluator", PAIR_EVALUATOR_DIR)):
            (d / FILE).write_text(json.dumps(out[key], indent=1) + "\n")
    return out


def format_table(out: dict) -> str:
    lines = []
    for key, r in out.items():
        c = r["counts"]
        lines.append(f"{key}: threshold {r['threshold']} ({r['rule']}): TPR {r['tpr']:.3f}, FPR "
                     f"{r['fpr']:.3f}; AUC {r['auc']:.3f}; P(match|s) = σ({r['logistic']['a']}·s + "
                     f"{r['logistic']['b']}); {c['windows']} windows, {c['positives']} positive and "
                     f"{c['negatives']} negative pairs")
        lines.append(f"{'threshold':>10}{'TPR':>8}{'FPR':>8}")
        lines += [f"{p['threshold']:>10.3f}{p['tpr']:>8.3f}{p['fpr']:>8.3f}" for p in r["roc"]]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog=COMMAND, description=__doc__.splitlines()[0])
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--dry-run", action="store_true", help="measure, do not write calibration.json")
    args = ap.parse_args(argv)
    out = calibrate(write=not args.dry_run, log=lambda m: print(m, file=sys.stderr))
    print(json.dumps(out, indent=1) if args.json else format_table(out))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
