"""The `interplay` command: serve, generate, edit, react, metrics, export, bench, eval,
eval-react, eval-pair, data build.

Bad files or arguments exit with code 2 and a one-line message on stderr."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path


class CliError(Exception):
    """A user error: printed as `interplay: error: …`, exit code 2."""


def _read_motion(path: str):
    from .motion.motion import Motion
    p = Path(path)
    if not p.is_file():
        raise CliError(f"{path}: no such file")
    try:
        return Motion.from_json(json.loads(p.read_text()))
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise CliError(f"{path}: not valid JSON ({exc})") from None
    except ValueError as exc:
        raise CliError(f"{path}: not a motion file: {exc}") from None


def _write(path: str, text: str) -> None:
    p = Path(path)
    if p.is_dir():
        raise CliError(f"{path} is a directory; give a file name")
    if not p.parent.is_dir():
        raise CliError(f"{p.parent}: no such directory")
    p.write_text(text)


def cmd_serve(args) -> int:
    import uvicorn

    from .api.app import create_app
    from .settings import get_settings
    settings = get_settings()
    host, port = args.host or settings.host, args.port if args.port is not None else settings.port
    uvicorn.run(create_app(settings.model_copy(update={"host": host, "port": port})),
                host=host, port=port, log_level="info")
    return 0


def cmd_generate(args) -> int:
    from pydantic import ValidationError

    from .agents.generator import load_generator
    from .api.app import readable_errors
    from .api.jobs import make_request, random_seed
    from .api.motion_json import plain
    from .api.schemas import JobCreate
    from .motion.metrics import clip_metrics
    from .settings import get_settings
    try:
        body = JobCreate(prompt=args.prompt, persons=args.persons, seconds=args.seconds,
                         seed=args.seed)
    except ValidationError as exc:
        raise CliError(readable_errors(exc.errors())) from None
    if Path(args.out).is_dir():
        raise CliError(f"{args.out} is a directory; give a file name")
    seed = body.seed if body.seed is not None else random_seed()
    generator = load_generator(get_settings().data_dir, get_settings().spam_dir,
                               coda_dir=get_settings().coda_dir)
    motion = generator.generate(make_request(body.prompt, body.persons, body.seconds, seed))
    if not motion.metrics:
        motion.metrics = clip_metrics([p.astype("float64") for p in motion.people])
    motion.prompt, motion.seed = motion.prompt or body.prompt, seed
    _write(args.out, json.dumps(plain(motion.to_json()), separators=(",", ":")))
    print(f"wrote {args.out}: {len(motion.people)} person(s), {motion.frames} frames "
          f"({motion.seconds:g} s), seed {seed}", file=sys.stderr)
    return 0


def _frames(text: str) -> list[int]:
    try:
        a, b = (int(x) for x in text.split(":"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a frame range a:b") from None
    if not 0 <= a < b:
        raise argparse.ArgumentTypeError(f"{text!r}: need 0 ≤ a < b") from None
    return [a, b]


def _trajectory_arg(value: str, person: int) -> dict:
    """--trajectory: a preset shape name (circle, zigzag, …) or a JSON file with the drawn
    points ([[x, z], …] metres) or a {"points": …} / {"shape": …, …} object; validated as the
    API validates it."""
    from pydantic import ValidationError

    from .agents.plan_schema import readable
    from .api.schemas import TrajectoryIn
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
    from .agents.generator import load_generator
    from .agents.spam_generator import EditUnavailable, resolve_edit_part
    from .api.edits import edit_joints, follow_path
    from .api.motion_json import plain
    from .motion.metrics import clip_metrics
    from .motion.motion import Motion
    from .settings import get_settings
    motion = _read_motion(args.motion)
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
            settings = get_settings()
            generator = load_generator(settings.data_dir, settings.spam_dir,
                                       coda_dir=settings.coda_dir)
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
    _write(args.out, json.dumps(plain(out.to_json()), separators=(",", ":")))
    print(f"wrote {args.out}: {'; '.join(said)}", file=sys.stderr)
    return 0


def cmd_review_eval(args) -> int:
    """The reviewer before/after its correction rounds on CoMA's 40 Table 8 prompts."""
    from .agents.generator import load_generator
    from .agents.review_eval import format_table, run, table8_prompts
    from .settings import get_settings
    if args.limit is not None and args.limit < 1:
        raise CliError("--limit must be at least 1")
    settings = get_settings()
    generator = load_generator(settings.data_dir, settings.spam_dir, coda_dir=settings.coda_dir)
    prompts = table8_prompts()[:args.limit]
    report = run(generator, prompts, seconds=args.seconds, rounds=args.rounds,
                 log=lambda m: print(m, file=sys.stderr))
    print(json.dumps(report, indent=1) if args.json else format_table(report))
    return 0


def cmd_plan(args) -> int:
    from .agents.planner import plan_json
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


def cmd_metrics(args) -> int:
    from .api.motion_json import plain
    from .motion.metrics import clip_metrics
    motion = _read_motion(args.motion)
    metrics = plain(clip_metrics([p.astype("float64") for p in motion.people]))
    if args.json:
        print(json.dumps(metrics, indent=1))
    else:
        width = max(map(len, metrics), default=0)
        print(f"{args.motion}: {len(motion.people)} person(s), {motion.frames} frames")
        for k, v in metrics.items():
            print(f"  {k:<{width}}  {v:.4f}" if isinstance(v, float) else f"  {k:<{width}}  {v}")
    return 0


def cmd_export(args) -> int:
    motion = _read_motion(args.motion)
    if args.format == "json":
        from .api.motion_json import plain
        text = json.dumps(plain(motion.to_json()), separators=(",", ":"))
    else:
        if not 0 <= args.person < len(motion.people):
            raise CliError(f"--person {args.person}: the motion has {len(motion.people)} "
                           f"person(s), numbered from 0")
        from .motion.bvh import write_bvh
        text = write_bvh(motion.people[args.person].astype("float64"), fps=motion.fps)
    _write(args.out, text)
    print(f"wrote {args.out}", file=sys.stderr)
    return 0


def cmd_bench(args) -> int:
    from .bench import format_table, run_bench
    if args.runs < 1:
        raise CliError("--runs must be at least 1")
    from .bench_model import format_model_table, run_model_bench
    from .settings import get_settings
    report, tables, only = {}, [], args.only
    if only in (None, "api"):
        report = run_bench(runs=args.runs, seconds=args.seconds, warmup=args.warmup)
        tables.append(format_table(report))
    if only in (None, "model"):
        report["model"] = run_model_bench(get_settings().spam_dir, runs=args.runs,
                                          warmup=args.warmup)
        tables.append(format_model_table(report["model"]))
    if only in (None, "pair"):
        from .bench_pair import format_pair_table, run_pair_bench
        report["pair"] = run_pair_bench(get_settings().coda_dir, runs=args.runs,
                                        warmup=args.warmup)
        tables.append(format_pair_table(report["pair"]))
    if only in (None, "reaction"):
        from .bench_reaction import format_reaction_table, run_reaction_bench
        report["reaction"] = run_reaction_bench()
        tables.append(format_reaction_table(report["reaction"]))
    print(json.dumps(report, indent=1) if args.json else "\n\n".join(tables))
    return 0


def cmd_data(args) -> int:
    if args.action != "build":
        raise CliError(f"unknown data action {args.action!r}; expected 'build'")
    from .data.build import main as build_main
    return int(build_main(args.rest) or 0)


def _sampling_args(items: list[str] | None) -> list[tuple[str, object]]:
    """["cfg=2.5", "mode=inpaint"] → [("cfg", 2.5), ("mode", "inpaint")] (numbers parsed)."""
    out = []
    for item in items or []:
        key, sep, value = item.partition("=")
        if not sep or not key.strip():
            raise CliError(f"--sampling takes KEY=VALUE, got {item!r}")
        try:
            parsed: object = int(value) if value.strip().lstrip("-").isdigit() else float(value)
        except ValueError:
            parsed = value
        out.append((key.strip(), parsed))
    return out


def cmd_eval(args) -> int:
    from .eval.report import EvalConfig, format_table, run_eval
    from .eval.rows import ROW_NAMES
    rows = [r.strip() for r in args.rows.split(",") if r.strip()] if args.rows else list(ROW_NAMES)
    unknown = [r for r in rows if r not in ROW_NAMES]
    if unknown or not rows:
        raise CliError(f"--rows: unknown row(s) {unknown}; expected some of {','.join(ROW_NAMES)}")
    try:
        cfg = EvalConfig(repeats=args.repeats, seed=args.seed, split=args.split,
                         sampling=tuple(_sampling_args(args.sampling)))
        report = run_eval(rows, cfg, log=lambda m: print(m, file=sys.stderr))
    except (ValueError, FileNotFoundError) as exc:
        raise CliError(str(exc)) from None
    except TypeError as exc:     # a --sampling key the runtime does not take
        raise CliError(f"--sampling: {exc}") from None
    print(json.dumps(report, indent=1) if args.json else format_table(report))
    return 0


def cmd_react(args) -> int:
    """A reactor (ARFlow, online) for person 0 of a motion file → a two-person motion file."""
    from .agents.reaction_cli import react_file
    try:
        text, summary = react_file(_read_motion(args.actor), args.prompt, args.seed,
                                   guidance=not args.no_guidance)
    except (FileNotFoundError, ValueError) as exc:
        raise CliError(str(exc)) from None
    _write(args.out, text)
    print(f"wrote {args.out}: {summary}", file=sys.stderr)
    return 0


def cmd_eval_react(args) -> int:
    from dataclasses import replace as _replace

    from .agents.reaction import get_reaction_model
    from .agents.reaction_eval import ROWS, format_table, run_eval_react
    try:
        rows = tuple(args.rows.split(",")) if args.rows else ROWS
        if any(r not in ROWS for r in rows):
            raise ValueError(f"--rows: expected some of {','.join(ROWS)}, got {args.rows!r}")
        model = get_reaction_model()
        sampling = model.sampling
        for item in args.sampling or ():
            key, _, value = item.partition("=")
            if key not in sampling.__dataclass_fields__ or not value:
                raise ValueError(f"--sampling {item!r}: expected KEY=VALUE with KEY one of "
                                 f"{', '.join(sampling.__dataclass_fields__)}")
            kind = type(getattr(sampling, key))
            sampling = _replace(sampling, **{key: kind(float(value)) if kind is int else kind(value)})
        report = run_eval_react(rows, repeats=args.repeats, seed=args.seed, model=model,
                                sampling=sampling, split=args.split,
                                log=lambda m: print(m, file=sys.stderr))
    except (FileNotFoundError, ValueError) as exc:
        raise CliError(str(exc)) from None
    print(json.dumps(report, indent=1) if args.json else format_table(report))
    return 0


def _seconds(text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of seconds") from None


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="interplay", description="Text to 3D human motion for one "
                                 "or two people, on CPU.")
    sub = ap.add_subparsers(dest="command", required=True, metavar="COMMAND")

    p = sub.add_parser("serve", help="run the studio (API + front end)")
    p.add_argument("--host", help="listen address (default INTERPLAY_HOST or 127.0.0.1)")
    p.add_argument("--port", type=int, help="port (default INTERPLAY_PORT or 8000)")
    p.set_defaults(func=cmd_serve)

    p = sub.add_parser("generate", help="generate a motion from text into a motion JSON file")
    p.add_argument("--prompt", required=True)
    p.add_argument("--persons", type=int, choices=(1, 2), default=1)
    p.add_argument("--seconds", type=_seconds, default=6.0, help="1–20 (default 6)")
    p.add_argument("--seed", type=int)
    p.add_argument("--out", required=True, help="motion JSON file to write")
    p.set_defaults(func=cmd_generate)

    p = sub.add_parser("edit", help="re-generate a body part (or frames) of a one-person motion "
                       "with SPAM")
    p.add_argument("motion", help="motion JSON file to edit")
    p.add_argument("--part", default="whole_body", help="left_arm, right_arm, left_leg, "
                   "right_leg, whole_body (default) or a model part such as left_upper")
    p.add_argument("--prompt", help="what the edited part does (optional with --trajectory)")
    p.add_argument("--frames", type=_frames, help="a:b — edit frames a … b−1 only")
    p.add_argument("--seed", type=int)
    p.add_argument("--trajectory", help="a preset shape (circle, zigzag, heart, …) or a JSON "
                   "file of drawn points [[x, z], …] (metres, world) for the person to follow")
    p.add_argument("--person", type=int, default=0, help="who follows --trajectory (default 0)")
    p.add_argument("--out", required=True, help="motion JSON file to write")
    p.set_defaults(func=cmd_edit)

    p = sub.add_parser("review-eval", help="the reviewer before/after its correction rounds on "
                       "CoMA's 40 Table 8 prompts (alignment, confirmed part edits, metrics)")
    p.add_argument("--json", action="store_true", help="the full report as JSON")
    p.add_argument("--limit", type=int, help="only the first N prompts")
    p.add_argument("--seconds", type=float, default=8.0, help="length per prompt (default 8)")
    p.add_argument("--rounds", type=int, default=2, help="K review rounds (default 2)")
    p.set_defaults(func=cmd_review_eval)

    p = sub.add_parser("plan", help="the planner's plan for a prompt (segments, part edits, "
                       "trajectories, durations) without generating")
    p.add_argument("--prompt", required=True)
    p.add_argument("--persons", type=int, choices=(1, 2), default=1)
    p.add_argument("--seconds", type=_seconds, help="total length (default: estimated)")
    p.add_argument("--json", action="store_true", help="the plan JSON the API streams")
    p.set_defaults(func=cmd_plan)

    p = sub.add_parser("metrics", help="clip metrics of a motion JSON file")
    p.add_argument("motion")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.set_defaults(func=cmd_metrics)

    p = sub.add_parser("export", help="export a motion JSON file as BVH (one person) or JSON")
    p.add_argument("motion")
    p.add_argument("--format", choices=("bvh", "json"), required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--person", type=int, default=0, help="BVH: which person (default 0)")
    p.set_defaults(func=cmd_export)

    p = sub.add_parser("bench", help="time jobs through the real HTTP API and WebSocket, and "
                       "the SPAM model on onnxruntime")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.add_argument("--runs", type=int, default=3, help="timed jobs per person count (default 3)")
    p.add_argument("--seconds", type=_seconds, default=6.0, help="motion length (default 6)")
    p.add_argument("--warmup", type=int, default=1, help="untimed jobs first (default 1)")
    p.add_argument("--only", choices=("api", "model", "pair", "reaction"), help="one section: "
                   "jobs through the API, SPAM on onnxruntime, CODA two-person generation, or "
                   "the ARFlow reactor (default all)")
    p.set_defaults(func=cmd_bench)

    p = sub.add_parser("eval", help="text-to-motion metrics (R-precision, FID, …) of every "
                       "generator on the test split, with 95%% confidence intervals")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.add_argument("--repeats", type=int, default=10, help="repeats for the CIs (default 10)")
    p.add_argument("--rows", help="comma-separated: real,retrieval,spam,spam_fp32,spam_nocs,"
                   "spam_vq,single_vq (default all; rows without weights are skipped)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--split", choices=("test", "val"), default="test",
                   help="val: choose settings there (its own edit cases), never on test")
    p.add_argument("--sampling", nargs="*", metavar="KEY=VALUE",
                   help="SPAM rows' settings, e.g. cfg=2.5 steps=10 mode=inpaint")
    p.set_defaults(func=cmd_eval)

    p = sub.add_parser("react", help="generate a reactor (ARFlow) for person 0 of a motion "
                       "file, frame by frame; writes the pair")
    p.add_argument("actor", help="motion JSON whose person 0 is the actor")
    p.add_argument("--out", required=True, help="two-person motion JSON to write")
    p.add_argument("--prompt", help="optional intent, e.g. 'shake hands'")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--no-guidance", action="store_true", help="no penetration guidance")
    p.set_defaults(func=cmd_react)

    p = sub.add_parser("eval-react", help="ARFlow reactions on the test split's pairs: FID, "
                       "IV, IF, contacts, skating without/with guidance and reprojection")
    p.add_argument("--json", action="store_true", help="machine-readable output")
    p.add_argument("--repeats", type=int, default=2, help="sampling seeds per row (default 2)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--split", choices=("test", "val"), default="test",
                   help="val: for choosing sampling settings (never tune on test)")
    p.add_argument("--rows", help="comma-separated subset of the rows (default all)")
    p.add_argument("--sampling", action="append", metavar="KEY=VALUE",
                   help="override a sampling setting, e.g. guidance=0.5 (repeatable)")
    p.set_defaults(func=cmd_eval_react)

    from .eval.pair_cli import add_eval_pair
    add_eval_pair(sub)

    p = sub.add_parser("data", help="processed data set: `interplay data build [options]`")
    p.add_argument("action", choices=("build",))
    p.add_argument("rest", nargs=argparse.REMAINDER, help="options passed to the build")
    p.set_defaults(func=cmd_data)
    return ap


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except CliError as exc:
        print(f"interplay: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130


if __name__ == "__main__":
    sys.exit(main())
