"""The model card of the SPAM weights, written from the numbers `pipeline.run_all` measured."""

from __future__ import annotations

import json
from pathlib import Path

from models.common.sources import licence_section

from .config import PARTS


def _f(x, nd: int = 3) -> str:
    return "n/a" if x is None or x != x else f"{x:.{nd}f}"


LABELS = {"spam": "**SPAM-VQ, shipped** (4 parts, with CCL, full budget)",
          "spam_short": "SPAM-VQ (4 parts, with CCL), ablation steps",
          "spam_nocs": "SPAM-VQ without CCL/geometric losses, ablation steps",
          "spam_single": "single codebook (whole body), ablation steps"}


def _recon_rows(numbers: dict) -> list[str]:
    rows = ["| model | MPJPE (mm) | root-relative MPJPE (mm) | positions-block MPJPE (mm) "
            "| positions + IK MPJPE (mm) | bone dev. (m) | foot skating (m/s) | ground pen. (m) "
            "| COM angle (°) | VQ steps | final recon L1 |",
            "|---|---|---|---|---|---|---|---|---|---|---|"]
    for name in LABELS:
        r, n = numbers[name]["recon"], numbers[name]
        rows.append(f"| {LABELS[name]} | {_f(r['mpjpe_mm'], 1)} | {_f(r['mpjpe_root_relative_mm'], 1)} "
                    f"| {_f(r['mpjpe_positions_mm'], 1)} | {_f(r.get('mpjpe_positions_ik_mm'), 1)} "
                    f"| {_f(r['bone_deviation'], 4)} | {_f(r['foot_skating'])} "
                    f"| {_f(r['ground_penetration'], 4)} | {_f(r['com_angle'], 1)} "
                    f"| {n['vq_steps']} | {_f(n['vq_final'].get('recon'))} |")
    r = numbers["spam"]["recon"]
    rows.append(f"| reference (test motion itself) | 0 | 0 | 0 | 0 | {_f(r['reference_bone_deviation'], 4)} "
                f"| {_f(r['reference_foot_skating'])} | {_f(r['reference_ground_penetration'], 4)} "
                f"| {_f(r['reference_com_angle'], 1)} | | |")
    return rows


def _usage_rows(numbers: dict) -> list[str]:
    rows = ["| model | part | layer-0 codes used | layer-0 perplexity | mean used (all layers) "
            "| mean perplexity |", "|---|---|---|---|---|---|"]
    for name in LABELS:
        for part, u in numbers[name]["usage"].items():
            rows.append(f"| {name} | {part} | {u['base_used']:.0%} | {u['base_perplexity']:.0f} "
                        f"| {u['mean_used']:.0%} | {u['mean_perplexity']:.0f} |")
    return rows


def _transformer_rows(numbers: dict) -> list[str]:
    rows = ["| model | steps | final train CE | final train acc | val CE | val acc |",
            "|---|---|---|---|---|---|"]
    for name in ("spam", "spam_nocs"):
        for kind in ("base", "residual"):
            n = numbers[name]
            tr, va = n[f"{kind}_final"], n[f"{kind}_val"]
            rows.append(f"| {name} {kind} | {n[f'{kind}_steps']} | {_f(tr['ce'])} | {tr['acc']:.1%} "
                        f"| {_f(va['ce'])} | {va['acc']:.1%} |")
    return rows


EVAL_LABELS = {"real": "real test motion", "retrieval": "retrieval (train captures)",
               "spam": "**SPAM, shipped** (int8 transformers, planted feet held)",
               "spam_fp32": "SPAM, float transformers, feet not held",
               "spam_nolock": "SPAM, shipped, feet not held",
               "spam_nocs": "SPAM without commonsense losses", "spam_vq": "SPAM VQ reconstruction",
               "single_vq": "single-codebook VQ reconstruction"}


def _eval_rows(eval_path: Path) -> list[str]:
    """The headline of `interplay eval --json` saved next to the card as eval.json (written
    by hand after an eval run: the eval needs the exported weights and takes minutes)."""
    if not eval_path.is_file():
        return ["## Evaluation", "Not run yet: `interplay eval --json > "
                "models/weights/spam/eval.json`, then rewrite this card.", ""]
    rep = json.loads(eval_path.read_text())
    ts, cell = rep["test_set"], lambda v, d=3, k=1: "–" if v is None else f"{v[0] * k:.{d}f}±{v[1] * k:.{d}f}"
    lines = ["## Evaluation (text-to-motion metrics)",
             f"`interplay eval --json > models/weights/spam/eval.json` on the test split with the "
             f"project's TMR-style evaluator ({ts['samples']} windows, {ts['texts']} prompts, "
             f"{rep['config']['repeats']} repeats, mean ± 95% CI); protocol and reading in "
             "[`docs/eval.md`](../../../docs/eval.md).", "",
             "| row | R@1 | R@3 | FID | MM-Dist | Diversity | MultiModality | foot skate (m/s) "
             "| penetration (cm) | COM angle (°) |", "|---|---|---|---|---|---|---|---|---|---|"]
    for name, r in rep["rows"].items():
        lines.append(f"| {EVAL_LABELS.get(name, name)} | " + " | ".join(
            cell(r.get(k)) for k in ("top1", "top3", "fid", "mm_dist", "diversity",
                                     "multimodality")) + f" | {cell(r.get('foot_skating'))} | "
            f"{cell(r.get('ground_penetration'), 2, 100)} | {cell(r.get('com_angle'), 1)} |")
    for name, cases in rep.get("edits", {}).items():
        conf = [c["confirmed"] for c in cases]
        lines.append(f"\nPart edits ({name}): the captioner confirms the edited part in "
                     f"{sum(conf) / max(1, len(conf)):.0%} of frames on average over "
                     f"{len(cases)} cases (docs/eval.md lists them).")
    return lines + [""]


def write_card(numbers: dict, path: Path, nocs_path: Path) -> None:
    vq, tr = numbers["configs"]["vq"], numbers["configs"]["transformer"]
    times = numbers["times_s"]
    lines = [
        "# SPAM — body-part RVQ-VAE + masked transformers (CoMA §4.2)",
        "",
        "Single-person text-to-motion generator of Interplay: `vq_encode.onnx`, `vq_decode.onnx`, "
        "`base.onnx`, `residual.onnx` (contract in `models/spam/export.py`), `normalizer.npz`, "
        "`config.json`; all numbers in `metrics.json`. Made by `make train` "
        "(`python -m models.train_all`), code in `models/spam/`.",
        "",
        "## Data",
        f"The processed capture set in `models/data/` (train split only; {numbers['data']['tracks']} "
        f"person tracks incl. left/right mirrored train tracks, {numbers['data']['train_frames']} "
        f"train frames at 20 fps; salsa pairs as two single-person tracks; "
        f"{numbers['data']['texts']} distinct prompts/captions embedded with MiniLM); its sources "
        "and what their licences mean for these weights in the next section.",
        "",
        *licence_section(numbers.get("training_data")),
        "## Model (sizes scaled down from CoMA E.1 to the data and a 2-core CPU)",
        f"- RVQ-VAE: 4 part encoders (CoMA E.2 overlapping parts, input dims from "
        f"`features.part_feature_mask`), conv1d res-blocks width {vq['width']}, depth "
        f"{vq['depth']}, temporal downsampling {vq['downsample']}; per part Q = {vq['layers']} "
        f"residual layers of K = {vq['codes']} EMA codes (latent {vq['latent']}, decay "
        f"{vq['ema_decay']}, codes below {vq.get('dead_fraction', 'n/a')} of the mean usage reset "
        f"to batch latents), quantizer dropout {vq['quantizer_dropout']}, "
        f"β = {vq['beta']}; one whole-body decoder from the concatenated part latents "
        f"({len(PARTS)} × {vq['latent']}) to 239 features. (Paper: Q = 6, K = 512, 128-d.)",
        "- Losses: L1 on normalised features + β·commitment + geometric/commonsense terms on "
        "root-relative joints from the denormalised `positions`/`root_height` blocks: joint "
        "velocity, foot contact, bone length, CODA eq. 4 COM (segment masses) and eq. 5 key-joint "
        "trajectory, plus the joints posed by FK of the decoded 6D rotations on the rest skeleton "
        "(`models/spam/losses.py`). The `spam_nocs` ablation drops them all.",
        f"- Base and residual transformers: d = {tr['d']}, {tr['blocks']} factorised blocks "
        f"(spatial attention over the 4 part tokens of a step, then temporal attention per part), "
        f"{tr['heads']} heads, MLP ×{tr['ff']}, dropout {tr['dropout']}; one text token per part "
        f"(MiniLM 384 → d) prepended to that part's sequence, a learned null token when cond = 0 "
        f"(10% condition dropout); learned positions up to {tr['max_tokens']} tokens (10 s); "
        "training texts 50/50 global prompt repeated / per-part captions; cosine mask schedule, "
        "20% of samples also mask whole parts (as part editing does). Residual model: one "
        "embedding table per layer, layer-index embedding, one output head per layer. "
        "(Paper: 9 layers, 512 wide.)",
        "- Sampling defaults written to config.json (CoMA E.1): " + ", ".join(
            f"{k} = {v}" for k, v in numbers["sampling"].items()) + ".",
        "",
        "## Training time on this machine",
        f"{numbers['machine']}; the CPU was shared with other jobs, so each stage ran "
        "for its wall-clock budget (`models/spam/pipeline.py` Budgets) and the step counts below "
        "are what fitted." + (f" **Note:** {numbers['note']}." if numbers.get("note") else ""),
        "",
        "| stage | seconds |", "|---|---|",
        *[f"| {k} | {v:.0f} |" for k, v in times.items()],
        "",
        "## Reconstruction on the test split (decoded to joints by FK on each track's offsets)",
        "MPJPE over all joints and frames, mm: after FK of the decoded rotations with the root "
        "trajectory integrated from the decoded velocities (global), the same with each frame's "
        "pelvis subtracted (root-relative), of the decoded `positions` block directly (no "
        "FK), and of those positions fitted to the track's skeleton (`kinematics.fit_to_skeleton`, "
        "IK → FK: rigid bones). The three ablation rows ran the same number of steps with the same schedule. "
        "Physical plausibility via `interplay.motion.metrics.clip_metrics` on the FK joints "
        f"(frame-weighted means over {numbers['spam']['recon']['tracks']} test tracks).",
        "",
        *_recon_rows(numbers),
        "",
        "## Codebook usage (train split tokens)",
        "",
        *_usage_rows(numbers),
        "",
        "## Transformers (cross-entropy on masked base tokens / on a random residual layer)",
        "Validation: 20 fixed random batches of val-split windows.",
        "",
        *_transformer_rows(numbers),
        "",
        f"Evaluator: {numbers['evaluator']}.",
        "",
        *_eval_rows(path.parent / "eval.json"),
        "## Limits",
        f"- {numbers['data']['train_frames']} train frames (mirrors included) and "
        f"{numbers['data']['texts']} distinct prompts and automatic part captions: the "
        "transformers learn these families, not open-vocabulary text.",
        "- Budgets are minutes on a shared 2-core CPU; numbers are from one run (seed 0).",
        "",
    ]
    path.write_text("\n".join(lines))
    nocs_path.parent.mkdir(parents=True, exist_ok=True)
    nocs_path.write_text(
        "# SPAM without the geometric/commonsense losses (ablation)\n\n"
        "Same architecture, data and contract as `../spam/`, trained with L1 + commitment only "
        "and smaller transformer budgets; numbers in `../spam/MODEL_CARD.md` and "
        "`../spam/metrics.json`.\n\n" + "\n".join(licence_section(numbers.get("training_data"))))
