"""The `interplay` command: serve, worker, generate, plan, edit, react, metrics, export, bench, eval,
eval-react, review-eval, eval-pair, data build, actions; one module per command group registers its
subcommands here.

Bad files or arguments exit with code 2 and a one-line message on stderr."""

from __future__ import annotations

import argparse
import sys

from interplay.cli import actions, bench, data, eval_pair, evals, files, generate, react, serve, worker
from interplay.cli.args import CliError

GROUPS = (serve, worker, generate, react, files, bench, evals, eval_pair, data, actions)


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="interplay", description="Text to 3D human motion for one "
                                 "or two people, on CPU.")
    sub = ap.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for group in GROUPS:
        group.register(sub)
    return ap


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except CliError as exc:
        print(f"interplay: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130


if __name__ == "__main__":
    sys.exit(main())
