"""`interplay generate`, `plan` and `edit`: the pipeline from the command line."""

from __future__ import annotations

import argparse  # noqa: F401
import json
import sys
from pathlib import Path

from interplay.cli.args import CliError, frame_range, read_motion, seconds, write_text


def cmd_generate(args) -> int:
    from pydantic import ValidationError

    from interplay.generators.base import Request, random_seed
    from interplay.generators.router import load_generator
    from interplay.motion.metrics import clip_metrics, frame_highlights
    from interplay.motion.motion import Motion
    from interplay.pipeline.motion_json import plain
    from interplay.pipeline.orchestrator import StageError, default_evaluator, orchestrate
    from interplay.pipeline.requests import GenerationRequest, readable_errors
    try:
        body = GenerationRequest(prompt=args.prompt, persons=args.persons, seconds=args.seconds,
                         seed=args.seed)
    except ValidationError as exc:
        raise CliError(readable_errors(exc.errors())) from None
    prompt = body.prompt
    assert prompt is not None                     # --prompt is required and validated non-empty
    if Path(args.out).is_dir():
        raise CliError(f"{args.out} is a directory; give a file name")
    seed = body.seed if body.seed is not None else random_seed()
    # The studio's pipeline (plan → generate → review → trajectory), so the CLI and the
    # studio give the same motion for the same prompt and seed.
    try:
        out = orchestrate(load_generator(), Request(prompt, body.persons, body.seconds, seed),
                          emit=lambda event: None, on_frames=lambda start, chunk: None,
                          evaluator=default_evaluator())
    except StageError as exc:
        raise CliError(f"generation failed at {exc.stage}: {exc.reason}") from None
    people = [p.astype("float64") for p in out.people]
    motion = Motion(people=out.people, plan=out.plan.to_json(), metrics=clip_metrics(people),
                    highlights=frame_highlights(people), prompt=prompt, seed=seed)
    write_text(args.out, json.dumps(plain(motion.to_json()), separators=(",", ":")))
    print(f"wrote {args.out}: {len(motion.people)} person(s), {motion.frames} frames "
          f"({motion.seconds:g} s), seed {seed}", file=sys.stderr)
    for seg in out.plan.segments:       # what the studio could not make, said (never silent)
        cov = seg.coverage
        if cov is not None and cov.how == "nearest":
            shown = f": {cov.shown}" if cov.shown else ""
            print(f"segment {seg.index} '{seg.prompt}': not in the library — showing the "
                  f"nearest{shown} (verdict not_covered)", file=sys.stderr)
    return 0


def _trajectory_arg(value: str, person: int) -> dict:
    """--trajectory: a preset shape name (circle, zigzag, …) or a JSON file with the drawn
    points ([[x, z], …] metres) or a {"points": …} / {"shape": …, …} object; validated as the
    API validates it."""
    from pydantic import ValidationError

    from interplay.pipeline.requests import TrajectoryIn
    from interplay.planner.schema import readable
    path = Path(value)
    if value.endswith(".json") or path.is_file():
        try:
            data = json.loads(path.read_text())
        except (OSError, ValueError) as exc:
            raise CliError(f"--trajectory {value}: {exc}") from None
        data = {"points": data} if isinstance(data, list) else data
        if not isinstance(data, dict):
            raise CliError(f"--trajectory {value}: expected a list of points or an object")
    else:
        data = {"shape": value}
    try:
        return TrajectoryIn.model_validate({"person": person, **data}).plain()
    except ValidationError as exc:
        raise CliError(f"--trajectory: {readable(exc)}") from None


def cmd_edit(args) -> int:
    from interplay.generators.base import EditUnavailable
    from interplay.generators.router import load_generator
    from interplay.generators.spam.generator import resolve_edit_part
    from interplay.motion.metrics import clip_metrics
    from interplay.motion.motion import Motion
    from interplay.pipeline.editing import edit_joints, follow_path
    from interplay.pipeline.motion_json import plain
    motion = read_motion(args.motion)
    if args.prompt is None and args.trajectory is None:
        raise CliError("give --prompt, --trajectory or both")
    if args.prompt is not None and not args.prompt.strip():
        raise CliError("--prompt must not be empty")
    if Path(args.out).is_dir():
        raise CliError(f"{args.out} is a directory; give a file name")
    trajectory = _trajectory_arg(args.trajectory, args.person) if args.trajectory else None
    people, plan, seed, said = motion.people, motion.plan, motion.seed, []
    try:
        if args.prompt is not None:
            resolve_edit_part(args.part)
            generator = load_generator()
            joints, plan, _, seed = edit_joints(
                generator, motion.people, motion.plan, motion.prompt, args.part, args.prompt,
                args.frames, args.seed)
            people = [joints]
            edit = plan["edits"][-1]
            said.append(f"{edit['part']} frames {edit['frames'][0]}:{edit['frames'][1]}, seed "
                        f"{seed}, untouched joints moved {edit['untouched_change_cm']:.2f} cm")
        if trajectory is not None:
            people = follow_path(people, trajectory)
            plan = dict(plan or {})
            plan["edits"] = list(plan.get("edits") or []) + [{"trajectory": trajectory}]
            what = trajectory.get("shape") or f"{len(trajectory['points'])} drawn points"
            said.append(f"person {trajectory['person']} follows {what}")
    except (ValueError, EditUnavailable) as exc:
        raise CliError(str(exc)) from None
    metrics = clip_metrics([p.astype("float64") for p in people])
    out = Motion(people=people, plan=plan, metrics=metrics, prompt=motion.prompt, seed=seed)
    write_text(args.out, json.dumps(plain(out.to_json()), separators=(",", ":")))
    print(f"wrote {args.out}: {'; '.join(said)}", file=sys.stderr)
    return 0


def cmd_plan(args) -> int:
    from interplay.planner.plan import plan_json
    try:
        plan = plan_json(args.prompt, args.persons, args.seconds)
    except ValueError as exc:
        raise CliError(str(exc)) from None
    if args.json:
        print(json.dumps(plan, indent=1, ensure_ascii=False))
        return 0
    print(f"planner: {plan['planner']} · {len(plan['segments'])} segment(s) · {plan['seconds']:g} s")
    if plan.get("fallback_reason"):
        print(f"fallback: {plan['fallback_reason']}")
    for s in plan["segments"]:
        print(f"{s['index']:>2}  {s['start'] / 20:5.2f}–{s['end'] / 20:5.2f} s  {s['persons']}  "
              f"{s['prompt']}" + (f"  (×{s['repeat']})" if s["repeat"] > 1 else ""))
        print(f"      base: {s['base']}")
        for part, text in (s["edits"] or {}).items():
            if text:
                print(f"      {part}: {text}")
        if s["trajectory"]:
            t = {k: v for k, v in s["trajectory"].items() if v is not None and k != "text"}
            print(f"      trajectory: {t}")
        for who, text in (s["roles"] or {}).items():
            print(f"      person {who}: {text}")
    for reason in plan["reasons"]:
        print(f"  · {reason}")
    return 0


def register(sub) -> None:
    p = sub.add_parser("generate", help="generate a motion from text into a motion JSON file")
    p.add_argument("--prompt", required=True)
    p.add_argument("--persons", type=int, choices=(1, 2), default=1)
    p.add_argument("--seconds", type=seconds, default=6.0, help="1–20 (default 6)")
    p.add_argument("--seed", type=int)
    p.add_argument("--out", required=True, help="motion JSON file to write")
    p.set_defaults(func=cmd_generate)

    p = sub.add_parser("edit", help="re-generate a body part (or frames) of a one-person motion "
                       "with SPAM")
    p.add_argument("motion", help="motion JSON file to edit")
    p.add_argument("--part", default="whole_body", help="left_arm, right_arm, left_leg, "
                   "right_leg, head, whole_body (default) or a model part such as left_upper")
    p.add_argument("--prompt", help="what the edited part does (optional with --trajectory)")
    p.add_argument("--frames", type=frame_range, help="a:b — edit frames a … b−1 only")
    p.add_argument("--seed", type=int)
    p.add_argument("--trajectory", help="a preset shape (circle, zigzag, heart, …) or a JSON "
                   "file of drawn points [[x, z], …] (metres, world) for the person to follow")
    p.add_argument("--person", type=int, default=0, help="who follows --trajectory (default 0)")
    p.add_argument("--out", required=True, help="motion JSON file to write")
    p.set_defaults(func=cmd_edit)

    p = sub.add_parser("plan", help="the planner's plan for a prompt (segments, part edits, "
                       "trajectories, durations) without generating")
    p.add_argument("--prompt", required=True)
    p.add_argument("--persons", type=int, choices=(1, 2), default=1)
    p.add_argument("--seconds", type=seconds, help="total length (default: estimated)")
    p.add_argument("--json", action="store_true", help="the plan JSON the API streams")
    p.set_defaults(func=cmd_plan)
