"""`interplay actions`: what the studio knows how to make (the catalogue), as a table or JSON."""

from __future__ import annotations

import json

from interplay.catalogue.listing import KIND_TITLES, rows


def cmd_actions(args) -> int:
    out = rows(tuple(args.kind or ()))
    if args.json:
        print(json.dumps(out, indent=1))
        return 0
    for r in out:
        say = ", ".join(r["phrases"][:3])
        print(f"{r['name']:<28} {r['kind']:<8} {r['made_by'][:34]:<34} {say}")
    print(f"{len(out)} actions; words not listed are shown as the nearest captures, and said so")
    return 0


def register(sub) -> None:
    p = sub.add_parser("actions", help="what can be asked for: the catalogue of actions")
    p.add_argument("--kind", action="append", choices=tuple(KIND_TITLES), help="only this kind (repeatable)")
    p.add_argument("--json", action="store_true", help="JSON rows instead of a table")
    p.set_defaults(func=cmd_actions)
