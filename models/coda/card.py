"""MODEL_CARD.md for models/weights/coda (and a short one per exported ablation) from the
numbers of metrics.json (pipeline.run_all)."""

from __future__ import annotations

from pathlib import Path

from models.common.sources import licence_section

_ROWS = ("coda", "coda_short", "coda_noics", "coda_nogdm", "coda_noppl")
_DESC = {"coda": "CODA (ICS + full CCL), full budget", "coda_short": "CODA, short budget (reference)",
         "coda_noics": "w/o ICS (single codebook)", "coda_nogdm": "w/o GDM (λ_GDM = 0)",
         "coda_noppl": "w/o PPL (λ_PPL = 0)"}


def _recon_table(n: dict) -> list[str]:
    real = n["real"]["test_as_is"]
    lines = ["| variant | CVQ steps | MPJPE (m) | key joints (m) | IV (cm³/frame) | IF | "
             "contact frames | GDM err (m) | PPL (eq. 7) |", "|---|---|---|---|---|---|---|---|---|",
             f"| real test pairs | – | – | – | {real['iv_cm3']:.1f} | {real['if']:.3f} | "
             f"{real['contact_frames']:.2f} | – | – |"]
    for name in _ROWS:
        v = n["variants"].get(name)
        if not v:
            continue
        r = v["recon"]
        lines.append(f"| {_DESC[name]} | {v['cvq_steps']} | {r['mpjpe_m']:.4f} | "
                     f"{r['key_joint_error_m']:.4f} | {r['iv_cm3']:.1f} | {r['if']:.3f} | "
                     f"{r['contact_frames']:.2f} | {r['gdm_m']:.4f} | {r['ppl']:.5f} |")
    return lines


def _reading(n: dict) -> list[str]:
    """Ablation deltas against the short-budget reference, computed from the numbers."""
    v = n["variants"]
    if "coda_short" not in v:
        return []
    ref = v["coda_short"]["recon"]
    out = []
    for name in ("coda_noics", "coda_nogdm", "coda_noppl"):
        if name not in v:
            continue
        r = v[name]["recon"]
        out.append(f"- {_DESC[name]} vs the reference: MPJPE {r['mpjpe_m']:.3f} vs "
                   f"{ref['mpjpe_m']:.3f} m, IF {r['if']:.3f} vs {ref['if']:.3f}, IV "
                   f"{r['iv_cm3']:.0f} vs {ref['iv_cm3']:.0f} cm³, PPL {r['ppl']:.4f} vs "
                   f"{ref['ppl']:.4f}, GDM err {r['gdm_m']:.3f} vs {ref['gdm_m']:.3f} m.")
    main, real = v["coda"]["recon"], n["real"]["test_as_is"]
    out += ["",
            f"The shipped model reconstructs the test pairs to {main['mpjpe_m'] * 100:.1f} cm "
            f"MPJPE (joints in the pair frame, so root drift counts); its reconstructions touch "
            f"{'less' if main['contact_frames'] < real['contact_frames'] else 'more'} than the real "
            f"pairs ({main['contact_frames']:.1f} vs "
            f"{real['contact_frames']:.1f} hand-contact frames per window, IF {main['if']:.3f} vs "
            f"{real['if']:.3f}) and their intersection volume is "
            f"{'larger' if main['iv_cm3'] > real['iv_cm3'] else 'smaller'} (IV "
            f"{main['iv_cm3']:.0f} vs {real['iv_cm3']:.0f} cm³/frame). Caveats: every row is one seed; the ablation rows "
            "are short (under-trained) runs, so differences of a few per cent between them are "
            "within what a second seed could change (not measured); the CCL weights are the "
            "paper's, not tuned here."]
    return out


def _cmt_table(n: dict) -> list[str]:
    lines = ["| variant | CMT steps | train CE | val CE | val accuracy |", "|---|---|---|---|---|"]
    for name in _ROWS:
        v = n["variants"].get(name)
        if v and "cmt_val" in v:
            lines.append(f"| {_DESC[name]} | {v['cmt_steps']} | {v['cmt_final']['ce']:.3f} | "
                         f"{v['cmt_val']['ce']:.3f} | {v['cmt_val']['acc']:.3f} |")
    return lines


def _search_table(n: dict) -> list[str]:
    rows = n["variants"]["coda"].get("sampling_search")
    if not rows:
        return ["(no search in this run: the paper's defaults)"]
    real = rows[0]["real"]
    lines = ["| CFG | temperature | top-k | IF | contact share | pelvis distance (m) | IV | score |",
             "|---|---|---|---|---|---|---|---|",
             f"| real val pairs | | | {real['if']:.3f} | {real['contact_share']:.3f} | "
             f"{real['pelvis_distance_m']:.2f} | {real['iv_cm3']:.1f} | |"]
    for r in rows[1:]:
        s = r["setting"]
        lines.append(f"| {s['cfg']} | {s['temperature']} | {s['topk']} | {r['if']:.3f} | "
                     f"{r['contact_share']:.3f} | {r['pelvis_distance_m']:.2f} | "
                     f"{r['iv_cm3']:.1f} | {r['score']:.3f} |")
    return lines


def write_cards(n: dict, weights: Path) -> None:
    cvq, cmt, d = n["configs"]["cvq"], n["configs"]["cmt"], n["data"]
    status = ("" if n["trained"] else
              "\n**EARLY EXPORT (`\"trained\": false`): a short training so the runtime can be "
              "developed against real files; not for serving.**\n")
    lines = [
        "# CODA two-person interaction model (`encode.onnx`, `decode.onnx`, `cmt.onnx`)", status,
        "CODA (paper 000, §3.1–3.3): a CVQ-VAE with the Interactive Codebook Storager (ICS) "
        "trained under the Commonsense Constraint Loss (CCL), and a Conditional Masked "
        "Transformer (CMT) over both people's pose tokens. Code: `models/coda/`.", "",
        "## Data", "",
        f"Two-person clips of `models/data` (captured salsa pairs + composed SYNTHETIC pairs), "
        f"80-frame windows (4 s at 20 fps; 20 tokens per person). Train: {d['train']['windows']} "
        f"windows from {d['train']['clips']} clips ({d['train']['synthetic']} synthetic), both "
        f"role orders, mirrored left/right, stride 10. Val: {d['val']['windows']} windows "
        f"(checkpoint/sampling choice), test: {d['test']['windows']} windows (both role orders, "
        "not mirrored, stride 20); the test tables use one role order per window "
        f"({d['test_as_is']['windows']} windows). Per person and frame: 22 joints (66 numbers) in "
        "the pair's canonical frame (first person's pelvis at the XZ origin facing +Z at "
        "frame 0), normalised by one mean/std shared by both people (`normalizer.npz`). Text: "
        "MiniLM (384-d) embedding of the clip prompt.", "",
        *licence_section(n.get("training_data")),
        "## Sizes", "",
        f"- CVQ-VAE: shared conv encoder φ (width {cvq['width']}, {cvq['depth']} res-blocks per "
        f"stage, ×{cvq['downsample']} temporal downsampling), latent d' = {cvq['latent']}, pose "
        f"codebook |C| = {cvq['codes']}, interaction codebook |P| = {cvq['interaction_codes']} "
        f"(EMA {cvq['ema_decay']}, dead-code reset); ICS = one self-attention ψ + one "
        f"cross-attention φ ({cvq['heads']} heads, relative-time bias ±{cvq['rel_range']} "
        "steps) + MLP, shared by both people; pose decoder from w = z + t, commonsense "
        f"decoder (width {cvq['width'] // 2}) from z. The paper: d' = 512, |C| = |P| = 1024.",
        f"- CMT: {cmt['blocks']} blocks, d = {cmt['d']}, {cmt['heads']} heads, MLP ×{cmt['ff']}, "
        "plain attention over the 2n tokens of both people (person embedding, relative-time "
        f"bias ±{cmt['rel_range']} with separate same-person / cross-person tables, so any "
        f"n ≤ max_tokens = {cmt['max_tokens']} runs; trained at n = 20), text added in every "
        "block (zeros → learned null vector; dropped 10 % in training), cosine mask schedule, "
        "cross-entropy on masked tokens. The paper: 6 blocks × 384.", "",
        "## Losses (weights)", "",
        "Eq. 3: L1 reconstruction of the normalised joints + α = 0.02 pose commitment + L1 of "
        "the commonsense decoder (read as reconstructing the person's motion from z alone) + "
        "β = 0.02 interaction commitment. CCL (Algorithm 1) on the decoded joints in metres: "
        "λ_COM = 1 (eq. 4, COM = joint mean), λ_KTraj = 1 (eq. 5, pelvis/wrists/toes), "
        "λ_GDM = 0.5 (eq. 6, τ = 0.5, every 2nd frame), λ_PPL = 0.01 (eq. 7, 4×4 part-chain "
        "pairs, predicted-pair AABB overlap, every 8th frame), geometric: velocity 1, foot "
        "contact 1, bone length 1. The torch terms equal `interplay.motion.pair.interaction`'s numpy "
        "ones (tests/models/test_coda_losses.py).", "",
        "## Training", "",
        f"CPU, {n['machine']}, shared with other jobs. Budgets (s): {n['budgets_s']}. "
        f"Times (s): {n['times_s']}. CVQ batch {n['configs']['cvq_train']['batch']} pairs, "
        f"CMT batch {n['configs']['cmt_train']['batch']}, AdamW lr 1e-3 warm-up + cosine. "
        "The ablation rows train the same number of CVQ steps as `coda_short` (the reference "
        "row), each with a short CMT; `coda` is the shipped full-budget model.", "",
        "## Reconstruction of the test pairs (CVQ-VAE: encode both people, decode the pair)", "",
        *_recon_table(n), "", *_reading(n), "",
        "IV: mean sphere-body intersection volume per frame; IF: share of frames with "
        "intersecting bodies; contact frames: per 80-frame window, a hand within 3 cm of the "
        "other body (`interplay.motion.metrics.pair_geometry`). GDM err / PPL: eq. 6 / eq. 7 "
        "of the reconstruction against the real pair (numpy, every 4th frame).", "",
        "## CMT (masked-token prediction)", "", *_cmt_table(n), "",
        "## Sampling defaults (`config.json` \"sampling\")", "",
        f"Chosen: {n['sampling']}. Grid on the validation prompts (one pair per window, 10 "
        "steps):", "", *_search_table(n), "",
        "## Files and contract", "",
        "See `models/coda/export.py`: `encode.onnx` x (B, T, 66) → codes (B, T/4); `decode.onnx` "
        "codes_a, codes_b (B, n) → x_a, x_b (B, 4n, 66); `cmt.onnx` codes (B, 2, n) (K = mask), "
        "text (B, 384) → logits (B, 2, n, K). ONNX vs torch max error: "
        f"{n['onnx_roundtrip_max_error']}.", "",
        "## Commands", "",
        "    .venv/bin/python -m models.coda --all            # this card (part of make train)",
        "    .venv/bin/python -m models.coda --all --scale 0.5",
        "    .venv/bin/pytest -q tests/models/test_coda_model.py tests/models/test_coda_losses.py",
    ]
    (weights / "coda" / "MODEL_CARD.md").write_text("\n".join(lines) + "\n")
    for name in ("coda_noics", "coda_nogdm", "coda_noppl"):
        if name in n["variants"] and (weights / name).exists():
            (weights / name / "MODEL_CARD.md").write_text(
                f"# {name}: CODA ablation — {_DESC[name]}\n\nSame data, sizes and contract as "
                "`../coda/MODEL_CARD.md` (where its numbers are), trained for "
                f"{n['variants'][name]['cvq_steps']} CVQ steps and "
                f"{n['variants'][name].get('cmt_steps', 0)} CMT steps (the short ablation "
                "budget): for the ablation rows of the evaluation, not for serving.\n\n"
                + "\n".join(licence_section(n.get("training_data"))))
