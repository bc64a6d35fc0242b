"""`interplay data build --staged`: sources read from named repository snapshots (`mirror`),
written to `models/data/staged/` (its own index.json, one npz per source, README.md card with
the provenance manifest).

Staged sources are opt-in at run time: the app's `default_clips()` reads `models/data/index.json`
only, so nothing here changes retrieval, the behaviour fixtures or the trained models until a
later step moves a staged source into the main build (and regenerates fixtures and evaluations).
Load them explicitly with `interplay.motion.clip.load_clips(STAGED_DIR)`.

Sources:
- `bandai-namco-2`: the rest of Bandai Namco Research motion dataset 2 (the 2,482 clips of its
  2,902 that ../shared/data/bandai-namco/dataset-2 does not hold): walk, turns, run, waves and
  raised hands in 7 styles, 3 actors; CC BY-NC 4.0 (non-commercial), the same retargeter as
  `bandai-namco` (`interplay.motion.retarget.bandai_namco`).
- `reactidle`: ReActIdle's idle standing captures (acted and genuine, one performer's takes
  share a split), MIT (`interplay.motion.retarget.reactidle`). The snapshot lacks three acted
  takes (files of 4 MiB and more).
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

from interplay.data.card import _family_lines, _hours, _rate_lines
from interplay.data.cmu_pairs import PAIRS, build_cmu_pairs
from interplay.data.licences import BANDAI_NAMCO, MIT_REACTIDLE
from interplay.data.mirror import Snapshot, SnapshotMissing, mirror_root
from interplay.data.pairs import pair_contact_lines
from interplay.data.splits import _stable_rank, add_captions, stratified_split
from interplay.motion.clip import DATA_DIR, Clip, save_clips
from interplay.motion.labels import label_family
from interplay.motion.skeleton import FPS

STAGED_DIR = DATA_DIR / "staged"
DEFAULT_SOURCE = DATA_DIR.parents[2] / "shared" / "data"   # ../shared/data, as the main build

BANDAI = Snapshot(
    repo="BandaiNamcoResearchInc/Bandai-Namco-Research-Motiondataset",
    commit="74ead3ba1ae4696404e6086233779f60de8bf9ef",
    path="dataset/Bandai-Namco-Research-Motiondataset-2",
    licence="CC BY-NC 4.0 (dataset/Bandai-Namco-Research-Motiondataset-2/LICENSE)")

REACTIDLE = Snapshot(
    repo="Enekoassets/ReActIdle",
    commit="90b0ac78b205001edf170f65ff372448ccd0f1c7",
    path=".",
    licence="MIT (LICENSE.txt, \"Copyright (c) 2025 [RSAIT]\")")

CMU_MOCAP = Snapshot(
    repo="una-dinosauria/cmu-mocap",
    commit="62ac0fb0ec43cff2bf66426928f4fa6682d4bbdc",
    path=".",
    licence="CMU terms (mocap.cs.cmu.edu; the repository has no licence of its own)")

SNAPSHOTS = {"bandai-namco-2": BANDAI, "reactidle": REACTIDLE, "cmu-pairs": CMU_MOCAP}
SKIPPED: list[tuple[str, list[str]]] = []
# Files under a staged source's path that its snapshot lacks (it leaves out files of 4 MiB and more).
ABSENT: dict[str, list[str]] = {}


def build_bandai_more(raw: Path, shared: Path, limit: int | None = None) -> list[Clip]:
    """Dataset 2's clips from the extracted snapshot folder `raw` (its data/ and cfg/), less
    those ../shared/data/bandai-namco/dataset-2 holds (the main build's `bandai-namco`); at
    most `limit` files, taken by a stable hash of the name."""
    from interplay.motion.retarget.bandai_namco import bandai_prompt, load_bandai, read_labels

    have = {p.name for p in (shared / "bandai-namco" / "dataset-2" / "data").glob("*.bvh")}
    paths = sorted((raw / "data").glob("*.bvh"))
    if limit is not None:
        paths = sorted(sorted(paths, key=lambda p: _stable_rank(p.name))[:limit])
    clips = []
    for path in paths:
        if path.name in have:
            continue
        rel = f"{BANDAI.path}/data/{path.name}"
        labels = read_labels(path)
        joints, offsets, meta = load_bandai(path)
        meta.update({"file": rel, "repository": BANDAI.repo, "commit": BANDAI.commit, **labels})
        if meta["defects"]:
            SKIPPED.append((rel, meta["defects"]))
            continue
        clips.append(Clip(id=f"bandai2:{path.stem}", source="bandai-namco-2", people=[joints],
                          offsets=[offsets], label=f"{labels['content']} ({labels['style']})",
                          prompt=bandai_prompt(labels["content"], labels["style"]),
                          licence=BANDAI_NAMCO.name, meta=meta))
    return clips


def build_reactidle(raw: Path) -> list[Clip]:
    """ReActIdle's acted and genuine idle captures (the extracted snapshot folder `raw`)."""
    from interplay.motion.retarget.reactidle import load_reactidle, reactidle_prompt

    clips = []
    for path in sorted(raw.glob("*/*.bvh")):
        kind = path.parent.name
        person = path.stem.split("_")[0]
        rel = f"{kind}/{path.name}"
        joints, offsets, meta = load_reactidle(path)
        meta.update({"file": rel, "repository": REACTIDLE.repo, "commit": REACTIDLE.commit,
                     "person": person, "kind": kind})
        if meta["defects"]:
            SKIPPED.append((f"reactidle/{rel}", meta["defects"]))
            continue
        clips.append(Clip(id=f"reactidle:{path.stem}", source="reactidle", people=[joints], offsets=[offsets],
                          label=f"idle ({kind})", prompt=reactidle_prompt(kind), licence=MIT_REACTIDLE.name,
                          meta=meta))
    return clips


def assign_staged_splits(clips: list[Clip]) -> None:
    """Bandai Namco by take within each content (as the main build): 15% test, 10% val.
    ReActIdle by performer (one person's acted and genuine takes share a split)."""
    groups: dict[str, list[str]] = {}
    people: dict[str, list[str]] = {}
    for c in clips:
        if c.source == "cmu-pairs":
            groups.setdefault(f"cmu-pairs:{c.meta['kind']}", []).append(c.id)
        elif c.source == "reactidle":
            people.setdefault(c.meta["person"], []).append(c.id)
        else:
            groups.setdefault(f"{c.source}:{c.meta.get('content', label_family(c.prompt))}", []).append(c.id)
    split = stratified_split(groups)
    for person, s in stratified_split({"reactidle": sorted(people)}).items():
        split.update({cid: s for cid in people[person]})
    for c in clips:
        c.split = split.get(c.id, "train")


def _check_lines(clips: list[Clip]) -> list[str]:
    """Per source: how many clips pass the benchmark's no-pops and grounded checks (the
    retargeters' own checks, broken roots and foot contact, already left failures out)."""
    from interplay.motion.bodyframe import body_frame
    from interplay.motion.checks.named import grounded, no_pops

    out = []
    for source in SNAPSHOTS:
        group = [c for c in clips if c.source == source]
        if not group:
            continue
        ok = [all(check(p, body_frame(p, FPS))[0] for p in c.people for check in (no_pops, grounded))
              for c in group]
        out.append(f"- {source}: {sum(ok)} of {len(group)} clips pass `no_pops` and `grounded` "
                   "(`interplay.motion.checks.named`); bones are fixed by the fit (IK → FK), the broken-root "
                   "and foot-contact checks of `interplay.motion.retarget.checks` ran in the retargeter.")
    return out


def _pair_rate_lines(clips: list[Clip]) -> list[str]:
    """CMU's pairs are read at CMU's indexed rate; where `estimate_true_fps` disagrees for a
    person, the pair is named."""
    pairs = [c for c in clips if c.source == "cmu-pairs"]
    if not pairs:
        return []
    used = sorted({f"{c.meta['source_fps']:g}" for c in pairs})
    off = [c.id for c in pairs if any(abs(e - c.meta["source_fps"]) > 1e-6 for e in c.meta["fps_estimate"])]
    return [f"- cmu-pairs: CMU's indexed rate used ({', '.join(used)} fps); the estimate agrees for both people "
            f"in {len(pairs) - len(off)} of {len(pairs)} pairs" + (f" (differs: {', '.join(off)})" if off else "") + "."]


def write_staged_card(clips: list[Clip], out: Path) -> None:
    lines = ["# Staged capture data (models/data/staged)", "",
             "Written by `interplay data build --staged` (`backend/interplay/data/staged.py`) from named",
             "repository snapshots; **not loaded by the app** (`default_clips()` reads `models/data/index.json`",
             "only). Same processing as the main set (22 joints, 20 fps, fixed bones, canonical frame).", "",
             "## Provenance manifest", "", "| source | repository | commit | path | licence | clips | hours |",
             "|---|---|---|---|---|---|---|"]
    for source, snap in SNAPSHOTS.items():
        group = [c for c in clips if c.source == source]
        frames = sum(p.shape[0] for c in group for p in c.people)
        lines.append(f"| {source} | {snap.repo} | `{snap.commit}` | `{snap.path}` | {snap.licence} | "
                     f"{len(group)} | {_hours(frames):.2f} |")
    for source in SNAPSHOTS:
        if not any(c.source == source for c in clips):
            lines.append(f"\n{source}: not built on this machine: its raw files are in no mirror"
                         + (" nor in ../shared/data/cmu-pairs (the snapshot is 789 MB, over the 500 MiB that "
                            "`fetch` brings; `interplay.data.cmu_pairs` says what to copy there)"
                            if source == "cmu-pairs" else "") + ".")
    lines += ["", "Fetch step: the search tool's `fetch github:<repository>` puts a bare git directory at",
              "`/work/.mirror/<owner>+<name>/repo`; the build reads the commit above from it (`git cat-file`)",
              "and stops with a message naming this step when it is absent.", "",
              "## Frame rates", "", *[f"- {n}" for n in _rate_lines(clips, ("bandai-namco-2", "reactidle"))],
              *_pair_rate_lines(clips), ""]
    lines += ["## Checks", "", *_check_lines(clips), ""]
    left = [f"- `{f}`: {'; '.join(r)}" for f, r in SKIPPED]
    left += [f"- `{name}: {f}`: absent from the snapshot (4 MiB or more)" for name, fs in ABSENT.items() for f in fs]
    if left:
        lines += ["## Left out", "", *left, ""]
    lines += _family_lines(clips)
    lines += pair_contact_lines(clips)
    lines += ["## Split (by take, never by window)", "",
              "bandai-namco-2: within each content, takes ordered by a stable hash of the file name: 15% test,",
              "10% val. reactidle: by performer (the number in the file name; one performer's acted and genuine",
              "takes share a split), performers ordered by a stable hash. ReActIdle's prompts fall in",
              "`label_family`'s \"other\" (it has no idle family). cmu-pairs: by trial within each interaction",
              "kind (stable hash), as the main build splits salsa.", "",
              "| source | train | val | test |", "|---|---|---|---|"]
    for source in SNAPSHOTS:
        n = {s: sum(1 for c in clips if c.source == source and c.split == s) for s in ("train", "val", "test")}
        lines.append(f"| {source} | {n['train']} | {n['val']} | {n['test']} |")
    lines += ["", "## Licences", "",
              f"- `bandai-namco-2.npz`: {BANDAI_NAMCO.consequence}. Credit: {BANDAI_NAMCO.credit}",
              f"- `reactidle.npz`: {MIT_REACTIDLE.consequence}. Credit: {MIT_REACTIDLE.credit}", ""]
    (out / "README.md").write_text("\n".join(lines))


def _raw(name: str, tmp: Path, root: Path, source: Path) -> Path:
    """The raw folder a staged source is built from: its snapshot, extracted into `tmp`; CMU's
    pairs from ../shared/data/cmu-pairs when it exists, else their subjects' folders of the
    una-dinosauria snapshot."""
    if name != "cmu-pairs":
        return SNAPSHOTS[name].extract(tmp, root)
    if (source / "cmu-pairs").is_dir():
        return source / "cmu-pairs"
    try:
        CMU_MOCAP.require(root)
    except SnapshotMissing as e:
        raise SnapshotMissing(f"{e}; or copy its BVH files of subjects 18-23, 33, 34 (0SS/SS_TT.bvh) into "
                              f"{source / 'cmu-pairs'} (the snapshot is 789 MB, over what fetch brings)") from None
    for pair in PAIRS:
        for subject in pair:
            CMU_MOCAP.extract(tmp, root, under=f"{subject:03d}")
    return tmp


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="interplay data build --staged", description=__doc__)
    ap.add_argument("--mirror", type=Path, default=None, help="mirror root (default /work/.mirror)")
    ap.add_argument("--source", type=Path, default=DEFAULT_SOURCE, help="raw data folder (../shared/data)")
    ap.add_argument("--out", type=Path, default=STAGED_DIR, help="output folder (models/data/staged)")
    ap.add_argument("--limit", type=int, default=None, help="at most N clips per source (tests)")
    ap.add_argument("--only", nargs="*", choices=sorted(SNAPSHOTS), help="build only these staged sources")
    args = ap.parse_args(argv)
    root = args.mirror or mirror_root()
    SKIPPED.clear()
    ABSENT.clear()
    clips: list[Clip] = []
    builders = {"bandai-namco-2": lambda raw: build_bandai_more(raw, args.source, args.limit),
                "reactidle": lambda raw: build_reactidle(raw)[:args.limit],
                "cmu-pairs": lambda raw: build_cmu_pairs(raw, args.source / "cmu-index" / "cmu_index.csv",
                                                         SKIPPED)[:args.limit]}
    # CMU's pairs only when their files are somewhere (../shared/data/cmu-pairs or a mirror).
    names = args.only or [n for n in SNAPSHOTS if n != "cmu-pairs" or (args.source / "cmu-pairs").is_dir()
                          or CMU_MOCAP.git_dir(root).is_dir()]
    try:
        for name in names:
            with tempfile.TemporaryDirectory() as tmp:
                t0 = time.time()
                raw = _raw(name, Path(tmp), root, args.source)
                absent = raw / ".absent"
                ABSENT[name] = [f for f in absent.read_text().split() if f.endswith(".bvh")] if absent.exists() else []
                got = builders[name](raw)
                print(f"{name:14s} {len(got):4d} clips  {time.time() - t0:6.1f} s", flush=True)
                clips.extend(got)
    except SnapshotMissing as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    assign_staged_splits(clips)
    add_captions(clips)
    save_clips(clips, args.out)
    write_staged_card(clips, args.out)
    print(f"wrote {len(clips)} staged clips to {args.out}")
    return 0


__all__ = ["BANDAI", "REACTIDLE", "SNAPSHOTS", "STAGED_DIR", "build_bandai_more", "build_reactidle", "main"]


if __name__ == "__main__":
    raise SystemExit(main())
