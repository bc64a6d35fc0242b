"""MODEL_CARD.md for models/weights/arflow from the training summary and, when present, the
`interplay eval-react --json` report saved next to the checkpoint (var/arflow/eval_react.json)."""

from __future__ import annotations

import json
from pathlib import Path

from models.common.sources import licence_section


def _table(report: dict) -> list[str]:
    cols = ("fid", "fid_stats", "iv_cm3", "if", "contact_frames", "foot_skating")
    lines = []
    for name, rows in report["sets"].items():
        kind = "composed pairs — SYNTHETIC" if name == "synthetic" else "captured salsa pairs"
        lines += ["", f"**{name}** ({kind}; {rows['windows']} test windows of "
                  f"{report['window']} frames, both role orders; {report['repeats']} seeds)", "",
                  "| row | FID (pair evaluator) | FID (statistics) | IV (cm³/frame) | IF | "
                  "contact frames | foot skating (m/s) |", "|---|---|---|---|---|---|---|"]
        for row, r in rows.items():
            if row != "windows":
                lines.append(f"| {row} | " + " | ".join(f"{r[c]:.3f}" if c in r else "-"
                                                        for c in cols) + " |")
        kinds = list(rows.get("real", {}).get("per_kind", {}))
        if kinds:
            lines += ["", "IF per composed kind:", "", "| row | " + " | ".join(kinds) + " |",
                      "|---" * (len(kinds) + 1) + "|"]
            lines += [f"| {row} | " + " | ".join(f"{r['per_kind'][k]['if']:.3f}" for k in kinds)
                      + " |" for row, r in rows.items() if row != "windows" and "per_kind" in r]
    return lines


def write_card(weights: Path, ckpt_dir: Path) -> Path:
    summary = json.loads((Path(ckpt_dir) / "train_summary.json").read_text())
    config = json.loads((Path(weights) / "config.json").read_text())
    m = config["model"]
    lines = [
        "# ARFlow reaction model (`arflow.onnx`)", "",
        "Action → reaction flow matching with x-prediction (ARFlow §3.1): the flow starts at the "
        "actor's motion plus a little noise and ends at the reactor's; a causal transformer "
        "decoder predicts the clean reaction, frame i seeing actor frames ≤ i only (online).",
        "", "## Data and representation", "",
        "Two-person clips of the processed set (`models/data`), **train split only**: the 11 "
        "captured salsa pairs and 144 composed (synthetic) pairs; 2 s windows (stride 5 "
        "frames), both role orders, mirrored. Each window: both people's 22 joints in the "
        "actor's first-frame heading frame (66 numbers per person and frame), normalised by "
        "one mean/std shared by both people (`normalizer.npz`). Optional intent: the MiniLM "
        "embedding of the clip prompt (dropped to zeros 20 % of the time: the no-prompt case).",
        "", *licence_section(summary.get("training_data")), "## Network and training", "",
        f"{m['layers']} decoder layers × {m['d_model']} wide, {m['heads']} heads, feed-forward "
        f"{m['ff']}; {summary['parameters']:,} parameters. Loss: MSE on the predicted clean "
        f"reaction + {m['velocity_weight']} × frame-difference MSE + {m['bone_weight']} × bone "
        f"length MSE; σ = {m['noise']} (normalised units). {summary['steps']} AdamW steps of "
        f"batch {summary['train_config']['batch_size']} in {summary['seconds']:.0f} s on a "
        f"shared 2-core CPU; best validation loss {summary['best_val']:.4f} "
        f"(first training batch {summary['first_loss']:.3f}, last {summary['last_loss']:.3f}).",
        "", "Made by `python -m models.arflow.train` (part of `make train`), which exports with "
        "`models/arflow/export.py`.", "", "## Sampling (runtime `interplay.reaction.session`)", "",
        f"Defaults in config.json: {json.dumps(config['sampling'])}.",
        "Euler x-prediction steps; penetration guidance (sphere-body SDF loss with safe "
        "distance) on the predicted clean pose, then reprojection with weight γ between the "
        "predicted and the real start point.", "", "## Measured", ""]
    ev = Path(ckpt_dir) / "eval_react.json"
    if ev.exists():
        report = json.loads(ev.read_text())
        lines += ["`interplay eval-react --json` (FID from the learned pair evaluator, "
                  "models/weights/pair_evaluator; the statistics FID as a second column; see "
                  "docs/reaction.md):"] + _table(report)
    else:
        lines.append("Run `interplay eval-react` for FID, IV, IF, contacts and skating.")
    bench = Path(ckpt_dir) / "bench_reaction.json"
    if bench.exists():
        b = json.loads(bench.read_text())
        b = b.get("reaction", b)          # `interplay bench --only reaction --json` output
        lines += ["", f"`interplay bench --only reaction` (load average {b['load_avg_1m']}):", ""]
        lines += [f"- per-frame step, {'cached keys/values' if r.get('cached') else 'window'}, "
                  f"guidance {r['guidance']}: p50 {r['p50_ms']} ms, p95 {r['p95_ms']} ms"
                  for r in b["rows"]]
    lines += ["", "## Limits", "",
              "Trained on 11 captured pairs of one activity (salsa) plus composed pairs: "
              "reactions outside these are not expected to be good. Joints, not rotations, are "
              "generated; bones are restored by IK → FK (offline) or per-frame bone-length "
              "projection (online). Guidance lowers the pair evaluator's FID but can raise the "
              "statistics FID (it did on the test pairs at the shipped defaults), takes hand "
              "contacts away (the safe distance applies to hands) and raises foot skating (the "
              "whole-body term slides the reactor; nothing pins its feet): read the FID with the "
              "contact and skating columns (docs/reaction.md). The defaults were chosen on the "
              "validation split (`python -m models.arflow.sweep_guidance`)."]
    out = Path(weights) / "MODEL_CARD.md"
    out.write_text("\n".join(lines) + "\n")
    return out
