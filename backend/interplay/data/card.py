"""The data card (models/data/README.md), written from the clips so its numbers match the data."""

from __future__ import annotations

from collections import Counter, defaultdict
from collections.abc import Sequence
from pathlib import Path

from interplay.data.hunt import SOURCES_CONSIDERED
from interplay.data.pairs import pair_contact_lines
from interplay.motion.clip import Clip
from interplay.motion.labels import label_family
from interplay.motion.skeleton import FPS

SOURCES = {
    "cmu-bvh": ("CMU Graphics Lab mocap, Daz-friendly BVH (subjects 02–16: walks, runs, jumps)", "CMU terms"),
    "cmu-salsa": ("CMU subjects 60 (lead) + 61 (follow), synchronised salsa pairs", "CMU terms"),
    "hdm05": ("HDM05 pre-cut clips, 11 classes, 5 actors, Acclaim ASF/AMC", "CC BY-SA 3.0"),
    "cmu-8action": ("CMU 8-action motion-prediction set (exp-map text)", "CMU terms"),
    "bandai-namco": ("Bandai Namco Research motion dataset 1 + part of 2: 3 actors on one aligned figure, "
                     "17 + 10 contents in 15 + 7 styles", "CC BY-NC 4.0 (non-commercial)"),
    "cmu-iclone": ("CMU trials of subjects 01, 02, 05, 06 retargeted onto Reallusion's CC_Base rig "
                   "(dance, basketball, swordplay, punches)", "CMU terms"),
    "cmu-asfamc": ("CMU trials in their original Acclaim ASF/AMC (karate kata, soccer kick, hops)",
                   "CMU terms"),
    "deepmimic": ("DeepMimic's humanoid clips (flips, cartwheel, crawl, get-ups, roll, kicks, dances)",
                  "MIT"),
    "composed": ("synthetic two-person clips composed from the real single-person clips above "
                 "(commercially usable sources only), contact solved with IK", "its bases' (per clip)"),
}

# How each source was split (by capture, never by window), as the build does it.
SPLIT_NOTES = [
    "- CMU trials (cmu-bvh, cmu-iclone, cmu-asfamc), salsa pairs and DeepMimic clips: within each source's",
    "  action families, trials ordered by a stable hash; 15% test (at least one per family of ≥ 3), 10% val,",
    "  the rest train (a family of one or two trials is all train).",
    "- HDM05: actor `mm` is held out entirely as test; 10% of the other actors' clips per class are val.",
    "- Bandai Namco: by take. The files carry no actor label (the dataset aligned its three actors onto one",
    "  figure), so whole takes are held out: within each content of each dataset (walk, bow, wave-left-hand …),",
    "  takes ordered by a stable hash of the file name, 15% test, 10% val. A test take is a capture no train clip",
    "  comes from; its style may be one the content has no train take of (e.g. dataset-1's single takes).",
    "- cmu-8action: its own `train/` and `test/` folders. Its CMU source trials are not recorded, so",
    "  some of its walks/runs/jumps may be the same captures as cmu-bvh trials; compare on cmu-bvh/",
    "  hdm05/salsa test trials when that matters.",
    "- One capture once: a CMU trial in several raw folders is kept from cmu-bvh first, then cmu-asfamc,",
    "  then cmu-iclone (the others are listed under Left out).",
]

LICENCES_TEXT = """\
## Licences and acknowledgements
One processed file per source, so each licence's derived data stays separable; every clip's `licence` in
`index.json` names it (`interplay.data.licences` is the table the model cards read).
- **CMU** (`cmu-bvh.npz`, `cmu-salsa.npz`, `cmu-8action.npz`, `cmu-iclone.npz`, `cmu-asfamc.npz`): free for
  research and for commercially sold products; the data itself may not be resold, even converted. "The data used
  in this project was obtained from mocap.cs.cmu.edu. The database was created with funding from NSF
  EIA-0196217." `cmu-iclone` is a third party's retarget onto Reallusion's CC_Base rig
  (DragonForgedTheArtist/IClone-CMU-Mocap, no licence file of its own).
- **HDM05** (`hdm05.npz`, and every clip whose `licence` says so in `index.json`): Creative Commons
  Attribution-ShareAlike 3.0 Unported; derived data stays CC BY-SA 3.0, which is why it has its own file.
  "The data used in this project was obtained from HDM05." M. Müller, T. Röder, M. Clausen, B. Eberhardt,
  B. Krüger, A. Weber: Documentation Mocap Database HDM05, Technical report CG-2007-2, Universität Bonn, 2007.
  Model cards say which weights were trained with it.
- **Bandai Namco** (`bandai-namco.npz`): Creative Commons Attribution-NonCommercial 4.0 International:
  **non-commercial use only**, for the data and for weights trained with it. "Bandai Namco Research Inc.,
  Bandai-Namco-Research-Motiondataset (CC BY-NC 4.0)", © 2022 Bandai Namco Research Inc.; M. Kobayashi,
  C.-C. Liao, K. Inoue, S. Yojima, M. Takahashi: "Motion Capture Dataset for Practical Use of AI-based Motion
  Editing and Stylization", arXiv:2306.08861, 2023. Changes: retargeted to 22 joints, resampled to 20 fps, the
  upper body re-posed on human proportions, labels turned into prompts. Composed clips never use it;
  `make train EXCLUDE_NONCOMMERCIAL=1` trains without it.
- **DeepMimic** (`deepmimic.npz`): MIT License, "Copyright (c) 2018 Xue Bin Peng" (github.com/xbpeng/DeepMimic);
  the permission notice travels with the data (raw `deepmimic/LICENSE`). Where DeepMimic's clips were
  captured is not stated there.
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


def _family_lines(clips: list[Clip]) -> list[str]:
    """Hours of real capture per action family (interplay.motion.labels.label_family), one
    column per source, and the total of real single-person capture."""
    real = [c for c in clips if not c.synthetic]
    sources = sorted({c.source for c in real})
    frames: dict[tuple[str, str], int] = defaultdict(int)
    for c in real:
        frames[label_family(c.prompt), c.source] += sum(p.shape[0] for p in c.people)
    families = sorted({f for f, _ in frames}, key=lambda f: -sum(frames[f, s] for s in sources))
    single = sum(p.shape[0] for c in real if len(c.people) == 1 for p in c.people)
    lines = ["## Hours per action family (real capture, person-hours)", "",
             f"Real single-person capture: **{_hours(single):.2f} h** ({single} frames at {FPS} fps); "
             "families by `interplay.motion.labels.label_family` of the prompt.", "",
             "| family | " + " | ".join(sources) + " | all |", "|---|" + "---|" * (len(sources) + 1)]
    for f in families:
        row = [frames[f, s] for s in sources]
        lines.append(f"| {f} | " + " | ".join(f"{_hours(n):.3f}" if n else "" for n in row)
                     + f" | {_hours(sum(row)):.3f} |")
    return lines + [""]


def _rate_lines(clips: list[Clip],
                sources: Sequence[str] = ("bandai-namco", "cmu-iclone", "cmu-asfamc", "deepmimic")) -> list[str]:
    """Frame rates of the newer sources: what was stated, what the motion says, where they
    disagree (the clips recorded `checks.decide_rate`'s evidence)."""
    lines = []
    for source in sources:
        group = [c for c in clips if c.source == source]
        if not group:
            continue
        used = sorted({f"{c.meta['source_fps']:g}" for c in group})
        off = [c for c in group if abs(c.meta["fps_estimate"] - c.meta["source_fps"]) > 1e-6]
        grav = []
        for c in group:
            g = c.meta["fps_evidence"].get(f"{c.meta['source_fps']:g}", {}).get("com_gravity")
            if g is not None and 6.0 <= g <= 16.0:
                grav.append(g)
        text = f"{source}: {', '.join(used)} fps used; {len(group) - len(off)} of {len(group)} clips agree with " \
               "`estimate_true_fps`"
        if grav:
            text += (f"; in {len(grav)} clips with a flight the centre of mass falls at "
                     f"{min(grav):.1f}–{max(grav):.1f} m/s² at the rate used")
        if off:
            text += "; the estimate differs for " + ", ".join(
                f"{c.id.split(':', 1)[1]} ({c.meta['fps_estimate']:g})" for c in off) + \
                " (kept at the stated rate: see the source's retarget module)"
        lines.append(text + ".")
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
    notes += _rate_lines(clips)
    lines += ["## Frame rates", "", *[f"- {n}" for n in notes], ""]
    if skipped:
        lines += ["## Left out", "", *[f"- `{f}`: {'; '.join(r)}" for f, r in skipped], ""]

    lines += _family_lines(clips)
    lines += ["## Split (by trial, never by window)", "", *SPLIT_NOTES, "",
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
              "", *pair_contact_lines(clips), LICENCES_TEXT, SOURCES_CONSIDERED]
    (out_dir / "README.md").write_text("\n".join(lines))
