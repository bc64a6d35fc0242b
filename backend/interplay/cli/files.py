"""`interplay metrics` and `export`: motion files in, numbers or other formats out."""

from __future__ import annotations

import json
import sys

from interplay.cli.args import CliError, read_motion, write_bytes, write_text


def cmd_metrics(args) -> int:
    from interplay.motion.metrics import clip_metrics
    from interplay.pipeline.motion_json import plain
    motion = read_motion(args.motion)
    metrics = plain(clip_metrics([p.astype("float64") for p in motion.people]))
    if args.json:
        print(json.dumps(metrics, indent=1))
    else:
        width = max(map(len, metrics), default=0)
        print(f"{args.motion}: {len(motion.people)} person(s), {motion.frames} frames")
        for k, v in metrics.items():
            print(f"  {k:<{width}}  {v:.4f}" if isinstance(v, float) else f"  {k:<{width}}  {v}")
    return 0


def _leaves(motion) -> list[dict]:
    """Per person, the leaves to export: the motion's own (an edit's) over the captures' own
    where its frames are a capture's (`pipeline.leaves`: retrieval, retrieve-then-edit)."""
    from interplay.pipeline.leaves import captured_since
    captured = captured_since(motion.plan, len(motion.people), motion.frames)
    return [{**c, **motion.leaves_of(k)} for k, c in enumerate(captured)]


def cmd_export(args) -> int:
    motion = read_motion(args.motion)
    given = [f"--{k}" for k in ("fps", "units", "up", "names") if getattr(args, k) is not None]
    if given and args.format == "json":
        raise CliError(f"{', '.join(given)}: presets for --format bvh or glb only")
    if args.up is not None and args.format == "glb":
        raise CliError("--up: BVH only (glTF is Y up by definition)")
    if args.format == "glb":
        from interplay.motion.formats.gltf import write_glb
        write_bytes(args.out, write_glb([p.astype("float64") for p in motion.people], fps=motion.fps,
                                        mesh=not args.no_mesh, name=motion.prompt or "motion",
                                        out_fps=args.fps or motion.fps, units=args.units or "m",
                                        names=args.names or "smpl",
                                        leaves=_leaves(motion)))
        print(f"wrote {args.out}", file=sys.stderr)
        return 0
    if args.format == "json":
        from interplay.pipeline.motion_json import plain
        text = json.dumps(plain(motion.to_json(rig=True, rig_leaves=_leaves(motion))), separators=(",", ":"))
    else:
        if not 0 <= args.person < len(motion.people):
            raise CliError(f"--person {args.person}: the motion has {len(motion.people)} "
                           f"person(s), numbered from 0")
        from interplay.motion.formats.bvh import write_bvh
        from interplay.motion.kinematics import floor_height
        people = [p.astype("float64") for p in motion.people]
        text = write_bvh(people[args.person], fps=motion.fps, out_fps=args.fps or motion.fps,
                         units=args.units or "m", up=args.up or "y", names=args.names or "smpl",
                         floor=floor_height(people), leaves=_leaves(motion)[args.person])
    write_text(args.out, text)
    print(f"wrote {args.out}", file=sys.stderr)
    return 0


def cmd_export_floor(args) -> int:
    """The floor pass measured on the library: for every clip that goes low (a wrist or knee
    within 25 cm of the floor), how deep hands, knees and feet go under it, of the GLB's mesh
    and of the BVH's joints and end sites, before the pass (the solved rig) and after (the
    export's rig)."""
    import numpy as np

    from interplay.motion.clip import default_clips
    from interplay.motion.formats.floor import TOLERANCE, floor_pass, goes_low, worst
    from interplay.motion.kinematics import floor_height
    from interplay.motion.rig import solve_rig
    rows: list[dict] = []
    for clip in default_clips():
        people = [np.asarray(p, np.float64) for p in clip.people]
        floor = floor_height(people)
        if not goes_low(people, floor):
            continue
        for k, joints in enumerate(people):
            rig = solve_rig(joints, floor=floor)
            row: dict = {"clip": clip.id, "person": k}
            for body in ("mesh", "joints"):
                row[body, "before"] = worst(rig, floor, body)
                row[body, "after"] = worst(floor_pass(rig, floor, body)[0], floor, body)
            rows.append(row)
    print(f"{len(rows)} people in {len({r['clip'] for r in rows})} library clips that go low; "
          f"cm under the floor (worst frame), people over {TOLERANCE * 100:.0f} cm")
    print(f"{'body':<7} {'region':<6} {'before: worst':>14} {'> 1 cm':>7} {'after: worst':>13} {'> 1 cm':>7}")
    for body in ("mesh", "joints"):
        for region in ("hands", "knees", "feet"):
            b = np.array([r[body, "before"][region] for r in rows])
            a = np.array([r[body, "after"][region] for r in rows])
            print(f"{body:<7} {region:<6} {b.max() * 100:>14.1f} {int((b > TOLERANCE).sum()):>7} "
                  f"{a.max() * 100:>13.1f} {int((a > TOLERANCE).sum()):>7}")
    return 0


def cmd_export_channels(args) -> int:
    """BVH channel jumps on the library: per joint, the largest frame-to-frame change of any
    rotation channel and its excess over the true turn, with each joint's fixed order (before)
    and with the order each file picks (after, `formats/channels.channel_order`)."""
    import numpy as np

    from interplay.motion import skeleton as sk
    from interplay.motion.clip import default_clips
    from interplay.motion.formats.channels import _write_order, channel_jumps, channel_order
    from interplay.motion.kinematics import floor_height
    from interplay.motion.rig import solve_rig
    clips = default_clips()[::args.every]
    worst = np.zeros((2, 2, sk.NUM_JOINTS))          # (before/after, jump/excess, joint)
    for clip in clips:
        people = [np.asarray(p, np.float64) for p in clip.people]
        floor = floor_height(people)
        for joints in people:
            if len(joints) < 2:
                continue
            local = solve_rig(joints, floor=floor).matrices()
            for j, name in enumerate(sk.JOINT_NAMES):
                for k, order in enumerate((_write_order(name), channel_order(name, local[:, j]))):
                    jump, turn = channel_jumps(local[:, j], order)
                    worst[k, 0, j] = max(worst[k, 0, j], jump.max())
                    worst[k, 1, j] = max(worst[k, 1, j], (jump - turn).max())
    print(f"{len(clips)} library clips: the largest BVH channel change a frame (deg) and its excess "
          f"over the true turn, fixed orders (before) and per-file orders (after)")
    print(f"{'joint':<15} {'jump before':>11} {'excess':>7} {'jump after':>10} {'excess':>7}")
    for j, name in enumerate(sk.JOINT_NAMES):
        print(f"{name:<15} {worst[0, 0, j]:>11.1f} {worst[0, 1, j]:>7.1f} {worst[1, 0, j]:>10.1f} "
              f"{worst[1, 1, j]:>7.1f}")
    print(f"{'all':<15} {worst[0, 0].max():>11.1f} {worst[0, 1].max():>7.1f} {worst[1, 0].max():>10.1f} "
          f"{worst[1, 1].max():>7.1f}")
    return 0


def cmd_export_leaves(args) -> int:
    """The leaves' steps on the library (`rig/steps.py`): per leaf, how many frame steps of
    its channel exceed max(30°, its parent bone's turn) and by how much at worst, against the
    bone's whole turn (the test's measure) and against its direction's turn only."""
    if args.captured or args.generated:            # the captures' own (`leaves_report.py`)
        from interplay.cli.leaves_report import captured_report, generated_report
        if args.captured:
            captured_report()
        if args.generated:
            generated_report(args.generated)
        return 0
    import numpy as np

    from interplay.motion.clip import default_clips
    from interplay.motion.kinematics import floor_height
    from interplay.motion.rig import solve_rig
    from interplay.motion.rig.steps import LEAF_PARENTS, leaf_excess
    clips = default_clips()[::args.every]
    over: dict[tuple[str, bool], list] = {(leaf, a): [0, 0.0] for leaf in LEAF_PARENTS for a in (False, True)}
    seen, worst_at = 0, []
    for clip in clips:
        people = [np.asarray(p, np.float64) for p in clip.people]
        floor = floor_height(people)
        for k, joints in enumerate(people):
            rig = solve_rig(joints, floor=floor)
            seen += max(rig.frames - 1, 0)
            for along in (False, True):
                for leaf, excess in leaf_excess(rig, direction=along).items():
                    bad = excess > 0
                    over[leaf, along][0] += int(bad.sum())
                    over[leaf, along][1] = max(over[leaf, along][1], float(excess.max(initial=0.0)))
                    if not along:
                        worst_at += [(float(excess[i]), clip.id, k, leaf, int(i) + 1) for i in np.flatnonzero(bad)]
    print(f"{len(clips)} library clips, {seen} frame steps per leaf: steps over max(30°, the parent "
          f"bone's turn) and the worst excess (deg)")
    print(f"{'leaf':<12} {'bone: over':>10} {'worst':>6} {'direction: over':>15} {'worst':>6}")
    for leaf in LEAF_PARENTS:
        bone, line = over[leaf, False], over[leaf, True]
        print(f"{leaf:<12} {bone[0]:>10} {bone[1]:>6.1f} {line[0]:>15} {line[1]:>6.1f}")
    for over_by, cid, k, leaf, frame in sorted(worst_at, reverse=True)[:10]:
        print(f"  {cid} person {k} {leaf} frame {frame}: {over_by:.1f}° over")
    return 0


def register(sub) -> None:
    p = sub.add_parser("metrics", help="clip metrics of a motion JSON file")
    p.add_argument("motion")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.set_defaults(func=cmd_metrics)

    p = sub.add_parser("export", help="export a motion JSON file as BVH (one person), GLB "
                                      "(everyone, skinned) or JSON")
    p.add_argument("motion")
    p.add_argument("--format", choices=("bvh", "glb", "json"), required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--person", type=int, default=0, help="BVH: which person (default 0)")
    from interplay.motion.formats.bvh import FPS_CHOICES, NAMINGS, UNITS, UP_AXES
    p.add_argument("--fps", type=int, choices=FPS_CHOICES,
                   help="BVH, GLB: frames per second, resampled keeping the last pose "
                        "(default 20, the motion's)")
    p.add_argument("--units", choices=tuple(UNITS), help="BVH, GLB: m (default) or cm")
    p.add_argument("--up", choices=UP_AXES,
                   help="BVH: up axis, y (default) or z (facing -Y, as in Blender)")
    p.add_argument("--names", choices=NAMINGS,
                   help="BVH, GLB: joint names, smpl (default) or mixamo (mixamorig:Hips, ...; "
                        "the GLB with Mixamo's bone axes and end bones)")
    p.add_argument("--no-mesh", action="store_true",
                   help="GLB: skeletons and the animation only, no skinned mesh")
    p.set_defaults(func=cmd_export)

    p = sub.add_parser("export-floor", help="the exports' floor pass measured on the library's "
                                            "clips that go low (a table)")
    p.set_defaults(func=cmd_export_floor)

    p = sub.add_parser("export-channels", help="BVH channel jumps per joint on the library's "
                                               "clips, fixed vs per-file Euler orders (a table)")
    p.add_argument("--every", type=int, default=1, help="every n-th clip (default all, ~2 min)")
    p.set_defaults(func=cmd_export_channels)

    p = sub.add_parser("export-leaves", help="head, wrist and toe steps a frame over max(30°, the "
                                             "parent bone's turn) on the library's clips (a table)")
    p.add_argument("--every", type=int, default=1, help="every n-th clip (default all, ~1 min)")
    p.add_argument("--captured", action="store_true", help="instead: per source, the clips carrying "
                   "the captures' own head and hands, and their steps exported with them (~2 min)")
    p.add_argument("--generated", type=int, default=0, metavar="SEEDS",
                   help="instead: the default generator's motions on fixed prompts × SEEDS, exported "
                        "as the API does: captured share, channel turns, steps")
    p.set_defaults(func=cmd_export_leaves)
