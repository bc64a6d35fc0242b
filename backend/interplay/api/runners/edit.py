"""The edit jobs: a part edit (`POST /api/motions/{id}/edit`, `pipeline.editing.edit_stored`)
and a segment re-run (`POST /api/motions/{id}/segments/{index}/rerun`,
`pipeline.rerun.rerun_stored`), run in a job worker, so they wait in the same queue, under the
same limits, as generation.

Its stream is one event: `done` (the new motion is stored under the job's motion id) or
`error`, with the HTTP status the request answers in the job's result (422 for a bad edit, 503
when the model cannot edit or fails). The new version's review is its parent's, with the
segments the edit changed reviewed again (`version_review`)."""

from __future__ import annotations

import logging
from typing import cast

from interplay.api.events import DoneEvent, ErrorEvent
from interplay.api.runners.version_review import Reviewing
from interplay.generators.base import EditUnavailable
from interplay.pipeline.editing import edit_stored
from interplay.pipeline.orchestrator import default_evaluator
from interplay.pipeline.rerun import rerun_stored
from interplay.pipeline.segment_source import Cancelled
from interplay.store.repository import MotionRepository

log = logging.getLogger(__name__)


def edit_job(job, generator, repo) -> None:
    """Run `job` (JobSpec mode "edit"): store the edited motion, push `done` or `error`."""
    spec, parent = job.spec, _parent(job, repo)
    if parent is None:
        return
    try:
        what = {"kind": "edit", "part": spec.part, "prompt": spec.prompt, "frames": spec.frames}
        edited = edit_stored(_reviewing(repo, parent, what, default_evaluator()), generator,
                             parent, spec.part, spec.prompt, spec.frames,
                             spec.seed, spec.trajectory, id=job.motion_id,
                             client_id=spec.client_id)
    except ValueError as exc:
        return _fail(job, 422, str(exc))
    except EditUnavailable as exc:
        return _fail(job, 503, str(exc))
    except Exception as exc:  # a model failure is reported, never a bare 500
        log.exception("edit of motion %s failed", spec.parent_id)
        return _fail(job, 503, f"the edit failed: {type(exc).__name__}: {exc}")
    job.push(DoneEvent(motion_id=edited.id, frames=edited.frames).dump())


def rerun_job(job, generator, repo) -> None:
    """Run `job` (JobSpec mode "rerun"): store the motion with segment `spec.segment` generated
    again with `spec.seed`, push `done` or `error`."""
    spec, parent = job.spec, _parent(job, repo)
    if parent is None:
        return
    try:
        what = {"kind": "rerun", "segment": int(spec.segment or 0), "seed": spec.seed}
        made = rerun_stored(_reviewing(repo, parent, what, default_evaluator()), generator, parent,
                            int(spec.segment or 0), int(spec.seed or 0),
                            client_id=spec.client_id, id=job.motion_id)
    except ValueError as exc:
        return _fail(job, 422, str(exc))
    except Exception as exc:  # a model failure is reported, never a bare 500
        log.exception("re-run of segment %s of motion %s failed", spec.segment, spec.parent_id)
        return _fail(job, 503, f"the re-run failed: {type(exc).__name__}: {exc}")
    job.push(DoneEvent(motion_id=made.id, frames=made.frames).dump())


def _reviewing(repo, parent, what: dict, evaluator) -> MotionRepository:
    """The repository whose `create` also stores the new version's own review (`Reviewing`
    stands in for it by delegation, so the pipeline's functions take it as the repository)."""
    return cast(MotionRepository, Reviewing(repo, parent, what, evaluator))


def _parent(job, repo):
    """The stored motion the job changes, or None with the job failed (404)."""
    if job.cancelled:
        raise Cancelled()
    parent = repo.get(job.spec.parent_id)
    if parent is None:
        _fail(job, 404, f"no motion {job.spec.parent_id!r} (unknown or malformed id)")
    return parent


def _fail(job, status: int, message: str) -> None:
    job.result = {"http_status": status}
    job.push(ErrorEvent(stage="edit", message=message).dump())
