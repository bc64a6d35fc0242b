"""`interplay data build`: the processed data set from the raw captures."""

from __future__ import annotations

import argparse

from interplay.cli.args import CliError


def cmd_data(args) -> int:
    if args.action != "build":
        raise CliError(f"unknown data action {args.action!r}; expected 'build'")
    from interplay.data.build import main as build_main
    return int(build_main(args.rest) or 0)


def register(sub) -> None:
    p = sub.add_parser("data", help="processed data set: `interplay data build [options]`")
    p.add_argument("action", choices=("build",))
    p.add_argument("rest", nargs=argparse.REMAINDER, help="options passed to the build")
    p.set_defaults(func=cmd_data)
