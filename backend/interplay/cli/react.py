"""`interplay react actor.json --out pair.json`: the file-to-file form of the react job."""

from __future__ import annotations

import json
import sys

import numpy as np

from interplay.cli.args import CliError, read_motion, write_text
from interplay.motion.metrics import clip_metrics
from interplay.motion.motion import Motion
from interplay.reaction.react import react


def react_file(actor_motion: Motion, prompt: str | None, seed: int,
               guidance: bool = True) -> tuple[str, str]:
    """(Motion JSON text of the pair [actor, reactor], one-line summary)."""
    from interplay.pipeline.motion_json import plain
    actor = np.asarray(actor_motion.people[0], dtype=np.float64)
    reactor = react(actor, prompt=prompt, seed=seed, guidance=guidance)
    people = [actor.astype(np.float32), reactor.astype(np.float32)]
    metrics = clip_metrics([p.astype(np.float64) for p in people])
    plan = {"mode": "react", "generator": "arflow", "prompt": prompt, "guidance": guidance}
    out = Motion(people, plan=plan, metrics=plain(metrics),
                 prompt=actor_motion.prompt or (prompt or ""), seed=seed)
    summary = (f"2 people, {out.frames} frames, intersection frequency "
               f"{metrics['intersection_frequency']:.3f}, volume "
               f"{metrics['intersection_volume']:.1f} cm³/frame")
    return json.dumps(plain(out.to_json()), separators=(",", ":")), summary


def cmd_react(args) -> int:
    """A reactor (ARFlow, online) for person 0 of a motion file → a two-person motion file."""
    try:
        text, summary = react_file(read_motion(args.actor), args.prompt, args.seed,
                                   guidance=not args.no_guidance)
    except (FileNotFoundError, ValueError) as exc:
        raise CliError(str(exc)) from None
    write_text(args.out, text)
    print(f"wrote {args.out}: {summary}", file=sys.stderr)
    return 0


def register(sub) -> None:
    p = sub.add_parser("react", help="generate a reactor (ARFlow) for person 0 of a motion "
                       "file, frame by frame; writes the pair")
    p.add_argument("actor", help="motion JSON whose person 0 is the actor")
    p.add_argument("--out", required=True, help="two-person motion JSON to write")
    p.add_argument("--prompt", help="optional intent, e.g. 'shake hands'")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--no-guidance", action="store_true", help="no penetration guidance")
    p.set_defaults(func=cmd_react)
