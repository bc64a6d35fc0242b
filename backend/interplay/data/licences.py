"""The licence of every processed source, and what it means for weights trained on it: one
table that the data card, the model cards (models/*/card.py) and the training option
`--exclude-noncommercial` all read, so they cannot disagree.

A clip's `licence` string (index.json) names its source's licence; composed clips carry
their bases' licences joined by " + " (`interplay.motion.pair.compose`).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass


@dataclass(frozen=True)
class Licence:
    name: str            # as written in a clip's `licence`
    commercial: bool     # may weights trained on it be used commercially?
    consequence: str     # what it means for weights trained with it (model cards)
    credit: str          # the attribution / acknowledgement text to carry


CMU = Licence(
    "CMU", True,
    "CMU's terms: free for research and commercial products; the motion data itself may not be "
    "resold; acknowledge CMU",
    '"The data used in this project was obtained from mocap.cs.cmu.edu. The database was created '
    'with funding from NSF EIA-0196217."')
HDM05 = Licence(
    "CC BY-SA 3.0 (HDM05)", True,
    "CC BY-SA 3.0: attribute HDM05, and treat the weights as derived from CC BY-SA 3.0 material "
    "(share alike)",
    '"The data used in this project was obtained from HDM05." M. Müller, T. Röder, M. Clausen, '
    "B. Eberhardt, B. Krüger, A. Weber: Documentation Mocap Database HDM05, Technical report "
    "CG-2007-2, Universität Bonn, 2007.")
BANDAI_NAMCO = Licence(
    "CC BY-NC 4.0 (Bandai Namco)", False,
    "CC BY-NC 4.0: **non-commercial use only**; attribute Bandai Namco Research (retrain with "
    "`make train EXCLUDE_NONCOMMERCIAL=1` for weights without this term)",
    '"Bandai Namco Research Inc., Bandai-Namco-Research-Motiondataset (CC BY-NC 4.0)"; '
    'M. Kobayashi, C.-C. Liao, K. Inoue, S. Yojima, M. Takahashi: "Motion Capture Dataset for '
    'Practical Use of AI-based Motion Editing and Stylization", arXiv:2306.08861, 2023. '
    "© 2022 Bandai Namco Research Inc.")
DEEPMIMIC = Licence(
    "MIT (DeepMimic)", True,
    "MIT: keep DeepMimic's copyright and permission notice (\"Copyright (c) 2018 Xue Bin Peng\")",
    'DeepMimic motion data, MIT License, "Copyright (c) 2018 Xue Bin Peng" '
    "(github.com/xbpeng/DeepMimic; the notice is in `deepmimic/LICENSE` of the raw data).")

MIT_REACTIDLE = Licence(
    "MIT (ReActIdle)", True,
    "MIT: keep ReActIdle's copyright and permission notice (\"Copyright (c) 2025 [RSAIT]\")",
    'ReActIdle dataset, MIT License, "Copyright (c) 2025 [RSAIT]" (github.com/Enekoassets/ReActIdle); '
    "E. Atxa Landa, E. Lazkano, I. Rodriguez, I. Rodríguez-Moreno, I. Irigoien: \"Evaluating Idle "
    'Animation Believability: a User Perspective", arXiv:2509.05023, 2025.')

LICENCES: dict[str, Licence] = {lic.name: lic for lic in (CMU, HDM05, BANDAI_NAMCO, DEEPMIMIC, MIT_REACTIDLE)}

# Source → its licence (composed clips: per clip, their bases').
SOURCE_LICENCE: dict[str, Licence] = {
    "cmu-bvh": CMU, "cmu-salsa": CMU, "cmu-8action": CMU, "cmu-iclone": CMU, "cmu-asfamc": CMU,
    "hdm05": HDM05, "bandai-namco": BANDAI_NAMCO, "bandai-namco-2": BANDAI_NAMCO, "deepmimic": DEEPMIMIC,
    "reactidle": MIT_REACTIDLE,
}


def licences_of(licence: str) -> list[Licence]:
    """The licences a clip's `licence` string names (" + "-joined for composed clips);
    unknown names raise, so a new source cannot slip past the non-commercial filter."""
    out = []
    for part in licence.split(" + "):
        part = part.strip()
        if part not in LICENCES:
            raise ValueError(f"unknown licence {part!r}; expected one of {sorted(LICENCES)}")
        out.append(LICENCES[part])
    return out


def is_noncommercial(licence: str) -> bool:
    """Whether a clip with this `licence` string may not be used commercially."""
    return any(not lic.commercial for lic in licences_of(licence))


def commercial_only(clips: Iterable, exclude_noncommercial: bool = True) -> list:
    """The clips whose licences allow commercial use (all clips when not excluding)."""
    return [c for c in clips if not (exclude_noncommercial and is_noncommercial(c.licence))]


def weights_notice(licences: Iterable[str]) -> list[str]:
    """Model-card lines for the clip `licence` strings weights were trained on: one bullet per
    licence with its consequence and credit, and a headline saying whether the weights are for
    non-commercial use only."""
    used: dict[str, Licence] = {}
    for s in licences:
        for lic in licences_of(s):
            used[lic.name] = lic
    names = [n for n in LICENCES if n in used]           # the table's order
    noncommercial = [n for n in names if not used[n].commercial]
    head = ("**These weights are for non-commercial use only**: they were trained with "
            f"{', '.join(noncommercial)} data. `make train EXCLUDE_NONCOMMERCIAL=1` retrains them without it."
            if noncommercial else
            "These weights were trained without non-commercial data (no CC BY-NC source); the "
            "terms below still apply.")
    lines = [head, ""]
    lines += [f"- {n}: {used[n].consequence}. Credit: {used[n].credit}" for n in names]
    return lines
