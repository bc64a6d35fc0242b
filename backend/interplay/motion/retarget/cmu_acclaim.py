"""CMU trials in their original Acclaim form (`cmu-asfamc/`: ASF skeleton per subject beside
each AMC) → the 22-joint SMPL layout.

The files are CMU's own captures, each subject on its own measured skeleton: the same
31-bone Acclaim tree, units (`length 0.45`: inches / 0.45) and axes (Y up, rest facing +Z,
left at +X) as HDM05, so `formats.acclaim` reads them and HDM05's joint map applies
unchanged (`hdm05.JOINT_MAP`: each SMPL joint the end of one Acclaim bone, spine3 between
upperback and thorax, a collar a third of the way along its clavicle).

File names: `csci520/NN_TT-label.amc` with `NN-label.asf`, `fairmotion-tests/NN_TT.amc`
with `NN.asf`. Labels come from CMU's index (`cmu-index/cmu_index.csv`) by (subject, trial).

Frame rate: 120 fps, CMU's index for all six trials; the evidence (`checks.decide_rate`
over 120 and 60: gravity in 01_01's forward jumps and 131_04's hops, cadence of 07_05's
walk and 09_06's run) is recorded per clip in meta["fps_evidence"].
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from interplay.motion.formats.acclaim import load_acclaim
from interplay.motion.retarget import map_joints, to_smpl22
from interplay.motion.retarget.checks import decide_rate, record_fit, settle
from interplay.motion.retarget.hdm05 import JOINT_MAP

CMU_FPS = 120.0
FPS_CANDIDATES = (120.0, 60.0)


def trial_of(amc_path: str | Path) -> tuple[int, int]:
    """NN_TT[-label].amc → (subject, trial)."""
    subject, _, trial = Path(amc_path).stem.partition("-")[0].partition("_")
    if not (subject.isdecimal() and trial.isdecimal()):
        raise ValueError(f"{amc_path}: not a CMU AMC name (NN_TT.amc or NN_TT-label.amc)")
    return int(subject), int(trial)


def find_asf(amc_path: str | Path) -> Path:
    """The subject's ASF beside an AMC: NN.asf or NN-label.asf (subject number as written)."""
    amc_path = Path(amc_path)
    subject = amc_path.stem.split("_")[0]
    found = sorted(p for p in amc_path.parent.glob("*.asf")
                   if p.stem == subject or p.stem.startswith(f"{subject}-"))
    if len(found) != 1:
        raise ValueError(f"{amc_path}: expected one {subject}.asf or {subject}-*.asf beside it, found "
                         f"{[p.name for p in found]}")
    return found[0]


def load_cmu_acclaim(amc_path: str | Path, asf_path: str | Path | None = None) -> tuple[np.ndarray, np.ndarray, dict]:
    """One CMU AMC (+ its subject's ASF, found beside it unless given) → (joints (T, 22, 3)
    at 20 fps, metres, Y up, canonical; offsets (22, 3); meta with the rate evidence, the
    contact check and any defects)."""
    asf_path = find_asf(amc_path) if asf_path is None else Path(asf_path)
    named, asf, amc = load_acclaim(amc_path, asf_path)
    unit = asf.metres_per_unit
    meta: dict = {"skeleton": f"cmu-asf:{asf_path.name}", "frames_native": amc.n_frames,
                  "metres_per_unit": unit, "defects": []}
    fps = decide_rate(map_joints(named, JOINT_MAP) * unit, CMU_FPS, FPS_CANDIDATES, meta)
    fitted, offsets, raw = to_smpl22(named, JOINT_MAP, fps=fps, scale=unit)
    record_fit(fitted, raw, meta)
    return settle(fitted, meta), offsets, meta


__all__ = ["CMU_FPS", "trial_of", "find_asf", "load_cmu_acclaim"]
