"""`interplay data build`: every raw capture source in ../shared/data → the processed data set
in models/data (one npz per source, index.json, README.md data card).

Each source is retargeted onto the 22-joint skeleton at 20 fps and canonicalised by its own
module under `interplay.motion.retarget`; this module only walks the folders, labels, splits
by trial (never by window) and captions.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from interplay.data.card import write_card
from interplay.data.licences import BANDAI_NAMCO, CMU, DEEPMIMIC, commercial_only
from interplay.data.splits import SPLIT_SHARES, _stable_rank, add_captions, stratified_split
from interplay.motion.clip import DATA_DIR, Clip, save_clips
from interplay.motion.labels import cmu_prompt, label_family

REPO = Path(__file__).resolve().parents[3]
DEFAULT_SOURCE = REPO.parent / "shared" / "data"
# HDM05's actor "mm" is held out entirely as the test set: unseen performer, every class.
HDM05_TEST_ACTOR = "mm"
# Composed two-person clips per kind and split (interplay.motion.pair.compose), 4 s each; a split's
# pairs are composed only from that split's real single-person clips.
COMPOSED_PER_KIND = {"train": 24, "val": 4, "test": 4}
COMPOSED_SECONDS = 4.0
COMPOSE_NOTES: list[str] = []
# Raw files left out of the set, with the reasons (broken root tracks …); listed in the card.
SKIPPED: list[tuple[str, list[str]]] = []


def build_cmu_bvh(src: Path) -> list[Clip]:
    from interplay.motion.retarget.cmu_daz import load_cmu_bvh, read_cmu_index

    index = read_cmu_index(src / "cmu-index" / "cmu_index.csv")
    clips = []
    for path in sorted((src / "cmu-bvh").glob("*/*.bvh")):
        subject, trial = (int(x) for x in path.stem.split("_")[:2])
        description, index_fps = index.get((subject, trial), ("unknown", 120))
        joints, offsets, meta = load_cmu_bvh(path)
        meta.update({"file": f"cmu-bvh/{path.parent.name}/{path.name}", "index_fps": index_fps,
                     "source_fps": meta["native_fps"]})
        if meta.get("defects"):
            print(f"  skipped {path.name}: {'; '.join(meta['defects'])}", flush=True)
            SKIPPED.append((f"cmu-bvh/{path.parent.name}/{path.name}", meta["defects"]))
            continue
        clips.append(Clip(id=f"cmu:{path.stem}", source="cmu-bvh", people=[joints], offsets=[offsets],
                          label=description, prompt=cmu_prompt(description), licence="CMU", meta=meta))
    return clips


def build_salsa(src: Path) -> list[Clip]:
    from interplay.motion.retarget.cmu_daz import load_salsa_pair

    clips = []
    for lead in sorted((src / "cmu-salsa" / "60").glob("60_*.bvh")):
        pair = lead.stem.split("_")[1]
        follow = src / "cmu-salsa" / "61" / lead.name.replace("60_", "61_", 1)
        if not follow.exists():
            continue
        people, offsets, meta = load_salsa_pair(lead, follow)
        meta.update({"files": [f"cmu-salsa/60/{lead.name}", f"cmu-salsa/61/{follow.name}"],
                     "roles": ["lead (subject 60)", "follow (subject 61)"],
                     "source_fps": meta["native_fps"],
                     "fps_note": "cmu-salsa: headers say 120 fps, CMU's index 60; the motion decides 60 "
                                 "(centre-of-mass acceleration and turn timing; evidence in "
                                 "interplay/motion/retarget/frame_rate.py)."})
        if meta.get("defects"):
            SKIPPED.append((f"cmu-salsa/{lead.name}", meta["defects"]))
            continue
        clips.append(Clip(id=f"salsa:{pair}", source="cmu-salsa", people=people, offsets=offsets,
                          label="salsa dance", prompt=cmu_prompt("salsa dance"), licence="CMU",
                          meta=meta))
    return clips


def build_hdm05(src: Path) -> list[Clip]:
    from interplay.motion.retarget.hdm05 import hdm05_prompt, load_hdm05

    clips = []
    for path in sorted((src / "hdm05").glob("*/*.amc")):
        actor = path.stem.split("_")[1]
        joints, offsets, meta = load_hdm05(path, src / "hdm05" / "asf" / f"HDM_{actor}.asf")
        cls = path.parent.name
        meta.update({"file": f"hdm05/{cls}/{path.name}", "actor": actor})
        clips.append(Clip(id=f"hdm05:{path.stem}", source="hdm05", people=[joints], offsets=[offsets],
                          label=cls, prompt=hdm05_prompt(cls), licence="CC BY-SA 3.0 (HDM05)",
                          meta=meta))
    return clips


def build_cmu_8action(src: Path) -> list[Clip]:
    from interplay.motion.retarget.cmu_8action import cmu_8action_prompt, load_cmu_8action

    clips = []
    for path in sorted((src / "cmu-8action").glob("*/*/*.txt")):
        folder, action = path.parts[-3], path.parts[-2]
        joints, offsets, meta = load_cmu_8action(path)
        meta.update({"file": f"cmu-8action/{folder}/{action}/{path.name}", "folder": folder})
        clips.append(Clip(id=f"8action:{folder}/{path.stem}", source="cmu-8action", people=[joints],
                          offsets=[offsets], label=action, prompt=cmu_8action_prompt(action),
                          licence="CMU", meta=meta))
    return clips


def _cmu_trials(src: Path, folder: str) -> dict[tuple[int, int], str]:
    """{(subject, trial): raw path} of the CMU trials a source folder holds."""
    out: dict[tuple[int, int], str] = {}
    if folder == "cmu-bvh":
        for path in sorted((src / "cmu-bvh").glob("*/*.bvh")):
            subject, trial = (int(x) for x in path.stem.split("_")[:2])
            out[subject, trial] = f"cmu-bvh/{path.parent.name}/{path.name}"
    elif folder == "cmu-asfamc":
        from interplay.motion.retarget.cmu_acclaim import trial_of
        for path in sorted((src / "cmu-asfamc").glob("*/*.amc")):
            out[trial_of(path)] = f"cmu-asfamc/{path.parent.name}/{path.name}"
    return out


def _skip(rel: str, reasons: list[str]) -> None:
    print(f"  skipped {rel}: {'; '.join(reasons)}", flush=True)
    SKIPPED.append((rel, reasons))


def build_bandai(src: Path) -> list[Clip]:
    from interplay.motion.retarget.bandai_namco import bandai_prompt, load_bandai, read_labels

    clips = []
    for path in sorted((src / "bandai-namco").glob("dataset-*/data/*.bvh")):
        rel = f"bandai-namco/{path.parent.parent.name}/data/{path.name}"
        labels = read_labels(path)
        joints, offsets, meta = load_bandai(path)
        meta.update({"file": rel, **labels})
        if meta["defects"]:
            _skip(rel, meta["defects"])
            continue
        clips.append(Clip(id=f"bandai:{path.stem}", source="bandai-namco", people=[joints],
                          offsets=[offsets], label=f"{labels['content']} ({labels['style']})",
                          prompt=bandai_prompt(labels["content"], labels["style"]),
                          licence=BANDAI_NAMCO.name, meta=meta))
    return clips


def _cmu_retargets(src: Path, source: str, paths, trial_of, load, index: dict,
                   have: dict[tuple[int, int], str]) -> list[Clip]:
    """The clips of a source of CMU trials (`load(path)` → joints, offsets, meta), labelled by
    CMU's `index`; a trial another source already holds (`have`) is left out, so one capture
    is kept once and cannot sit in two splits."""
    clips = []
    for path in paths:
        rel = str(path.relative_to(src))
        subject, trial = trial_of(path)
        if (subject, trial) in have:
            _skip(rel, [f"the same CMU trial as {have[subject, trial]}, which the set keeps"])
            continue
        description, index_fps = index.get((subject, trial), ("unknown", 120))
        joints, offsets, meta = load(path)
        meta.update({"file": rel, "subject": subject, "trial": trial, "index_fps": index_fps})
        if meta["defects"]:
            _skip(rel, meta["defects"])
            continue
        clips.append(Clip(id=f"{source}:{subject:02d}_{trial:02d}", source=source,
                          people=[joints], offsets=[offsets], label=description,
                          prompt=cmu_prompt(description), licence=CMU.name, meta=meta))
    return clips


def build_cmu_asfamc(src: Path) -> list[Clip]:
    """CMU's original Acclaim trials; a trial cmu-bvh already holds is left out."""
    from interplay.motion.retarget.cmu_acclaim import load_cmu_acclaim, trial_of
    from interplay.motion.retarget.cmu_daz import read_cmu_index

    return _cmu_retargets(src, "cmu-asfamc", sorted((src / "cmu-asfamc").glob("*/*.amc")),
                          trial_of, load_cmu_acclaim,
                          read_cmu_index(src / "cmu-index" / "cmu_index.csv"),
                          _cmu_trials(src, "cmu-bvh"))


def build_cmu_iclone(src: Path) -> list[Clip]:
    """The CC_Base retargets of CMU trials, labelled by `CMU data.csv`; a trial that cmu-bvh
    or cmu-asfamc already holds is left out."""
    from interplay.motion.retarget.cmu_iclone import load_cmu_iclone, read_cmu_index, trial_of

    return _cmu_retargets(src, "cmu-iclone",
                          sorted((src / "cmu-iclone" / "subjects").glob("*/*.bvh")), trial_of,
                          load_cmu_iclone, read_cmu_index(src / "cmu-iclone" / "CMU data.csv"),
                          {**_cmu_trials(src, "cmu-asfamc"), **_cmu_trials(src, "cmu-bvh")})


def build_deepmimic(src: Path) -> list[Clip]:
    from interplay.motion.retarget.deepmimic import clip_name, deepmimic_prompt, load_deepmimic

    clips = []
    for path in sorted((src / "deepmimic" / "motions").glob("humanoid3d_*.txt")):
        rel = f"deepmimic/motions/{path.name}"
        joints, offsets, meta = load_deepmimic(path)
        meta["file"] = rel
        if meta["defects"]:
            _skip(rel, meta["defects"])
            continue
        name = clip_name(path)
        clips.append(Clip(id=f"deepmimic:{name}", source="deepmimic", people=[joints], offsets=[offsets],
                          label=name, prompt=deepmimic_prompt(name), licence=DEEPMIMIC.name, meta=meta))
    return clips


def assign_splits(clips: list[Clip]) -> None:
    """By trial, never by window. HDM05: one held-out actor is test; cmu-8action keeps its own
    train/test folders; Bandai Namco by take within each (dataset, content); CMU trials, salsa
    pairs and the other sources' clips are split per action family by stable hash."""
    groups: dict[str, list[str]] = {}
    hdm_rest: dict[str, list[str]] = {}
    for c in clips:
        if c.source == "hdm05":
            if c.meta.get("actor") == HDM05_TEST_ACTOR:
                c.split = "test"
            else:
                hdm_rest.setdefault(c.label, []).append(c.id)
        elif c.source == "cmu-8action":
            c.split = "test" if c.meta.get("folder") == "test" else "train"
        elif c.source == "bandai-namco":
            # No actor labels (one aligned figure for all three actors): whole takes, ranked
            # within each content of each dataset, so every content has unseen takes in test.
            groups.setdefault(f"bandai-namco:{c.meta['dataset']}:{c.meta['content']}", []).append(c.id)
        else:
            groups.setdefault(f"{c.source}:{label_family(c.prompt)}", []).append(c.id)
    split = stratified_split(groups)
    # Held-out actor already gives HDM05 its test set; the others only give a validation share.
    for ids in hdm_rest.values():
        ranked = sorted(ids, key=_stable_rank)
        for i, trial in enumerate(ranked):
            split[trial] = "val" if i < max(1, round(len(ranked) * SPLIT_SHARES["val"])) else "train"
    for c in clips:
        if c.id in split:
            c.split = split[c.id]


def build_composed(clips: list[Clip], per_kind: dict[str, int] = COMPOSED_PER_KIND) -> list[Clip]:
    """Synthetic two-person clips composed from the real clips (after their splits are set):
    train pairs from train bases only, val/test pairs from val/test bases. Kinds a split has no
    bases for are skipped and noted in the card."""
    from interplay.motion.pair.compose import KINDS, compose_set, pool_of

    COMPOSE_NOTES.clear()
    # Bases never come from non-commercial sources, so composed.npz carries no NC term.
    clips = commercial_only(clips)
    out: list[Clip] = []
    for split, n in per_kind.items():
        pool = pool_of(clips, split)
        COMPOSE_NOTES.append(f"{split} bases: {len(pool.stand)} quiet standing stretches from "
                             f"{len({b.clip.id for b in pool.stand})} clips, {len(pool.walk)} level walks")
        got = compose_set(n, 0, clips=clips, split=split, seconds=COMPOSED_SECONDS)
        missing = [k for k in KINDS if k not in {c.meta["kind"] for c in got}]
        if missing:
            COMPOSE_NOTES.append(f"{split}: no composed {', '.join(missing)} (the {split} split has no "
                                 f"{'quiet standing or level walk' if len(missing) == len(KINDS) else 'suitable'}"
                                 " real bases for them)")
        out.extend(got)
    return out


BUILDERS = {"cmu-bvh": build_cmu_bvh, "cmu-salsa": build_salsa, "hdm05": build_hdm05,
            "cmu-8action": build_cmu_8action, "bandai-namco": build_bandai,
            "cmu-asfamc": build_cmu_asfamc, "cmu-iclone": build_cmu_iclone,
            "deepmimic": build_deepmimic}


def main(argv: list[str] | None = None) -> int:
    if argv and "--staged" in argv:  # sources read from repository snapshots: data/staged.py
        from interplay.data.staged import main as staged_main
        return staged_main([a for a in argv if a != "--staged"])
    ap = argparse.ArgumentParser(prog="interplay data build", description=__doc__)
    ap.add_argument("--source", type=Path, default=DEFAULT_SOURCE, help="raw data folder (../shared/data)")
    ap.add_argument("--out", type=Path, default=DATA_DIR, help="output folder (models/data)")
    ap.add_argument("--only", nargs="*", choices=sorted(BUILDERS) + ["composed"],
                    help="build only these sources")
    ap.add_argument("--composed", type=int, default=None, metavar="N",
                    help="composed pairs per kind in train (default "
                         f"{COMPOSED_PER_KIND['train']}; val/test keep at most their defaults)")
    args = ap.parse_args(argv)
    if not args.source.is_dir():
        print(f"error: raw data folder {args.source} not found (pass --source)", file=sys.stderr)
        return 2
    clips: list[Clip] = []
    for name, build in BUILDERS.items():
        if args.only and name not in args.only:
            continue
        t0 = time.time()
        got = build(args.source)
        print(f"{name:12s} {len(got):4d} clips  {time.time() - t0:6.1f} s", flush=True)
        clips.extend(got)
    assign_splits(clips)
    if not args.only or "composed" in args.only:
        t0 = time.time()
        per_kind = COMPOSED_PER_KIND if args.composed is None else {
            split: min(n, args.composed) if split != "train" else args.composed
            for split, n in COMPOSED_PER_KIND.items()}
        got = build_composed(clips, per_kind)
        print(f"{'composed':12s} {len(got):4d} clips  {time.time() - t0:6.1f} s", flush=True)
        clips.extend(got)
    t0 = time.time()
    add_captions(clips)
    print(f"captions     {sum(len(c.captions) for c in clips):4d}       {time.time() - t0:6.1f} s")
    save_clips(clips, args.out)
    write_card(clips, args.out, skipped=SKIPPED, composed_notes=COMPOSE_NOTES)
    print(f"wrote {len(clips)} clips to {args.out}")
    # The captures' own head and hand orientations beside the sources just written
    # (`data/leaves.py`; their frames must match the new clips').
    from interplay.data.leaves import CARRIED, build_leaves
    for source in (s for s in CARRIED if s in {c.source for c in clips}):
        summary = build_leaves(source, args.source, args.out)
        print(f"leaves       {source}: {summary['people']} people, {summary['frames']} frames")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
