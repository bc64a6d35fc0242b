"""`interplay eval-pair`: every two-person row on the held-out pairs with 95% intervals over
repeats (`pair` has the test set, rows and scores), and the contact check.

Repeats: a generated row makes one pair per test window per repeat (seeds differ per repeat);
the real row resamples the test windows with replacement per repeat (so its FID, against the
train split's windows of the same kind, is the floor for this many windows). Cells are
mean ± 1.96·std/√repeats (`eval.metrics.confidence`).

Contact check: for each contact kind of the composed data (handshake, high five, hug, push,
walking hand in hand) one prompt, `contact_seeds` 4 s samples per generated row; a sample
counts when a hand is within 3 cm of the other person's body (`metrics.pair_geometry`
hand_gap, either person, either hand) on some frame of the expected window. The expected
window of a kind is [earliest contact start − 4, latest contact end + 4) frames over all
composed clips of that kind that carry a contact annotation (meta["contact"], every split):
where the composer put the touch, widened by one token (0.2 s) either side. The same check on
those composed clips themselves is the `real` column (a check of the check).
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from interplay.eval.metrics import confidence, fid
from interplay.eval.pair import (
    ROW_NAMES,
    SCORES,
    WINDOW,
    Skip,
    fid_embedding,
    load_row,
    pair_set,
    window_scores,
)

CONTACT_PROMPTS = {
    "handshake": "two people shake hands",
    "high_five": "two people high five",
    "hug": "two people hug each other",
    "push": "one person pushes the other away with both hands",
    "walk_side_by_side": "two people walk side by side holding hands",
}
TOLERANCE = 4           # frames added to each side of the composed contact window
HAND_CONTACT = 0.03     # m
TARGET = 0.8            # share of samples with contact in the window


def contact_windows(clips) -> dict[str, dict]:
    """{kind: {"window": [lo, hi), "clips": [ids]}} from the composed clips' annotations."""
    out: dict[str, dict] = {}
    for c in clips:
        meta = c.meta or {}
        if not c.synthetic or meta.get("kind") not in CONTACT_PROMPTS or not meta.get("contact"):
            continue
        k = out.setdefault(meta["kind"], {"starts": [], "ends": [], "clips": []})
        k["starts"].append(int(meta["contact"]["start"]))
        k["ends"].append(int(meta["contact"]["end"]))
        k["clips"].append(c.id)
    return {kind: {"window": [max(0, min(v["starts"]) - TOLERANCE), max(v["ends"]) + TOLERANCE],
                   "clips": v["clips"]} for kind, v in sorted(out.items())}


def touches(pair: np.ndarray, window: list[int]) -> bool:
    """A hand within HAND_CONTACT of the other body on some frame of [lo, hi)."""
    from interplay.motion.metrics import pair_geometry
    lo, hi = window
    a, b = (np.asarray(p[lo:hi], np.float64) for p in pair)
    if len(a) == 0:
        return False
    return bool((pair_geometry(a, b)["hand_gap"] <= HAND_CONTACT).any())


def contact_check(generators: dict, clips, seeds: int = 10, seed: int = 0, log=None) -> dict:
    kinds = contact_windows(clips)
    by_id = {c.id: c for c in clips}
    out: dict[str, Any] = {"target": TARGET, "tolerance_frames": TOLERANCE, "seeds": seeds,
                           "frames": WINDOW, "kinds": {}}
    for kind, info in kinds.items():
        prompt, win = CONTACT_PROMPTS[kind], info["window"]
        real = [touches(np.stack(by_id[i].people), win) for i in info["clips"]]
        row = {"prompt": prompt, "window": win, "composed_clips": len(real),
               "shares": {"real": float(np.mean(real))}}
        for name, gen in generators.items():
            if gen is None:
                continue
            hits = [touches(gen(prompt, WINDOW, seed * 7919 + s), win) for s in range(seeds)]
            row["shares"][name] = float(np.mean(hits))
        out["kinds"][kind] = row
        if log:
            log(f"contact {kind} {win}: {row['shares']}")
    return out


def _row_repeats(gen, sub, emb, ref, ref_train, real_scores, repeats, seed, rng) -> np.ndarray:
    """(repeats, 1 + len(SCORES)): FID and the mean scores of each repeat."""
    runs = []
    for r in range(repeats):
        if gen is None:
            idx = rng.integers(0, len(sub), len(sub))
            runs.append([fid(ref[idx], ref_train), *real_scores[idx].mean(0)])
            continue
        pairs = np.stack([gen(p, WINDOW, seed * 1_000_003 + 101 * i + r)
                          for i, p in enumerate(sub.prompts)])
        scores = np.stack([window_scores(p) for p in pairs])
        runs.append([fid(emb(pairs), ref), *scores.mean(0)])
    return np.asarray(runs)


def run_eval_pair(rows=ROW_NAMES, repeats: int = 3, seed: int = 0, limit: int | None = None,
                  contact_seeds: int = 10, clips=None, weights=None, log=None,
                  bounds_seeds: int = 2) -> dict:
    """{"sets": {"captured"|"composed": {"windows", "rows": {row: {col: [mean, hw]}}}},
    "skipped": {row: why}, "fid_embedding", "contact": contact_check(...),
    "bounds": pair_bounds.bounds_check(...) (bounds_seeds 0 skips it)}."""
    from interplay.eval.pair import WEIGHTS
    from interplay.motion.clip import default_clips
    if repeats < 2:
        raise ValueError("--repeats must be at least 2 (for the intervals)")
    clips = list(clips or default_clips())
    train, test = pair_set("train", clips), pair_set("test", clips)
    emb = fid_embedding(train)
    report = {"window": WINDOW, "repeats": repeats, "seed": seed, "fid_embedding": emb.name,
              "sets": {}, "skipped": {}}
    generators = {}
    for name in rows:
        try:
            generators[name] = load_row(name, clips, weights or WEIGHTS)
        except Skip as why:
            report["skipped"][name] = str(why)
    rng = np.random.default_rng(seed)
    for kind, synthetic in (("captured", False), ("composed", True)):
        sub = test.subset(test.synthetic == synthetic)
        if limit:
            sub = sub.subset(np.arange(min(limit, len(sub))))
        if not len(sub):
            continue
        ref = emb(sub.windows)
        ref_train = emb(train.subset(train.synthetic == synthetic).windows)
        real_scores = np.stack([window_scores(w) for w in sub.windows])
        out: dict[str, Any] = {"windows": len(sub), "rows": {}}
        for name, gen in generators.items():
            t0 = time.perf_counter()
            runs = _row_repeats(gen, sub, emb, ref, ref_train, real_scores, repeats, seed, rng)
            out["rows"][name] = {col: list(confidence(runs[:, j]))
                                 for j, col in enumerate(("fid",) + SCORES)}
            if log:
                log(f"{kind} {name}: {len(sub)} windows × {repeats} ({time.perf_counter() - t0:.1f} s)")
        report["sets"][kind] = out
    if contact_seeds > 0:
        report["contact"] = contact_check(generators, clips, contact_seeds, seed, log)
    if bounds_seeds > 0:
        from interplay.eval.pair_bounds import bounds_check
        report["bounds"] = bounds_check(generators, "test", bounds_seeds, seed, log)
    return report


COLUMNS = {"fid": ("FID", 1.0), "iv_cm3": ("IV cm³", 1.0), "if": ("IF", 1.0),
           "contact_frames": ("contact fr", 1.0), "foot_skating": ("skate m/s", 1.0),
           "bone_deviation": ("bone dev mm", 1000.0), "penetration_cm": ("penetr. cm", 1.0)}


def format_table(report: dict) -> str:
    lines = [f"FID in: {report['fid_embedding']}",
             f"{report['window']}-frame windows, {report['repeats']} repeats, mean ± 95% interval"]
    for kind, res in report["sets"].items():
        tag = "captured salsa" if kind == "captured" else "composed, SYNTHETIC"
        lines.append(f"\n{kind} ({tag}): {res['windows']} test windows")
        lines.append(f"  {'row':<12}" + "".join(f"{COLUMNS[c][0]:>19}" for c in COLUMNS))
        for row, cells in res["rows"].items():
            body = "".join(f"{cells[c][0] * s:>10.3f} ±{cells[c][1] * s:>7.3f}"
                           for c, (_, s) in COLUMNS.items())
            lines.append(f"  {row:<12}{body}")
    for row, why in report["skipped"].items():
        lines.append(f"  skipped {row}: {why}")
    contact = report.get("contact")
    if contact:
        rows = sorted({r for k in contact["kinds"].values() for r in k["shares"]},
                      key=lambda r: (r != "real", r))
        lines.append(f"\ncontact check: share of {contact['seeds']} samples ({contact['frames']} "
                     f"frames) with a hand within 3 cm of the other body in the expected window "
                     f"(target ≥ {contact['target']:.0%}; real = the composed clips themselves)")
        lines.append(f"  {'kind':<18}{'window':>10}" + "".join(f"{r:>12}" for r in rows))
        for kind, k in contact["kinds"].items():
            cells = "".join(f"{k['shares'][r]:>12.0%}" if r in k["shares"] else f"{'-':>12}"
                            for r in rows)
            lines.append(f"  {kind:<18}{str(k['window'][0]) + '–' + str(k['window'][1]):>10}{cells}")
        for kind, k in contact["kinds"].items():
            lines.append(f"  {kind}: \"{k['prompt']}\"")
    if report.get("bounds"):
        from interplay.eval.pair_bounds import format_bounds
        lines.append(format_bounds(report["bounds"]))
    return "\n".join(lines)
