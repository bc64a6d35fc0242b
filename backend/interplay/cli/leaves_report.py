"""`interplay export-leaves --captured / --generated`: issue 27's measures of the captures' own
head and hand turns (`rig/steps.py`: a leaf's channel step over max(30°, its parent bone's
whole turn that frame) is a step over):

- captured: per source, how many clips and people carry captured leaves, and the steps over on
  every carried library clip exported with them, split by whether the capture's own leaf
  turns more than 30° in the world that frame (the source moves that fast: kept, not smoothed);
- generated: the default generator (retrieve-then-edit) on PROMPTS × seeds, exported as the
  API exports them (`pipeline.leaves.export_leaves`): the share of head / wrist frames that
  are the capture's, and the steps over, split by whether both frames are captured.
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np

from interplay.motion.rig.steps import STEP

LEAVES = ("head", "left_wrist", "right_wrist")      # what the exports take (`captured_leaves.EXPORTED`)
# One-person prompts over what retrieve-then-edit does: plain captures, arm actions (a wave, a
# raised arm), primitives (a nod, a shake, jumping jacks, claps), holds, a slowed walk.
PROMPTS = (
    "a person walks forward", "a person walks forward while waving the right hand",
    "a person nods", "a person shakes the head", "a person walks slowly",
    "a person stands still", "a person walks forward then raises the left arm above the head",
    "a person jumps", "a person runs forward", "a person waves with both hands",
    "a person does jumping jacks", "a person claps", "a person walks in a circle",
    "a person kicks with the right leg", "a person stands on one leg", "a person sits down",
)


def _steps(q: np.ndarray) -> np.ndarray:
    from interplay.motion.rig.steps import quat_steps
    return quat_steps(q)


def captured_report() -> None:
    from interplay.motion.captured_leaves import captured_local, captured_world
    from interplay.motion.clip import default_clips
    from interplay.motion.kinematics import floor_height
    from interplay.motion.rig import solve_rig
    from interplay.motion.rig.steps import leaf_excess
    rows: dict[str, dict] = defaultdict(lambda: {"clips": set(), "carried": set(), "people": 0, "with": 0,
                                                 "steps": 0, **{f"{leaf}_{k}": 0 for leaf in LEAVES
                                                                for k in ("over", "fast")}})
    for clip in default_clips():
        people = [np.asarray(p, np.float64) for p in clip.people]
        floor = floor_height(people)
        for k, joints in enumerate(people):
            row = rows[clip.source]
            row["clips"].add(clip.id)
            row["people"] += 1
            world = captured_world(clip.id, k, len(joints))
            if not world:
                continue
            row["carried"].add(clip.id)
            row["with"] += 1
            row["steps"] += len(joints) - 1
            world = {k: v for k, v in world.items() if k in LEAVES}
            excess = leaf_excess(solve_rig(joints, floor=floor, leaves=captured_local(joints, world, floor=floor)))
            for leaf in LEAVES:
                over = excess[leaf] > 0
                row[f"{leaf}_over"] += int(over.sum())
                if leaf in world:
                    row[f"{leaf}_fast"] += int((over & (_steps(world[leaf]) > STEP)).sum())
    print("captured leaves per source: clips and people carrying them, and on those, leaf steps over "
          f"max({STEP:g}°, the parent bone's turn) exported with them (of which the capture's own leaf "
          f"turns > {STEP:g}° in the world that frame)")
    print(f"{'source':<13} {'clips':>9} {'people':>9} {'steps':>7} " + " ".join(f"{leaf:>16}" for leaf in LEAVES))
    total: dict[str, int] = defaultdict(int)
    for source in sorted(rows):
        r = rows[source]
        cells = [f"{r[f'{leaf}_over']:>7} ({r[f'{leaf}_fast']:>5})" for leaf in LEAVES]
        print(f"{source:<13} {len(r['carried']):>4}/{len(r['clips']):<4} {r['with']:>4}/{r['people']:<4} "
              f"{r['steps']:>7} " + " ".join(f"{c:>16}" for c in cells))
        for key in ("with", "people", "steps", *(f"{leaf}_{k}" for leaf in LEAVES for k in ("over", "fast"))):
            total[key] += r[key]
    print(f"{'all':<13} {'':>9} {total['with']:>4}/{total['people']:<4} {total['steps']:>7} "
          + " ".join(f"{total[f'{leaf}_over']:>7} ({total[f'{leaf}_fast']:>5})" for leaf in LEAVES))


def _spread(q: np.ndarray) -> float:
    """How far (deg) a leaf's local rotations (T, 4) turn at most from their mean: 0 for a
    channel that never moves."""
    mean = q.mean(axis=0)
    mean = mean / max(float(np.linalg.norm(mean)), 1e-12)
    return float(np.degrees(2 * np.arccos(np.clip(np.abs(q @ mean), 0.0, 1.0))).max())


def generated_report(seeds: int) -> None:
    from interplay.generators.base import Request
    from interplay.generators.retrieve_edit.generator import RetrieveEditGenerator
    from interplay.generators.router import load_generator
    from interplay.motion import skeleton as sk
    from interplay.motion.kinematics import floor_height
    from interplay.motion.rig import solve_rig
    from interplay.motion.rig.steps import leaf_excess
    from interplay.pipeline.leaves import export_leaves
    gen = RetrieveEditGenerator(load_generator(use_spam=False).index)
    total: dict[str, int] = defaultdict(int)
    print(f"retrieve-then-edit (the default), {len(PROMPTS)} prompts × {seeds} seeds, 6 s, exported as "
          f"the API does. Per prompt and leaf: captured share of frames, its channel's largest turn from "
          f"its mean (deg, summed over seeds as the median), steps over max({STEP:g}°, parent's turn)")
    print(f"{'prompt':<62} " + " ".join(f"{leaf:>20}" for leaf in LEAVES))
    for prompt in PROMPTS:
        cells = []
        per: dict[str, list] = defaultdict(list)
        for seed in range(seeds):
            m = gen.generate(Request(prompt, seconds=6, seed=seed))
            joints = np.asarray(m.people[0], np.float64)
            leaves = export_leaves(m.plan, 1, len(joints))[0]
            rig = solve_rig(joints, floor=floor_height([joints]), leaves=leaves)
            excess = leaf_excess(rig)
            total["frames"] += len(joints)
            total["steps"] += len(joints) - 1
            for leaf in LEAVES:
                got = np.isfinite(leaves[leaf][:, 0]) if leaf in leaves else np.zeros(len(joints), bool)
                bad = excess[leaf] > 0
                per[leaf].append((got.mean(), _spread(rig.rotations[:, sk.JOINT_INDEX[leaf]]), int(bad.sum())))
                total[f"{leaf}_known"] += int(got.sum())
                total[f"{leaf}_over"] += int(bad.sum())
                total[f"{leaf}_both"] += int((bad & got[1:] & got[:-1]).sum())
        for leaf in LEAVES:
            share, spread, count = zip(*per[leaf])
            cells.append(f"{np.mean(share):4.0%} {np.median(spread):5.1f}° {sum(count):3d}")
        print(f"{prompt:<62} " + " ".join(f"{c:>20}" for c in cells))
    print(f"all: {total['frames']} frames, {total['steps']} steps; per leaf: captured frames, steps over "
          f"(of them between two captured frames)")
    for leaf in LEAVES:
        print(f"  {leaf:<12} {total[f'{leaf}_known']:>6} ({total[f'{leaf}_known'] / total['frames']:4.0%}) "
              f"{total[f'{leaf}_over']:>5} ({total[f'{leaf}_both']})")
