"""`interplay bench`: speed of the API, SPAM, CODA and the reactor (`interplay.bench`)."""

from __future__ import annotations

import json

from interplay.cli.args import CliError, seconds


def cmd_bench(args) -> int:
    from interplay.bench.api import format_table, run_bench
    if args.runs < 1:
        raise CliError("--runs must be at least 1")
    from interplay.bench.model import (
        format_default_table,
        format_model_table,
        run_default_bench,
        run_model_bench,
    )
    from interplay.settings import get_settings
    report, tables, only = {}, [], args.only
    if only in (None, "api"):
        report = run_bench(runs=args.runs, seconds=args.seconds, warmup=args.warmup)
        tables.append(format_table(report))
    if only in (None, "model"):
        report["model"] = run_model_bench(get_settings().spam_dir, runs=args.runs,
                                          warmup=args.warmup)
        tables.append(format_model_table(report["model"]))
        report["default"] = run_default_bench(runs=args.runs, warmup=args.warmup)
        tables.append(format_default_table(report["default"]))
    if only in (None, "pair"):
        from interplay.bench.pair import (
            format_default_pair_table,
            format_pair_table,
            run_default_pair_bench,
            run_pair_bench,
        )
        report["pair"] = run_pair_bench(get_settings().coda_dir, runs=args.runs,
                                        warmup=args.warmup)
        tables.append(format_pair_table(report["pair"]))
        report["pair_default"] = run_default_pair_bench(runs=args.runs, warmup=args.warmup)
        tables.append(format_default_pair_table(report["pair_default"]))
    if only in (None, "reaction"):
        from interplay.bench.reaction import format_reaction_table, run_reaction_bench
        report["reaction"] = run_reaction_bench()
        tables.append(format_reaction_table(report["reaction"]))
    print(json.dumps(report, indent=1) if args.json else "\n\n".join(tables))
    return 0


def register(sub) -> None:
    p = sub.add_parser("bench", help="time jobs through the real HTTP API and WebSocket, and "
                       "the SPAM model on onnxruntime")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.add_argument("--runs", type=int, default=3, help="timed jobs per person count (default 3)")
    p.add_argument("--seconds", type=seconds, default=6.0, help="motion length (default 6)")
    p.add_argument("--warmup", type=int, default=1, help="untimed jobs first (default 1)")
    p.add_argument("--only", choices=("api", "model", "pair", "reaction"), help="one section: "
                   "jobs through the API, SPAM on onnxruntime and the product default, CODA two-person generation, or "
                   "the ARFlow reactor (default all)")
    p.set_defaults(func=cmd_bench)
