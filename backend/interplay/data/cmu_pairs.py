"""CMU's real two-person trials → synchronised pairs for the staged set (`cmu-pairs`), with the
contact windows measured on them (`interplay.data.pairs`) for the composition library and the
pair evaluator's data.

CMU captured two people together in subjects 18/19, 20/21, 22/23 (120 fps) and 33/34 (60 fps,
CMU's index): trial t of the first subject ("subject A") and trial t of the second ("subject
B") are one performance seen from two skeletons in one world frame, like salsa's 60/61. They
are read with `cmu_daz.load_salsa_pair` (one canonical transform for both) at CMU's indexed rate.

Where the raw files come from: the BVH conversion of the whole CMU database in
una-dinosauria/cmu-mocap (files `0SS/SS_TT.bvh`, MotionBuilder bone names, read by `cmu_daz`).
Its snapshot (789 MB) is over what `fetch` brings, as is every other whole copy found (ju3tin/bvh,
Shriinivas/cmubvh; see the data card's "Sources considered"), so the build reads them from
`../shared/data/cmu-pairs/` (`0SS/SS_TT.bvh`, `data/0SS/SS_TT.bvh`, `SS/SS_TT.bvh` or flat; the
subjects above, about 100 files) or from the snapshot where a mirror holds it, and stops with a message
saying so when neither has them.
"""

from __future__ import annotations

from pathlib import Path

from interplay.data.licences import CMU
from interplay.data.pairs import contact_windows
from interplay.motion.clip import Clip
from interplay.motion.retarget.cmu_index import read_cmu_index

# (subject A, subject B): one performance per shared trial number.
PAIRS = ((18, 19), (20, 21), (22, 23), (33, 34))

# Interaction kind (first match in the description) → what the two people do, for the prompt.
KINDS: tuple[tuple[str, str, str], ...] = (
    ("shake hands", "handshake", "walk up to each other and shake hands"),
    ("high-five", "high_five", "walk past each other and high-five"),
    ("low-five", "low_five", "walk past each other and low-five"),
    ("pulls up", "help_up", "one helps the other up from sitting by pulling their hands"),
    ("pulls b by the elbow", "pull", "one pulls the other by the elbow while they resist"),
    ("pulls b", "pull", "one pulls the other along while they resist"),
    ("takes b by the arm", "lead_by_arm", "one leads the other through a crowd by the arm"),
    ("comfort", "comfort", "one comforts the other with hands on their shoulders"),
    ("shoulder rub", "shoulder_rub", "one stands and rubs the shoulders of the other, who sits"),
    ("shelters", "shelter", "one shelters the other from harm"),
    ("stumbles into", "bump", "one stumbles into the other"),
    ("passes soda", "hand_over", "one hands a soda to the other and both drink"),
    ("arm wrestle", "arm_wrestle", "rush up to each other and arm wrestle"),
    ("catches keys", "throw_catch", "walk, and one throws keys that the other catches"),
    ("catches wallet", "throw_catch", "walk, and one throws a wallet that the other catches"),
    ("football", "throw_catch", "throw and catch a football"),
    ("link arms", "walk_arm_in_arm", "link arms and walk together"),
    ("hold hands", "walk_hand_in_hand", "hold hands, swing their arms and walk together"),
    ("synchronized walk", "walk_side_by_side", "walk side by side in step"),
    ("march", "march_together", "march together"),
    ("jumping jacks", "exercise_together", "do jumping jacks together"),
    ("squats", "exercise_together", "take turns doing squats"),
    ("ring around", "play", "play ring-around-the-rosy, holding hands in a circle"),
    ("whip", "play", "hold hands and whip each other around"),
    ("blind man", "play", "play blindfold tag"),
    ("scramble for last seat", "play", "run and scramble for the last seat"),
    ("sits, b joins", "sit_together", "meet as friends; one sits and the other joins"),
    ("stares down", "stare_down", "one stares the other down, leaning on a high stool"),
    ("threatens", "threaten", "one picks up a high stool and threatens the other"),
    ("pounds high stool", "argue", "argue; one pounds a high stool and points at the other"),
    ("quarrel", "argue", "quarrel with angry hand gestures"),
    ("conversation", "conversation", "talk, explaining with hand gestures"),
    ("chicken dance", "dance", "do the chicken dance together"),
)


def without_note(description: str) -> str:
    """CMU's description without its closing "(2 subjects - subject A)" note (any case, the "2"
    optional, any spaces around the dash)."""
    body = description.rstrip()
    cut = body.rfind("(")
    if cut < 0 or not body.endswith(")"):
        return description
    note = body[cut + 1:-1].lower()
    if note.startswith("2"):
        note = note[1:].lstrip()
    subjects, dash, rest = note.partition("-")
    rest = rest.lstrip()
    tail = rest[len("subject"):]
    if (dash and subjects.rstrip() in ("subject", "subjects") and rest.startswith("subject")
            and tail[-1:] in ("a", "b") and tail[:-1][:1].isspace() and tail[:-1].isspace()):
        return body[:cut].rstrip()
    return description


def pair_kind(description: str) -> tuple[str, str]:
    """CMU's trial description → (interaction kind, prompt)."""
    text = without_note(description).lower()
    for key, kind, words in KINDS:
        if key in text:
            return kind, f"two people {words}"
    return "other", f"two people: {text}"


def _trial_files(folder: Path) -> dict[tuple[int, int], Path]:
    """`SS_TT.bvh` files at any depth under `folder`: una-dinosauria's `0SS/SS_TT.bvh` (commit
    62ac0fb), its newer `data/0SS/SS_TT.bvh`, or one flat folder."""
    out: dict[tuple[int, int], Path] = {}
    for path in sorted(folder.rglob("*.bvh")):
        subject, _, trial = path.stem.partition("_")
        if subject.isdecimal() and trial.isdecimal():
            out[int(subject), int(trial)] = path
    return out


def build_cmu_pairs(raw: Path, index_csv: Path,
                    skipped: list[tuple[str, list[str]]] | None = None) -> list[Clip]:
    """The synchronised pairs under `raw` (one folder per subject), labelled by CMU's index;
    pairs with defects (broken root tracks) go to `skipped`."""
    from interplay.motion.retarget.cmu_daz import load_salsa_pair

    files = _trial_files(raw)
    index = read_cmu_index(index_csv)
    clips = []
    for a, b in PAIRS:
        for (subject, trial), path_a in sorted(files.items()):
            if subject != a or (b, trial) not in files:
                continue
            description, fps = index.get((a, trial), ("unknown", 120))
            kind, prompt = pair_kind(description)
            people, offsets, meta = load_salsa_pair(path_a, files[b, trial], fps=fps)
            windows = contact_windows(people[0], people[1])
            meta.update({"files": [str(p.relative_to(raw)) for p in (path_a, files[b, trial])],
                         "roles": [f"subject A ({a})", f"subject B ({b})"], "kind": kind,
                         "index_fps": fps, "source_fps": meta["native_fps"],
                         "contact_windows": [vars(w) for w in windows]})
            if meta["defects"]:
                if skipped is not None:
                    skipped.append((f"cmu-pairs/{meta['files'][0]}", meta["defects"]))
                continue
            clips.append(Clip(id=f"cmu-pair:{a:02d}_{trial:02d}", source="cmu-pairs", people=people,
                              offsets=offsets, label=without_note(description), prompt=prompt,
                              licence=CMU.name, meta=meta))
    return clips


__all__ = ["KINDS", "PAIRS", "build_cmu_pairs", "pair_kind"]
