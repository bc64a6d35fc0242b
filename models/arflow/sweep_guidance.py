"""Choose guidance settings on the VALIDATION split (never on test): `interplay eval-react`'s
no-guidance and guidance (γ = 1) rows for each setting of a small grid, with the ratios the
issue's target is stated in (IF and IV against no guidance, FID rise), per set.

    .venv/bin/python -m models.arflow.sweep_guidance [--repeats 2] [--first N | --only I,J] > var/arflow/sweep_val.json
"""

from __future__ import annotations

import argparse
import json
import sys
from dataclasses import replace

from interplay.eval.reaction import run_eval_react
from interplay.reaction.session import get_reaction_model

# (guidance w, safe distance δ, rigid r, gradient steps per flow step)
GRID = [(0.3, 0.06, 0.3, 3), (0.3, 0.06, 0.3, 2), (0.3, 0.06, 0.3, 1), (0.5, 0.06, 0.3, 3),
        (0.5, 0.06, 0.3, 2), (0.3, 0.08, 0.3, 3), (0.3, 0.06, 0.6, 3), (0.5, 0.08, 0.3, 2),
        (0.3, 0.10, 0.3, 2), (0.5, 0.06, 0.6, 2),
        # second round (after the first showed rigid 0.6 helping FID and 1–2 steps enough)
        (0.3, 0.06, 0.6, 2), (0.3, 0.06, 0.6, 1), (0.3, 0.08, 0.6, 2), (0.3, 0.08, 0.6, 1)]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeats", type=int, default=2)
    ap.add_argument("--first", type=int, default=0, help="start at this grid entry")
    ap.add_argument("--only", help="comma-separated grid entries to run (e.g. 0,1,10)")
    args = ap.parse_args(argv)
    picks = ([GRID[int(i)] for i in args.only.split(",")] if args.only else GRID[args.first:])
    model = get_reaction_model()
    base = run_eval_react(("no_guidance",), repeats=args.repeats, model=model, split="val")
    out = []
    for w, safe, rigid, iters in picks:
        cfg = replace(model.sampling, guidance=w, safe_distance=safe, rigid=rigid,
                      guidance_iters=iters)
        rep = run_eval_react(("guidance",), repeats=args.repeats, model=model, sampling=cfg,
                             split="val")
        row = {"guidance": w, "safe_distance": safe, "rigid": rigid, "guidance_iters": iters}
        for name, rows in rep["sets"].items():
            g, b = rows["guidance"], base["sets"][name]["no_guidance"]
            row[name] = {"if_ratio": round(g["if"] / b["if"], 3),
                         "iv_ratio": round(g["iv_cm3"] / b["iv_cm3"], 4),
                         "fid_rise": round(g["fid"] / b["fid"] - 1, 3), "if": round(g["if"], 4),
                         "fid_stats_rise": round(g["fid_stats"] / b["fid_stats"] - 1, 3),
                         "foot_skating": round(g["foot_skating"], 3),
                         "fid": round(g["fid"], 4), "contact_frames": round(g["contact_frames"], 2)}
            if "per_kind" in g:
                row[name]["if_per_kind"] = {k: round(v["if"], 3) for k, v in g["per_kind"].items()}
        print(json.dumps(row), file=sys.stderr)
        out.append(row)
    print(json.dumps({"split": "val", "repeats": args.repeats, "no_guidance": {
        n: {k: v for k, v in r["no_guidance"].items() if k != "per_kind"}
        for n, r in base["sets"].items()}, "grid": out}, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
