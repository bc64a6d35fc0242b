"""The data card (models/data/README.md), written from the clips so its numbers match the data."""

from __future__ import annotations

from collections import Counter, defaultdict
from collections.abc import Sequence
from pathlib import Path

from interplay.motion.clip import Clip
from interplay.motion.skeleton import FPS

SOURCES = {
    "cmu-bvh": ("CMU Graphics Lab mocap, Daz-friendly BVH (subjects 02–16: walks, runs, jumps)", "CMU terms"),
    "cmu-salsa": ("CMU subjects 60 (lead) + 61 (follow), synchronised salsa pairs", "CMU terms"),
    "hdm05": ("HDM05 pre-cut clips, 11 classes, 5 actors, Acclaim ASF/AMC", "CC BY-SA 3.0"),
    "cmu-8action": ("CMU 8-action motion-prediction set (exp-map text)", "CMU terms"),
    "composed": ("synthetic two-person clips composed from the real single-person clips above, "
                 "contact solved with IK", "its bases' (per clip)"),
}

LICENCES = """\
## Licences and acknowledgements
- **CMU** (`cmu-bvh.npz`, `cmu-salsa.npz`, `cmu-8action.npz`): free for research and for commercially sold
  products; the data itself may not be resold, even converted. "The data used in this project was obtained from
  mocap.cs.cmu.edu. The database was created with funding from NSF EIA-0196217."
- **HDM05** (`hdm05.npz`, and every clip whose `licence` says so in `index.json`): Creative Commons
  Attribution-ShareAlike 3.0 Unported; derived data stays CC BY-SA 3.0, which is why it has its own file.
  "The data used in this project was obtained from HDM05." M. Müller, T. Röder, M. Clausen, B. Eberhardt,
  B. Krüger, A. Weber: Documentation Mocap Database HDM05, Technical report CG-2007-2, Universität Bonn, 2007.
  Model cards say which weights were trained with it.
"""


def _hours(frames: int) -> float:
    return frames / FPS / 3600


def _composed_lines(clips: list[Clip], notes: Sequence[str] = ()) -> list[str]:
    """The composed pairs: how they are made, how many of each kind per split."""
    composed = [c for c in clips if c.source == "composed"]
    lines = ["", "### Composed two-person clips (`composed.npz`)", "",
             "Built by `interplay.motion.pair.compose` after the real sources: two real single-person motions of",
             "the same split (train pairs only from train clips, val/test pairs from val/test clips) —",
             "quiet standing stretches (played back and forth with a cosine time warp) or level walks",
             "(looped on their gait cycle, the second time-warped to the first's speed) — are placed",
             "facing each other or side by side with their trunks, heads and legs apart, and the contact",
             "arms follow two-bone IK (`interplay.motion.ik`) to the partner's hand, back or chest with",
             "eased weights over a window; every other joint stays as captured. `meta` holds the kind,",
             "the contact window and hands, the placement and the bases. Each clip's `licence` is its",
             "bases' (CC BY-SA 3.0 when an HDM05 clip is one of them). They are marked `synthetic: true`."]
    if composed:
        kinds = sorted({c.meta["kind"] for c in composed})
        count = Counter((c.meta["kind"], c.split) for c in composed)
        lines += ["", "| kind | train | val | test |", "|---|---|---|---|"]
        lines += [f"| {k} | {count[k, 'train']} | {count[k, 'val']} | {count[k, 'test']} |" for k in kinds]
    else:
        lines += ["", "None in this build: no split had quiet standing or level walking real clips."]
    lines += [f"- {n}" for n in notes]
    return lines


def write_card(clips: list[Clip], out_dir: Path, skipped: Sequence[tuple[str, list[str]]] = (),
               composed_notes: Sequence[str] = ()) -> None:
    by_source: dict[str, list[Clip]] = defaultdict(list)
    for c in clips:
        by_source[c.source].append(c)
    lines = [
        "# Processed capture data (models/data)",
        "",
        "Written by `interplay data build` (`backend/interplay/data/build.py`) from the raw captures in",
        "`../shared/data`; regenerate with `make data`. Do not edit by hand: this card is generated too.",
        "Every clip is retargeted onto the 22-joint SMPL layout (`interplay.motion.skeleton`), resampled to",
        f"{FPS} fps, re-posed on fixed bone lengths (IK → FK, per-person offsets stored) and canonicalised",
        "(floor at y = 0, first person's pelvis at the XZ origin facing +Z on frame 0; a pair shares one",
        "transform). Joints are stored as float16 metres: one `<source>.npz` per source, `index.json` lists",
        "clips with labels, prompts, split, automatic part captions and provenance.",
        "",
        "## Sources",
        "| source | what | clips | people-frames | hours | native fps → 20 | licence |",
        "|---|---|---|---|---|---|---|",
    ]
    for source, group in sorted(by_source.items()):
        what, licence = SOURCES.get(source, (source, group[0].licence))
        frames = sum(p.shape[0] for c in group for p in c.people)
        fps = sorted({str(c.meta.get("source_fps", "?")) for c in group})
        lines.append(f"| {source} | {what} | {len(group)} | {frames} | {_hours(frames):.2f} | "
                     f"{', '.join(fps)} | {licence} |")
    total = sum(p.shape[0] for c in clips for p in c.people)
    lines += [f"| **all** | | {len(clips)} | {total} | {_hours(total):.2f} | | |", ""]

    notes = sorted({c.meta["fps_note"] for c in clips if c.meta.get("fps_note")})
    notes += ["cmu-bvh: 120 fps (gravity in jumps: the pelvis falls at 8.6–10.0 m/s² at 120 fps; "
              "16_01/16_02 headers say 30 but fall at 9.9–10.0 m/s² at 120, so CMU's index is right).",
              "hdm05: 120 fps (file names and headers agree).",
              "cmu-8action: undocumented; 120 fps from walking cadence (walks 1.6–1.9 steps/s at "
              "0.9–1.4 m/s; at 60 fps they would be 0.8–0.9 steps/s)."]
    lines += ["## Frame rates", "", *[f"- {n}" for n in notes], ""]
    if skipped:
        lines += ["## Left out", "", *[f"- `{f}`: {'; '.join(r)}" for f, r in skipped], ""]

    lines += ["## Split (by trial, never by window)", "",
              "- CMU trials and salsa pairs: within each action family, trials ordered by a stable hash;",
              "  15% test (at least one per family of ≥ 3), 10% val, the rest train.",
              "- HDM05: actor `mm` is held out entirely as test; 10% of the other actors' clips per class are val.",
              "- cmu-8action: its own `train/` and `test/` folders. Its CMU source trials are not recorded, so",
              "  some of its walks/runs/jumps may be the same captures as cmu-bvh trials; compare on cmu-bvh/",
              "  hdm05/salsa test trials when that matters.", "",
              "| source | train | val | test |", "|---|---|---|---|"]
    for source, group in sorted(by_source.items()):
        count = Counter(c.split for c in group)
        lines.append(f"| {source} | {count['train']} | {count['val']} | {count['test']} |")
    lines.append("")

    lines += ["## Labels → prompts", "", "| source | raw label | prompt | clips |", "|---|---|---|---|"]
    pairs = Counter((c.source, c.label, c.prompt) for c in clips)
    for (source, label, prompt), n in sorted(pairs.items()):
        lines.append(f"| {source} | {label} | {prompt} | {n} |")
    lines.append("")

    n_caps = sum(len(c.captions) for c in clips)
    texts = Counter(cap.text.split(": ", 1)[-1] for c in clips for cap in c.captions)
    lines += ["## Automatic part captions", "",
              f"{n_caps} captions from `interplay.motion.posecodes.caption_clip` (per body part, per segment).",
              "Most frequent:", ""]
    lines += [f"- {t} ({n})" for t, n in texts.most_common(25)]
    lines += ["", "## Synthetic data", "",
              f"{sum(c.synthetic for c in clips)} synthetic clips (composed pairs are marked `synthetic: true`"
              " and kept out of the evaluation's real reference set).", *_composed_lines(clips, composed_notes),
              "", LICENCES]
    (out_dir / "README.md").write_text("\n".join(lines))
