"""Build `backend/interplay/catalogue/wordnet_verbs.json.gz`: the verb half of the Open English
WordNet (CC BY 4.0, derived from Princeton WordNet under the WordNet licence), reduced to what
the planner reads: each verb lemma's senses in WordNet's order, and each verb sense's lexicographer
file (motion, contact, body …), member lemmas, hypernyms and first definition. Read from a `fetch`ed snapshot of
github:globalwordnet/english-wordnet at the commit named below (interplay.data.mirror); the app
reads only the file written here.

    .venv/bin/python scripts/build_wordnet_verbs.py [--mirror DIR]
"""

from __future__ import annotations

import argparse
import gzip
import json
import sys
from pathlib import Path

import yaml

from interplay.data.mirror import Snapshot, mirror_root

OEWN = Snapshot(repo="globalwordnet/english-wordnet",
                commit="d94538ad0df3d7a4c77837bde6af69d7a6592c32", path="src/yaml",
                licence="CC BY 4.0 (Open English WordNet) and the WordNet 3.0 licence (Princeton WordNet)")
OUT = Path(__file__).resolve().parents[1] / "backend" / "interplay" / "catalogue" / "wordnet_verbs.json.gz"


def _load(snapshot: Snapshot, root: Path, rel: str) -> dict:
    text = snapshot._git(root, "show", f"{snapshot.commit}:{rel}").stdout
    return yaml.load(text, Loader=yaml.CSafeLoader) or {}


def build(root: Path) -> dict:
    files = OEWN.files(root)
    synsets: dict[str, list] = {}
    for rel in (f for f in files if Path(f).name.startswith("verb.")):
        lexfile = Path(rel).name[len("verb."):-len(".yaml")]
        for sid, s in _load(OEWN, root, rel).items():
            synsets[sid] = [lexfile, list(s.get("members", [])), list(s.get("hypernym", [])),
                            (s.get("definition") or [""])[0]]
    lemmas: dict[str, list[str]] = {}
    for rel in (f for f in files if Path(f).name.startswith("entries-")):
        for lemma, pos in _load(OEWN, root, rel).items():
            senses = (pos or {}).get("v", {}).get("sense", []) if isinstance(pos, dict) else []
            ids = [s["synset"] for s in senses if s.get("synset") in synsets]
            if ids:
                lemmas[str(lemma).lower()] = ids
    return {"source": {"repository": f"https://github.com/{OEWN.repo}", "commit": OEWN.commit,
                       "path": OEWN.path, "licence": OEWN.licence,
                       "attribution": "Open English WordNet (https://en-word.net), based on Princeton "
                                      "WordNet 3.0, Copyright 2006 by Princeton University"},
            "synsets": synsets, "lemmas": lemmas}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--mirror", type=Path, default=None, help="folder of fetched snapshots")
    args = ap.parse_args(argv)
    data = build(args.mirror or mirror_root())
    raw = json.dumps(data, separators=(",", ":"), sort_keys=True).encode("utf-8")
    with open(OUT, "wb") as f, gzip.GzipFile(fileobj=f, mode="wb", compresslevel=9, mtime=0) as z:
        z.write(raw)                         # mtime 0: the same snapshot gives the same bytes
    print(f"{OUT}: {len(data['synsets'])} verb senses, {len(data['lemmas'])} lemmas, "
          f"{OUT.stat().st_size / 1e6:.2f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
