// The studio's actions: generate a motion (job + stream), open a stored one, start up.
// They write per-frame data into `frames` and UI state into the store. Edits, undo/redo and
// re-runs are in directing/actions.ts.
import { ApiError, cancelJob, createJob, getHistory, getMotion, getSkeleton, motionIdFromPath } from "./api/client";
import { openStream, reduceStream, startStream, type StreamHandle } from "./api/stream";
import { agentFromReview } from "./api/agent";
import type { JobRequest, Motion, StreamEvent, Trajectory } from "./api/types";
import { reactRequest } from "./directing/react";
import { fromHistory, moveTo, pushVersion } from "./directing/versions";
import { FPS, frames, playhead, useStudio } from "./store";

let stream: StreamHandle | null = null;
/** A react job keeps the actor on stage until its first frames arrive; then the buffer is
 * reset to this many people (so the stage never goes blank between the two). */
let pendingPersons: number | null = null;

export function message(err: unknown): string {
  if (err instanceof ApiError || err instanceof Error) return err.message;
  return String(err);
}

export function fail(err: unknown): void {
  useStudio.setState({ error: message(err) });
}

/** Put a URL in the address bar for the current version (push: a new version; replace: undo/redo). */
export function showInUrl(id: string, mode: "push" | "replace" = "push"): void {
  const path = `/m/${id}`;
  if (window.location.pathname === path) return;
  if (mode === "push") window.history.pushState({ motionId: id }, "", path);
  else window.history.replaceState({ motionId: id }, "", path);
}

function handleEvent(ev: StreamEvent): void {
  try {
    if (ev.type === "frames" && pendingPersons !== null) {
      frames.reset(pendingPersons);
      pendingPersons = null;
      playhead.pos = 0;
      useStudio.setState({ frame: 0, playing: true });
    }
    if (ev.type === "frames") frames.setFrames(ev.start, ev.people, ev.total);
    else if (ev.type === "highlights") frames.setHighlights(ev);
  } catch (err) {
    ev = { type: "error", message: `bad stream data: ${message(err)}` };
    stream?.close();
  }
  useStudio.setState((s) => ({ stream: reduceStream(s.stream, ev) }));
  const { mode, actorId, plan } = useStudio.getState().stream;
  if (mode === "react") {
    handleReactEnd(ev, actorId ?? null, (plan?.prompt as string | null | undefined) ?? null);
    return;
  }
  if (ev.type === "error") {
    useStudio.setState({ error: ev.cancelled ? null : ev.message });
    // cancelled: back to an empty, idle stage (the partial frames are not a motion)
    if (ev.cancelled) {
      frames.reset(frames.persons);
      playhead.pos = 0;
      useStudio.setState({ frame: 0, playing: false });
    }
    stream = null;
  } else if (ev.type === "done") {
    stream = null;
    useStudio.setState({ motionId: ev.motion_id, versions: fromHistory([ev.motion_id], ev.motion_id) });
    showInUrl(ev.motion_id);
  }
}

/** The end of a react job: done → the stored pair is the next version after the actor (undo
 * goes back to it); cancelled → back to the actor, as it was; failed → the actor, and the error. */
function handleReactEnd(ev: StreamEvent, actorId: string | null, intent: string | null): void {
  if (ev.type !== "done" && ev.type !== "error") return;
  stream = null;
  pendingPersons = null;
  if (ev.type === "done") {
    useStudio.setState((s) => ({
      motionId: ev.motion_id,
      motionPersons: 2,
      persons: 2,
      edit: { mode: "react", prompt: intent, part: null, frames: null, trajectory: null },
      versions: pushVersion(s.versions, ev.motion_id),
    }));
    showInUrl(ev.motion_id);
    return;
  }
  const error = ev.cancelled ? null : ev.message;
  if (actorId) void openMotion(actorId).then(() => useStudio.setState({ error }));
  else useStudio.setState({ error });
}

/** The drawn (or preset) path to send with a job, when there is one. */
export function currentTrajectory(): Trajectory | undefined {
  const { path, persons } = useStudio.getState();
  if (path.points.length < 2) return undefined;
  const person = (Math.min(path.person, persons - 1) as 0 | 1) ?? 0;
  return { person, points: path.points };
}

/** Start a generation job (the form's prompt, or `override`) and stream its frames into the scene. */
export async function generate(override: Partial<JobRequest> = {}): Promise<void> {
  const { prompt, persons, seconds } = useStudio.getState();
  stream?.close();
  stream = null;
  pendingPersons = null;
  useStudio.setState({ error: null, selected: null, range: null, edit: null });
  const req: JobRequest = { prompt, persons, seconds, ...override };
  const trajectory = override.trajectory ?? currentTrajectory();
  if (trajectory) req.trajectory = trajectory;
  let job;
  try {
    job = await createJob(req);
  } catch (err) {
    fail(err);
    return;
  }
  frames.reset(req.persons);
  playhead.pos = 0;
  useStudio.setState({
    stream: startStream(null, job.job_id),
    motionId: null,
    motionPersons: req.persons,
    frame: 0,
    playing: true,
  });
  stream = openStream(job.stream, handleEvent);
}

/** Add a reactor (person B, generated frame by frame) to the current one-person motion, with an
 * optional intent. The actor stays on stage until the pair's first frames arrive; the pair
 * then grows as it streams, and ends as a new version whose parent is the actor. */
export async function react(intent: string): Promise<void> {
  const { motionId, motionPersons } = useStudio.getState();
  if (!motionId || motionPersons !== 1) return;
  stream?.close();
  stream = null;
  useStudio.setState({ error: null, selected: null, range: null });
  let job;
  try {
    job = await createJob(reactRequest(motionId, intent));
  } catch (err) {
    fail(err);
    return;
  }
  pendingPersons = 2;
  useStudio.setState({ stream: startStream(null, job.job_id, "react", motionId) });
  stream = openStream(job.stream, handleEvent);
}

/** Cancel the running job. */
export async function cancel(): Promise<void> {
  const jobId = useStudio.getState().stream.jobId;
  if (!jobId) return;
  try {
    await cancelJob(jobId);
  } catch (err) {
    fail(err);
  }
}

/** Show a stored motion (already fetched) in the scene. */
export function showMotion(motion: Motion): void {
  frames.loadMotion(motion);
  playhead.pos = 0;
  const n = frames.received;
  useStudio.setState({
    error: null,
    stream: {
      phase: "done",
      plan: motion.plan,
      received: n,
      total: n,
      metrics: motion.metrics,
      motionId: motion.id,
      error: null,
      agent: agentFromReview(motion.review),
      jobId: null,
      cancelled: false,
    },
    motionId: motion.id,
    motionPersons: motion.people.length,
    prompt: motion.prompt,
    persons: motion.people.length === 2 ? 2 : 1,
    seconds: Math.max(1, Math.min(20, Math.round(n / FPS))),
    frame: 0,
    playing: true,
    edit: motion.edit ?? null,
  });
}

/** Load a stored motion (a share link, a version) into the scene, and its version history. */
export async function openMotion(id: string): Promise<void> {
  stream?.close();
  stream = null;
  pendingPersons = null;
  try {
    const motion = await getMotion(id);
    showMotion(motion);
    const known = useStudio.getState().versions;
    if (known.ids.includes(id)) {
      useStudio.setState({ versions: moveTo(known, id) });
      return;
    }
    let chain = [motion.parent_id, id].filter((x): x is string => Boolean(x));
    try {
      chain = (await getHistory(id)).map((v) => v.id);
    } catch {
      /* no history endpoint (yet): the parent and this version */
    }
    useStudio.setState({ versions: fromHistory(chain, id) });
  } catch (err) {
    fail(err);
  }
}

let started = false;

/** Fetch the skeleton, then open the motion named by the URL (/m/{id}) if any. Once per page
 * (React's StrictMode runs effects twice in development). */
export async function startStudio(): Promise<void> {
  if (started) return;
  started = true;
  window.addEventListener("popstate", () => {
    const id = motionIdFromPath(window.location.pathname);
    if (id && id !== useStudio.getState().motionId) void openMotion(id);
  });
  try {
    useStudio.setState({ skeleton: await getSkeleton() });
  } catch (err) {
    fail(err);
    return;
  }
  const id = motionIdFromPath(window.location.pathname);
  if (id) await openMotion(id);
}
