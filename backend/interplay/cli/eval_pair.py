"""`interplay eval-pair`: the parser entry and command (the report is `pair_report`)."""

from __future__ import annotations

import json
import sys

from interplay.cli.args import CliError
from interplay.eval.pair import ROW_NAMES


def cmd_eval_pair(args) -> int:
    from interplay.eval.pair_report import format_table, run_eval_pair
    rows = [r.strip() for r in args.rows.split(",") if r.strip()] if args.rows else list(ROW_NAMES)
    unknown = [r for r in rows if r not in ROW_NAMES]
    if unknown or not rows:
        raise CliError(f"--rows: unknown row(s) {unknown}; expected some of {','.join(ROW_NAMES)}")
    if args.limit is not None and args.limit < 1:
        raise CliError("--limit must be at least 1")
    if args.contact_seeds < 0:
        raise CliError("--contact-seeds must be 0 or more")
    if args.bounds_seeds < 0:
        raise CliError("--bounds-seeds must be 0 or more")
    try:
        report = run_eval_pair(rows, repeats=args.repeats, seed=args.seed, limit=args.limit,
                               contact_seeds=args.contact_seeds, bounds_seeds=args.bounds_seeds,
                               log=lambda m: print(m, file=sys.stderr))
    except (ValueError, FileNotFoundError) as exc:
        raise CliError(str(exc)) from None
    print(json.dumps(report, indent=1) if args.json else format_table(report))
    return 0


def register(sub) -> None:
    p = sub.add_parser("eval-pair", help="two-person generation (real, retrieval, composition, the "
                       "product default, CODA and its ablations) on the test split's pairs: FID, "
                       "IV, IF, contacts, skating, bones, penetration with 95%% intervals, the "
                       "contact check and the penetration bounds on the benchmark's prompts")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.add_argument("--repeats", type=int, default=3, help="repeats for the intervals (default 3)")
    p.add_argument("--rows", help="comma-separated: " + ",".join(ROW_NAMES) + " (default all; "
                   "rows whose weights are missing or untrained are listed as skipped)")
    p.add_argument("--limit", type=int, help="at most this many test windows per set (quick runs)")
    p.add_argument("--contact-seeds", type=int, default=10,
                   help="samples per contact prompt and row (default 10; 0 skips the check)")
    p.add_argument("--bounds-seeds", type=int, default=2,
                   help="outputs per two-person prompt of the eval-prompts test split for the "
                   "penetration bounds (default 2; 0 skips them)")
    p.add_argument("--seed", type=int, default=0)
    p.set_defaults(func=cmd_eval_pair)
