"""`interplay eval`, `eval-react`, `review-eval` and `eval-prompts`: the measurement commands (the
reports live in `interplay.eval`)."""

from __future__ import annotations

import json
import sys

from interplay.cli.args import CliError
from interplay.eval.prompts.suite import SPLITS as SUITE_SPLITS
from interplay.eval.rows import ROW_NAMES


def _sampling_args(items: list[str] | None) -> list[tuple[str, object]]:
    """["cfg=2.5", "mode=inpaint"] → [("cfg", 2.5), ("mode", "inpaint")] (numbers parsed)."""
    out = []
    for item in items or []:
        key, sep, value = item.partition("=")
        if not sep or not key.strip():
            raise CliError(f"--sampling takes KEY=VALUE, got {item!r}")
        try:
            parsed: object = int(value) if value.strip().lstrip("-").isdigit() else float(value)
        except ValueError:
            parsed = value
        out.append((key.strip(), parsed))
    return out


def cmd_eval(args) -> int:
    from interplay.eval.report import EvalConfig, format_table, run_eval
    rows = [r.strip() for r in args.rows.split(",") if r.strip()] if args.rows else list(ROW_NAMES)
    unknown = [r for r in rows if r not in ROW_NAMES]
    if unknown or not rows:
        raise CliError(f"--rows: unknown row(s) {unknown}; expected some of {','.join(ROW_NAMES)}")
    try:
        cfg = EvalConfig(repeats=args.repeats, seed=args.seed, split=args.split,
                         sampling=tuple(_sampling_args(args.sampling)))
        report = run_eval(rows, cfg, log=lambda m: print(m, file=sys.stderr))
    except (ValueError, FileNotFoundError) as exc:
        raise CliError(str(exc)) from None
    except TypeError as exc:     # a --sampling key the runtime does not take
        raise CliError(f"--sampling: {exc}") from None
    print(json.dumps(report, indent=1) if args.json else format_table(report))
    return 0


def cmd_eval_react(args) -> int:
    from dataclasses import replace as _replace

    from interplay.eval.reaction import ROWS, format_table, run_eval_react
    from interplay.reaction.session import get_reaction_model
    try:
        rows = tuple(args.rows.split(",")) if args.rows else ROWS
        if any(r not in ROWS for r in rows):
            raise ValueError(f"--rows: expected some of {','.join(ROWS)}, got {args.rows!r}")
        model = get_reaction_model()
        sampling = model.sampling
        for item in args.sampling or ():
            key, _, value = item.partition("=")
            if key not in sampling.__dataclass_fields__ or not value:
                raise ValueError(f"--sampling {item!r}: expected KEY=VALUE with KEY one of "
                                 f"{', '.join(sampling.__dataclass_fields__)}")
            kind = type(getattr(sampling, key))
            sampling = _replace(sampling, **{key: kind(float(value)) if kind is int else kind(value)})
        report = run_eval_react(rows, repeats=args.repeats, seed=args.seed, model=model,
                                sampling=sampling, split=args.split,
                                log=lambda m: print(m, file=sys.stderr))
    except (FileNotFoundError, ValueError) as exc:
        raise CliError(str(exc)) from None
    print(json.dumps(report, indent=1) if args.json else format_table(report))
    return 0


def _review_honesty(args, generator) -> int:
    """The reviewer's verdicts against the benchmark's checks on the prompt suite's split."""
    import numpy as np

    from interplay.eval.prompts import suite
    from interplay.eval.review import format_honesty, run_honesty
    from interplay.pipeline.orchestrator import default_evaluator, orchestrate
    if args.seeds < 1:
        raise CliError("--seeds must be at least 1")
    ids = [i.strip() for i in args.ids.split(",")] if args.ids else None
    try:
        prompts = (suite.load_split(args.split, ids=ids) if hasattr(suite, "load_split")
                   else suite.select(suite.load_suite(), args.split, ids=ids))
    except ValueError as exc:
        raise CliError(str(exc)) from None
    # a part edit's prompt judges the edit, not the generation the reviewer sees: left out
    prompts = [p for p in prompts if getattr(p, "edit", None) is None]
    if not prompts:
        raise CliError(f"no prompts in split {args.split!r}")
    evaluator = default_evaluator()

    def make(req):
        out = orchestrate(generator, req, lambda e: None, lambda s, c: None, evaluator=evaluator)
        return [np.asarray(p, np.float64) for p in out.people], out.review
    report = run_honesty(make, prompts[:args.limit], seeds=args.seeds,
                         log=lambda m: print(m, file=sys.stderr))
    report["split"] = args.split
    print(json.dumps(report, indent=1) if args.json else format_honesty(report))
    return 0


def cmd_review_eval(args) -> int:
    """The reviewer before/after its correction rounds on CoMA's 40 Table 8 prompts, or
    (`--honesty`) its verdicts against the benchmark's checks on a prompt split."""
    from interplay.eval.review import format_table, run, table8_prompts
    from interplay.generators.router import load_generator
    from interplay.settings import get_settings
    if args.limit is not None and args.limit < 1:
        raise CliError("--limit must be at least 1")
    settings = get_settings()
    generator = load_generator(settings)
    if args.honesty:
        return _review_honesty(args, generator)
    prompts = table8_prompts()[:args.limit]
    report = run(generator, prompts, seconds=args.seconds, rounds=args.rounds,
                 log=lambda m: print(m, file=sys.stderr))
    print(json.dumps(report, indent=1) if args.json else format_table(report))
    return 0


def cmd_review_calibrate(args) -> int:
    from interplay.eval.calibrate import calibrate, format_table
    try:
        out = calibrate(write=not args.dry_run, log=lambda m: print(m, file=sys.stderr))
    except (ValueError, FileNotFoundError) as exc:
        raise CliError(str(exc)) from None
    print(json.dumps(out, indent=1) if args.json else format_table(out))
    return 0


def cmd_eval_prompts(args) -> int:
    """Every generator row on the prompt suite's split, judged by the checks on the motion."""
    import time
    from pathlib import Path

    from interplay.eval.prompts.report import build_report, format_table, run, write
    from interplay.eval.prompts.rows import ROW_NAMES as PROMPT_ROWS
    from interplay.eval.prompts.rows import load_rows
    from interplay.eval.prompts.suite import load_split
    from interplay.motion.clip import DATA_DIR, default_clips
    from interplay.settings import get_settings
    names = [r.strip() for r in args.rows.split(",") if r.strip()] if args.rows else list(PROMPT_ROWS)
    if args.seeds < 1:
        raise CliError("--seeds must be at least 1")
    try:
        prompts = load_split(args.split,
                             ids=[i.strip() for i in args.ids.split(",")] if args.ids else None)
        if not prompts:
            raise ValueError(f"no prompts in split {args.split!r}" + (f" with ids {args.ids}" if args.ids else ""))
        rows, skipped = load_rows(names, get_settings())
    except (ValueError, FileNotFoundError) as exc:
        raise CliError(str(exc)) from None
    out = Path(args.out or f"var/eval-prompts/{args.split}")
    t0 = time.monotonic()
    results = run(rows, prompts, seeds=args.seeds, out=out, log=lambda m: print(m, file=sys.stderr))
    clips = default_clips(str(get_settings().data_dir or DATA_DIR))
    sources: dict[str, int] = {}
    for c in clips:
        sources[c.source] = sources.get(c.source, 0) + 1
    report = build_report(rows, skipped, prompts, results, args.split, args.seeds,
                          time.monotonic() - t0, {"clips": len(clips), "sources": dict(sorted(sources.items()))})
    write(out, report, results)
    print(json.dumps(report, indent=1) if args.json else format_table(report))
    print(f"per-prompt results and motions: {out}/", file=sys.stderr)
    return 0


def register(sub) -> None:
    p = sub.add_parser("eval", help="text-to-motion metrics (R-precision, FID, …) of every "
                       "generator on the test split, with 95%% confidence intervals")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.add_argument("--repeats", type=int, default=10, help="repeats for the CIs (default 10)")
    p.add_argument("--rows", help="comma-separated: " + ",".join(ROW_NAMES) + " (default all; "
                   "rows without weights are skipped)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--split", choices=("test", "val"), default="test",
                   help="val: choose settings there (its own edit cases), never on test")
    p.add_argument("--sampling", nargs="*", metavar="KEY=VALUE",
                   help="SPAM rows' settings, e.g. cfg=2.5 steps=10 mode=inpaint")
    p.set_defaults(func=cmd_eval)

    p = sub.add_parser("eval-react", help="ARFlow reactions on the test split's pairs: FID, "
                       "IV, IF, contacts, skating without/with guidance and reprojection")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.add_argument("--repeats", type=int, default=2, help="sampling seeds per row (default 2)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--split", choices=("test", "val"), default="test",
                   help="val: for choosing sampling settings (never tune on test)")
    p.add_argument("--rows", help="comma-separated subset of the rows (default all)")
    p.add_argument("--sampling", action="append", metavar="KEY=VALUE",
                   help="override a sampling setting, e.g. guidance=0.5 (repeatable)")
    p.set_defaults(func=cmd_eval_react)

    p = sub.add_parser("review-eval", help="the reviewer before/after its correction rounds on "
                       "CoMA's 40 Table 8 prompts (alignment, confirmed part edits, metrics)")
    p.add_argument("--json", action="store_true", help="the full report as JSON")
    p.add_argument("--limit", type=int, help="only the first N prompts")
    p.add_argument("--seconds", type=float, default=8.0, help="length per prompt (default 8)")
    p.add_argument("--rounds", type=int, default=2, help="K review rounds (default 2)")
    p.add_argument("--honesty", action="store_true", help="instead: the studio's verdicts on "
                   "the prompt suite's split against its checks (outputs failing half or more "
                   "that end ok, outputs passing all that end failed)")
    p.add_argument("--split", choices=SUITE_SPLITS, default="test", help="--honesty's split")
    p.add_argument("--seeds", type=int, default=1, help="--honesty's seeds per prompt (default 1)")
    p.add_argument("--ids", help="--honesty: comma-separated prompt ids")
    p.set_defaults(func=cmd_review_eval)

    p = sub.add_parser("review-calibrate", help="the reviewer's thresholds: the evaluators' "
                       "scores on the test split's captures with their own and other families' "
                       "captions, ROC and a logistic confidence → calibration.json beside the weights")
    p.add_argument("--json", action="store_true", help="the whole calibration as JSON")
    p.add_argument("--dry-run", action="store_true", help="measure only, write nothing")
    p.set_defaults(func=cmd_review_calibrate)

    p = sub.add_parser("eval-prompts", help="pass rates of every generator on a suite of prompts "
                       "as users type them, checked on the motion itself (per category, 95%% CI "
                       "over seeds)")
    p.add_argument("--split", choices=SUITE_SPLITS, default="test",
                   help="dev: tune there; test: the benchmark (default); fresh: prompts in "
                   "words the code has no table for, part edits among them; fresh2, fresh3, "
                   "fresh4: everyday prompts written blind (without seeing the studio's "
                   "vocabulary)")
    p.add_argument("--rows", help="comma-separated: retrieval,spam,coda,default (default all; "
                   "rows whose weights are missing are skipped)")
    p.add_argument("--seeds", type=int, default=3, help="seeds per prompt (default 3)")
    p.add_argument("--ids", help="comma-separated prompt ids (default every prompt of the split)")
    p.add_argument("--json", action="store_true", help="the report as JSON")
    p.add_argument("--out", help="where per-prompt results and motions go "
                   "(default var/eval-prompts/SPLIT)")
    p.set_defaults(func=cmd_eval_prompts)
