"""What the studio knows, for people: the catalogue as rows (`GET /api/actions`, `interplay
actions`) and as docs/actions.md (`python -m interplay.catalogue.listing --write`; a test
fails when the committed page differs from the catalogue).

    rows()      → [{"name": "jump", "kind": "whole", "made_by": "capture", "examples": […], …}, …]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from interplay.catalogue.load import catalogue
from interplay.catalogue.schema import Action

DOC = Path(__file__).resolve().parents[3] / "docs" / "actions.md"
KIND_TITLES = {
    "whole": "Whole-body actions", "travel": "Ways of getting somewhere", "part": "Arm and leg actions",
    "gesture": "Named gestures and moves", "pose": "Named poses (can be held)",
    "manner": "Manners (how it is done)", "move": "Moves built from body-part primitives",
    "interaction": "Two-person interactions",
}


def _made(a: Action) -> str:
    m = a.made_by
    if m.composition:
        return f"composed ({m.composition})"
    if m.primitive:
        return f"primitive ({m.primitive})"
    if m.families:
        return "captures: " + ", ".join(m.families)
    return "captures found by its words"


def row(a: Action) -> dict:
    phrases = a.names or a.words or ([a.name] if a.kind != "light" else [])
    return {"name": a.name, "kind": a.kind, "persons": a.persons,
            "description": a.descriptions[0] if a.descriptions else (a.text or ""),
            "phrases": [p.rstrip("*") for p in phrases][:8], "parts": a.parts or ([a.part] if a.part else []),
            "counts": a.counts, "seconds": a.seconds, "made_by": _made(a),
            "checks": [c.check for c in a.checks], "examples": a.examples}


def rows(kinds: tuple[str, ...] = ()) -> list[dict]:
    """Every entry people can ask for (light verbs, which carry no motion, left out)."""
    return [row(a) for a in catalogue().action
            if a.kind != "light" and (not kinds or a.kind in kinds)]


def markdown() -> str:
    out = ["# What you can ask for", "",
           "Made from the catalogue (`backend/interplay/catalogue/actions.toml`) by "
           "`python -m interplay.catalogue.listing --write`; `interplay actions` and "
           "`GET /api/actions` list the same. Words the catalogue does not name are matched to "
           "the nearest captures, and the studio says so (\"not in the library — showing the "
           "nearest: …\").", ""]
    by_kind: dict[str, list[dict]] = {}
    for r in rows():
        by_kind.setdefault(r["kind"], []).append(r)
    for kind, title in KIND_TITLES.items():
        if kind not in by_kind:
            continue
        out += [f"## {title}", "", "| action | say it as | made from | checked by | example |",
                "|---|---|---|---|---|"]
        for r in sorted(by_kind[kind], key=lambda r: r["name"]):
            say = ", ".join(r["phrases"][:4]).replace("|", "/")
            ex = r["examples"][0] if r["examples"] else ""
            out.append(f"| {r['name']} | {say} | {r['made_by']} | {', '.join(r['checks'])} | {ex} |")
        out.append("")
    return "\n".join(out)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m interplay.catalogue.listing")
    ap.add_argument("--write", action="store_true", help=f"write {DOC.name}")
    args = ap.parse_args(argv)
    text = markdown()
    if args.write:
        DOC.write_text(text, encoding="utf-8")
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
