"""The `react` job (`POST /api/jobs` with `mode: "react"`): a reactor generated frame by frame
(ARFlow, `reaction.react.open_session`) for the stored motion's person 0, streamed next to
the actor as person 1, then stored as a new two-person motion whose parent is the actor's.

Events: plan → segment(generating) → (frames, highlights)* → segment(done) → metrics → done.
Each frames event carries both people for its frames (the actor as stored, the new reactor),
so the player can draw the pair as it grows."""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from interplay.api.digest import frame_digests, motion_digest
from interplay.api.events import (
    DoneEvent,
    MetricsEvent,
    PlanEvent,
    SegmentEvent,
    frames_event,
    highlights_event,
)
from interplay.motion.metrics import clip_metrics
from interplay.motion.skeleton import FPS, NUM_JOINTS
from interplay.pipeline.motion_json import joints_list, plain
from interplay.pipeline.orchestrator import StageError
from interplay.pipeline.segment_source import Cancelled
from interplay.reaction.react import open_session
from interplay.reaction.session import get_reaction_model

CHUNK = 10          # frames per streamed event (0.5 s): the reactor is generated frame by frame


def react_job(job, repo, guidance: bool = True, chunk: int = CHUNK) -> None:
    """Run `job` (JobSpec mode "react"): push its events and store the pair."""
    spec = job.spec
    parent = repo.get(spec.actor_motion_id)
    if parent is None:
        raise StageError("react", f"no motion {spec.actor_motion_id!r} to react to")
    actor = np.asarray(parent.people[0], dtype=np.float64)
    if actor.ndim != 3 or actor.shape[1:] != (NUM_JOINTS, 3) or len(actor) == 0:
        raise StageError("react", f"the stored actor has joints of shape {actor.shape}")
    try:
        session = open_session(get_reaction_model(), prompt=spec.prompt, seed=spec.seed,
                               guidance=guidance)
    except (FileNotFoundError, ValueError) as exc:
        raise StageError("react", str(exc)) from exc
    total = len(actor)
    plan = {"mode": "react", "generator": "arflow", "actor_motion_id": parent.id,
            "prompt": spec.prompt, "frames": total, "guidance": guidance,
            "sampling": plain(vars(session.cfg)), "reproject": session.reproject,
            "session": type(session).__name__}
    job.push(PlanEvent(plan=plan).dump())
    job.push(SegmentEvent(index=0, status="generating", generator="arflow").dump())
    reactor = np.zeros((total, NUM_JOINTS, 3), dtype=np.float64)
    highlights: dict[str, list[Any]] = {"contacts": [], "penetration": [], "min_distance": []}
    step_ms = []
    for start in range(0, total, chunk):
        end = min(total, start + chunk)
        for f in range(start, end):
            if job.cancelled:
                raise Cancelled()
            t0 = time.perf_counter()
            reactor[f] = session.step(actor[f])
            step_ms.append(1000 * (time.perf_counter() - t0))
        people = [actor[start:end], reactor[start:end]]
        job.push(frames_event(start, total, [joints_list(p) for p in people]))
        ctx = 1 if start > 0 else 0
        hl = highlights_event(start, [actor[start - ctx:end], reactor[start - ctx:end]], ctx, 2)
        job.push(hl)
        for k in highlights:
            highlights[k] += hl[k]
    job.push(SegmentEvent(index=0, status="done", generator="arflow").dump())
    final = [actor.astype(np.float32), reactor.astype(np.float32)]
    metrics = plain(clip_metrics([p.astype(np.float64) for p in final], fps=FPS))
    metrics["reactor_step_ms_p50"] = float(np.median(step_ms))
    job.push(MetricsEvent(metrics=metrics).dump())
    edit = {"part": None, "prompt": spec.prompt, "frames": None, "trajectory": None,
            "mode": "react", "guidance": guidance}
    try:
        repo.create(id=job.motion_id, prompt=parent.prompt, people=final,
                    seconds=total / FPS, seed=spec.seed, plan=plain(plan), metrics=metrics,
                    highlights=highlights, parent_id=parent.id, edit=edit,
                    client_id=spec.client_id)
    except Exception as exc:
        raise StageError("store", f"{type(exc).__name__}: {exc}") from exc
    digests = frame_digests(final)
    job.push(DoneEvent(motion_id=job.motion_id, frames=total, digest=motion_digest(digests),
                       frame_digests=digests).dump())
