"""WebSocket /api/jobs/{job_id}/stream: replays a job's events from the first, then follows it
until `done` or `error`, then closes. An unknown job gets one error event and close code 4404;
a browser page of another origin than the served host is closed with 4403 and the reason."""

from __future__ import annotations

from fastapi import APIRouter, WebSocket, WebSocketDisconnect

from interplay.api.security import WS_FORBIDDEN, origin_allowed

router = APIRouter(tags=["jobs"])


@router.websocket("/api/jobs/{job_id}/stream")
async def stream_job(websocket: WebSocket, job_id: str) -> None:
    await websocket.accept()
    ok, why = origin_allowed(websocket, websocket.app.state.settings.allowed_origins)
    if not ok:      # a page of another site: closed before anything is sent
        await websocket.close(code=WS_FORBIDDEN, reason=why)
        return
    job = websocket.app.state.jobs.get(job_id)
    if job is None:
        await websocket.send_json({"type": "error",
                                   "message": f"no job {job_id!r} (unknown, malformed or expired)"})
        await websocket.close(code=4404)
        return
    try:
        async for event in job.events():
            await websocket.send_json(event)
        await websocket.close(code=1000)
    except WebSocketDisconnect:
        pass  # the client left; the job goes on and its motion is still stored
