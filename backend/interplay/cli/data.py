"""`interplay data build`: the processed data set from the raw captures; `interplay data
leaves`: the captures' own head and hand orientations beside it (`data/leaves.py`)."""

from __future__ import annotations

import argparse

from interplay.cli.args import CliError


def cmd_data(args) -> int:
    if args.action == "leaves":
        from interplay.data.leaves import main as leaves_main
        return int(leaves_main(args.rest) or 0)
    if args.action != "build":
        raise CliError(f"unknown data action {args.action!r}; expected 'build' or 'leaves'")
    from interplay.data.build import main as build_main
    return int(build_main(args.rest) or 0)


def register(sub) -> None:
    p = sub.add_parser("data", help="processed data set: `interplay data build [options]`; "
                                     "`interplay data leaves [options]`: the captures' head and "
                                     "hand orientations beside it")
    p.add_argument("action", choices=("build", "leaves"))
    p.add_argument("rest", nargs=argparse.REMAINDER, help="options passed to the build")
    p.set_defaults(func=cmd_data)
