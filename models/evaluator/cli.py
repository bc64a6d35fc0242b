"""The commands of an evaluator, this one's and the pair evaluator's (which reuses its towers):
train, export, and the two in order (`python -m models.evaluator`,
`python -m models.pair_evaluator`)."""

from __future__ import annotations

import argparse
from dataclasses import replace
from pathlib import Path

import torch

from interplay.motion.clip import DATA_DIR, default_clips


def add_train_args(ap: argparse.ArgumentParser, default_out: Path) -> None:
    """The train command's flags: --out, --data-dir, --steps, --seconds, --seed, --tiny."""
    ap.add_argument("--out", default=str(default_out), help="checkpoint directory")
    ap.add_argument("--data-dir", default=str(DATA_DIR))
    ap.add_argument("--steps", type=int)
    ap.add_argument("--seconds", type=float, help="wall-clock budget")
    ap.add_argument("--seed", type=int)
    ap.add_argument("--tiny", action="store_true", help="a tiny model (smoke runs)")


def train_command(argv: list[str] | None, description: str, configs: tuple, train_fn,
                  default_out: Path, filename: str) -> int:
    """Train (configs: (full, tiny) config, overridden by the flags) and save the checkpoint
    as <out>/<filename>."""
    ap = argparse.ArgumentParser(description=description)
    add_train_args(ap, default_out)
    args = ap.parse_args(argv)
    cfg = configs[1] if args.tiny else configs[0]
    cfg = replace(cfg, **{k: v for k, v in (("steps", args.steps), ("seconds", args.seconds),
                                             ("seed", args.seed)) if v is not None})
    ckpt = train_fn(cfg, default_clips(args.data_dir))
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    torch.save(ckpt, out / filename)
    print(f"wrote {out / filename}: {ckpt['steps']} steps in {ckpt['train_seconds']} s")
    return 0


def export_command(argv, description: str, default_ckpt: Path, default_out: Path, export_fn,
                   load_fn, runtime_cls, check_fn) -> tuple:
    """The export command's start: flags --ckpt, --out, --data-dir, --no-card; writes the
    runtime files, loads them back and checks ONNX against torch (check_fn(model, runtime)).
    Returns (args, checkpoint, torch model, runtime, max |Δ|); the caller measures and writes
    the card unless --no-card."""
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--ckpt", default=str(default_ckpt))
    ap.add_argument("--out", default=str(default_out))
    ap.add_argument("--data-dir", default=str(DATA_DIR))
    ap.add_argument("--no-card", action="store_true", help="skip the measurements and card")
    args = ap.parse_args(argv)
    ckpt = export_fn(args.ckpt, args.out)
    model, _ = load_fn(args.ckpt)
    runtime = runtime_cls.load(args.out)
    err = check_fn(model, runtime)
    print(f"wrote {args.out}; ONNX vs torch max |Δ| = {err:.2e}")
    return args, ckpt, model, runtime, err


def train_and_export(argv: list[str] | None, prog: str, description: str, train_main,
                     export_main, default_out: Path, filename: str, weights: Path) -> int:
    """Run the train command, then the export command on the checkpoint it wrote: the train
    flags, plus --weights (the export's --out), --no-card and --no-export."""
    ap = argparse.ArgumentParser(prog=prog, description=description)
    add_train_args(ap, default_out)
    ap.add_argument("--weights", default=str(weights), help="export directory")
    ap.add_argument("--no-card", action="store_true", help="export without measuring or the card")
    ap.add_argument("--no-export", action="store_true", help="train only")
    args = ap.parse_args(argv)
    train_argv = ["--out", args.out, "--data-dir", args.data_dir]
    for flag, value in (("--steps", args.steps), ("--seconds", args.seconds), ("--seed", args.seed)):
        if value is not None:
            train_argv += [flag, repr(value)]
    train_main(train_argv + ["--tiny"] * args.tiny)
    if args.no_export:
        return 0
    return export_main(["--ckpt", str(Path(args.out) / filename), "--out", args.weights,
                        "--data-dir", args.data_dir] + ["--no-card"] * args.no_card)
