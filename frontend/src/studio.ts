// The studio's actions: generate a motion (job + stream), open a stored one, start up.
// They write per-frame data into `frames` and UI state into the store. Edits, undo/redo and
// re-runs are in directing/actions.ts.
import { ApiError, cancelJob, createJob, getHistory, getJob, getMotion, getSkeleton, motionIdFromPath } from "./api/client";
import { intentKey, recalledRequest, rememberRequest, resumeFromSearch, resumeUrl } from "./api/intent";
import { refreshLibrary, showLibrary, watchLibrary } from "./library";
import { initialStream, openStream, reduceStream, startStream, type StreamHandle } from "./api/stream";
import { retryStream } from "./api/retry";
import { agentFromReview } from "./api/agent";
import type { JobRequest, Motion, StreamEvent, Trajectory } from "./api/types";
import { reactRequest } from "./directing/react";
import { fromHistory, moveTo, pushVersion } from "./directing/versions";
import { followedOf, useFollowed } from "./directing/followed";
import { FPS, frames, playhead, useStudio, type StudioState } from "./store";
import { copyCheck, resetCopyCheck, verifyCopy } from "./playback/verify";

let stream: StreamHandle | null = null;
/** A react job keeps the actor on stage until its first frames arrive; then the buffer is
 * reset to this many people (so the stage never goes blank between the two). */
let pendingPersons: number | null = null;
/** A job reattached after a reload: its people are known from its first frames. */
const FROM_FRAMES = -1;
/** A Generate whose POST is in flight (a second one is ignored until it answers). */
let starting = false;
/** Counts the actions that take the stage (a Generate, a reactor, a motion opened, a job
 * followed): one still waiting on the server when a later one came leaves the stage alone. */
let turn = 0;

/** Close the stream followed now, if any (an action that waited on the server may find one
 * opened meanwhile). */
function dropStream(): void {
  stream?.close();
  stream = null;
}

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
      const n = pendingPersons === FROM_FRAMES ? ev.people.length : pendingPersons;
      frames.reset(n);
      if (pendingPersons === FROM_FRAMES) useStudio.setState({ motionPersons: n });
      pendingPersons = null;
      playhead.pos = 0;
      useStudio.setState({ frame: 0, playing: true });
    }
    if (ev.type === "frames") frames.setFrames(ev.start, ev.people, ev.total);
    else if (ev.type === "replace") {
      // frames changed after they were streamed (a correction, the pair pass, a path)
      frames.setFrames(ev.start, ev.people);
      copyCheck.replaced += ev.people[0]?.length ?? 0;
    } else if (ev.type === "highlights") frames.setHighlights(ev);
    else if (ev.type === "restart") {
      // the job runs again from its start: what the earlier attempt streamed goes
      resetCopyCheck();
      pendingPersons = useStudio.getState().stream.mode === "react" ? 2 : FROM_FRAMES;
    }
  } catch (err) {
    ev = { type: "error", message: `bad stream data: ${message(err)}` };
    stream?.close();
  }
  useStudio.setState((s) => ({ stream: reduceStream(s.stream, ev) }));
  const { mode, actorId, plan } = useStudio.getState().stream;
  // a react job that did not finish goes back to its actor
  if (ev.type === "done" || ev.type === "error") leaveJobUrl(ev.type === "done" ? ev.motion_id : mode === "react" ? (actorId ?? null) : null);
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
    // the page's copy against the stored frames: any frame that differs is reloaded
    void verifyCopy(frames, ev, getMotion).catch((err) => fail(err));
    useStudio.setState({ motionId: ev.motion_id, versions: fromHistory([ev.motion_id], ev.motion_id) });
    showInUrl(ev.motion_id);
    void refreshLibrary();
    usePathUp();
  }
}

/** The drawn path the running job was sent with (it applies to that one Generate), and that job. */
let sentPath: unknown = null;
let sentJob: string | null = null;

/** A generation that followed the drawn path is done: the path is used up (it applied to that
 * Generate only), unless a new one was drawn meanwhile. A failed or cancelled one keeps it. */
function usePathUp(): void {
  const s = useStudio.getState();
  // it stays on the floor as the path this motion followed (directing/followed.ts)
  if (sentPath !== null && s.motionId) {
    useFollowed.setState({ path: { motionId: s.motionId, person: Math.min(s.path.person, s.motionPersons - 1), points: sentPath as [number, number][] } });
  }
  if (sentPath !== null && s.path.points === sentPath) s.setPath({ points: [], preset: null });
  sentPath = null;
  sentJob = null;
}

/** The URL of the job being followed (`/?job=…`, kept across a reload) gives way to the stored
 * motion's (`/m/{id}`, in its place) or, without one, to the plain studio. */
function leaveJobUrl(motionId: string | null): void {
  if (!resumeFromSearch(window.location.search)) return;
  window.history.replaceState(motionId ? { motionId } : null, "", motionId ? `/m/${motionId}` : "/");
}

/** The request Generate sends from the form (and the drawn path), with `override`. */
export function formRequest(override: Partial<JobRequest> = {}, s: StudioState = useStudio.getState()): JobRequest {
  const { prompt, persons, seconds } = s;
  // the seed field's seed (none: the server picks one); an override's seed wins
  const req: JobRequest = { prompt, persons, seconds, ...(s.seed !== null ? { seed: s.seed } : {}), ...override };
  const trajectory = override.trajectory ?? currentTrajectory(s);
  if (trajectory) req.trajectory = trajectory;
  return req;
}

/** Whether Generate would send one job too many: a Generate is being started, or a job for
 * this very request is running (a double click, Enter again). A changed request may go. */
export function generateBlocked(s: StudioState = useStudio.getState()): boolean {
  if (s.intent?.starting) return true;
  const running = s.stream.phase === "connecting" || s.stream.phase === "generating";
  if (running && s.stream.mode === "react") return true; // the reactor panel owns that job
  return running && s.intent !== null && s.intent.key === intentKey(formRequest({}, s));
}

/** The end of a react job: done → the stored pair is the next version after the actor (undo
 * goes back to it); cancelled → back to the actor, as it was; failed → the actor, and the error. */
function handleReactEnd(ev: StreamEvent, actorId: string | null, intent: string | null): void {
  if (ev.type !== "done" && ev.type !== "error") return;
  stream = null;
  pendingPersons = null;
  if (ev.type === "done") {
    void verifyCopy(frames, ev, getMotion).catch((err) => fail(err));
    useStudio.setState((s) => ({
      motionId: ev.motion_id,
      motionPersons: 2,
      persons: 2,
      edit: { mode: "react", prompt: intent, part: null, frames: null, trajectory: null },
      versions: pushVersion(s.versions, ev.motion_id),
    }));
    showInUrl(ev.motion_id);
    void refreshLibrary();
    return;
  }
  const error = ev.cancelled ? null : ev.message;
  if (actorId) void openMotion(actorId).then(() => useStudio.setState({ error }));
  else useStudio.setState({ error });
}

/** The drawn (or preset) path to send with a job, when there is one. */
export function currentTrajectory(s: StudioState = useStudio.getState()): Trajectory | undefined {
  const { path, persons } = s;
  if (path.points.length < 2) return undefined;
  const person = (Math.min(path.person, persons - 1) as 0 | 1) ?? 0;
  return { person, points: path.points };
}

/** Start a generation job (the form's prompt, or `override`) and stream its frames into the scene. */
export async function generate(override: Partial<JobRequest> = {}): Promise<void> {
  // One job per intent: nothing while a Generate is starting, nothing for the request already
  // running; a changed request replaces the running job (which is cancelled, not left to run).
  const req = formRequest(override);
  const key = intentKey(req);
  const before = useStudio.getState();
  const running = before.stream.phase === "connecting" || before.stream.phase === "generating";
  if (starting || (running && (before.intent?.key === key || before.stream.mode === "react"))) return;
  starting = true;
  const mine = ++turn;
  useStudio.setState({ intent: { key, starting: true } });
  if (running && before.stream.jobId) void cancelJob(before.stream.jobId).catch(() => undefined);
  stream?.close();
  stream = null;
  pendingPersons = null;
  useStudio.setState({ error: null, selected: null, range: null, edit: null });
  let job;
  try {
    job = await createJob(req);
  } catch (err) {
    useStudio.setState({ intent: null });
    // the running job was cancelled and its stream closed above: it ends here (its own last
    // event will not come), so the stage does not wait on it
    if (running && mine === turn) handleEvent({ type: "error", message: "cancelled", cancelled: true });
    fail(err);
    return;
  } finally {
    starting = false;
  }
  turn++; // the new job takes the stage, also from a job followed while its POST was in flight
  dropStream();
  sentPath = req.trajectory && !override.trajectory ? useStudio.getState().path.points : null;
  sentJob = job.job_id;
  window.history.pushState(null, "", resumeUrl(job.job_id, job.motion_id));
  rememberRequest(job.job_id, req);
  frames.reset(req.persons);
  resetCopyCheck();
  playhead.pos = 0;
  useStudio.setState({
    stream: { ...startStream(null, job.job_id), path: Boolean(req.trajectory) },
    intent: { key, starting: false },
    motionId: null,
    motionPersons: req.persons,
    frame: 0,
    playing: true,
  });
  stream = openStream(job.stream, handleEvent, () => void reconnect(job.job_id));
}

/** The stream of job `jobId` dropped before it ended: keep the job's URL, wait (longer each
 * time, api/retry.ts) until the server answers for the job again, then follow it again from its
 * first event (`resumeJob`: a job the restarted server runs again, a done motion, or one gone). */
async function reconnect(jobId: string): Promise<void> {
  stream = null;
  const mine = turn; // any later action (a Generate, a motion opened, …) ends the retries
  const show = (reconnecting: { attempt: number; nextInS: number } | null) =>
    useStudio.setState((s) => ({ stream: { ...s.stream, reconnecting } }));
  await retryStream({
    current: () => turn === mine && useStudio.getState().stream.jobId === jobId && stream === null,
    show,
    reachable: () => getJob(jobId).then(() => true, (err) => err instanceof ApiError && err.status === 404),
    resume: () => follow(jobId, resumeFromSearch(window.location.search)?.motion ?? null, mine),
    giveUp: () => handleEvent({ type: "error", message: "the server did not come back; reload the page to try again" }),
  });
}

/** The page stops following job `jobId` (it ended without a motion, or is unknown): a stage
 * still waiting on it (its stream dropped and was being followed again) goes idle. */
function stopFollowing(jobId: string): void {
  if (useStudio.getState().stream.jobId === jobId) useStudio.setState({ stream: initialStream });
}

/** After a reload with `?job=…`: follow that job again (its stream replays every event from
 * the start), or open its motion if it is done; if the server no longer knows it, say so and
 * show My motions. */
export function resumeJob(jobId: string, motionId: string | null): Promise<void> {
  return follow(jobId, motionId, ++turn);
}

/** `resumeJob` on the stage's turn `mine` (a retry follows on the turn it started in). */
async function follow(jobId: string, motionId: string | null, mine: number): Promise<void> {
  let status;
  try {
    status = await getJob(jobId);
  } catch (err) {
    if (mine !== turn) return; // the page moved on meanwhile (a Generate, a motion opened)
    // ApiError 0: no answer at all (api/client.ts)
    if (!(err instanceof ApiError) || err.status === 0 || err.status >= 500) {
      // the server is away (restarting): keep the job's URL and try again
      useStudio.setState({ stream: startStream(null, jobId) });
      stream = null;
      void reconnect(jobId);
      return;
    }
    if (err.status !== 404) {
      stopFollowing(jobId);
      fail(err);
      return;
    }
    // gone (expired, or the server restarted): its motion may still be stored
    const stored = motionId !== null && (await getMotion(motionId).then(() => true, () => false));
    if (mine !== turn) return;
    if (motionId && stored) {
      window.history.replaceState({ motionId }, "", `/m/${motionId}`);
      await openMotion(motionId);
      return;
    }
    stopFollowing(jobId);
    window.history.replaceState(null, "", "/");
    showLibrary("The generation this page was following is no longer on the server (it expired or the server restarted). Your motions are below.");
    return;
  }
  if (mine !== turn) return;
  if (status.status === "done") {
    window.history.replaceState({ motionId: status.motion_id }, "", `/m/${status.motion_id}`);
    await openMotion(status.motion_id);
    // the job this page sent with the drawn path ended while its stream was away
    if (sentJob === jobId && useStudio.getState().motionId === status.motion_id) usePathUp();
    return;
  }
  if (status.status === "failed" || status.status === "cancelled") {
    stopFollowing(jobId);
    window.history.replaceState(null, "", "/");
    showLibrary(`The generation this page was following ended without a motion${status.reason ? ` (${status.reason})` : ""}.`);
    return;
  }
  stream?.close();
  pendingPersons = FROM_FRAMES;
  frames.reset(1);
  resetCopyCheck();
  playhead.pos = 0;
  // this browser sent it: the form shows the request at once (else: from the plan, below)
  const sent = recalledRequest(status.job_id);
  if (sent) useStudio.setState({ prompt: sent.prompt, persons: sent.persons, seconds: sent.seconds });
  useStudio.setState({
    stream: { ...startStream(null, status.job_id), path: Boolean(sent?.trajectory) },
    intent: sent ? { key: intentKey(sent), starting: false } : null,
    motionId: null,
    frame: 0,
    playing: true,
  });
  stream = openStream(status.stream, (ev) => {
    // the plan says what is being made: the form shows it (so Generate knows it is running)
    if (ev.type === "plan" && ev.plan.mode !== "react") {
      if (sent) return handleEvent(ev);
      const p = ev.plan as { prompt?: string; persons?: number; seconds?: number };
      const form = {
        prompt: typeof p.prompt === "string" ? p.prompt : useStudio.getState().prompt,
        persons: (p.persons === 2 ? 2 : 1) as 1 | 2,
        seconds: typeof p.seconds === "number" ? p.seconds : useStudio.getState().seconds,
      };
      useStudio.setState({ ...form, motionPersons: form.persons });
      useStudio.setState({ intent: { key: intentKey(formRequest()), starting: false } });
    } else if (ev.type === "plan") {
      const actor = (ev.plan.actor_motion_id as string | undefined) ?? null;
      useStudio.setState((s) => ({ stream: { ...s.stream, mode: "react", actorId: actor } }));
    }
    handleEvent(ev);
  }, () => void reconnect(status.job_id));
}

/** Add a reactor (Person 2, generated frame by frame) to the current one-person motion, with an
 * optional intent. The actor stays on stage until the pair's first frames arrive; the pair
 * then grows as it streams, and ends as a new version whose parent is the actor. */
export async function react(intent: string): Promise<void> {
  const { motionId, motionPersons } = useStudio.getState();
  if (!motionId || motionPersons !== 1) return;
  turn++;
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
  window.history.pushState(null, "", resumeUrl(job.job_id, job.motion_id));
  useStudio.setState({ stream: startStream(null, job.job_id, "react", motionId) });
  stream = openStream(job.stream, handleEvent, () => void reconnect(job.job_id));
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
  useFollowed.setState({ path: followedOf(motion) }); // the path it followed stays on the floor
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
    seconds: ((l) => Math.max(l.secondsMin, Math.min(l.secondsMax, Math.round(n / FPS))))(useStudio.getState().limits),
    frame: 0,
    playing: true,
    edit: motion.edit ?? null,
  });
}

/** Load a stored motion (a share link, a version) into the scene, and its version history. */
export async function openMotion(id: string): Promise<void> {
  const mine = ++turn;
  stream?.close();
  stream = null;
  pendingPersons = null;
  try {
    const motion = await getMotion(id);
    if (mine !== turn) return; // a later action took the stage meanwhile
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
  watchLibrary();
  const resume = resumeFromSearch(window.location.search);
  if (resume) {
    await resumeJob(resume.job, resume.motion);
    return;
  }
  const id = motionIdFromPath(window.location.pathname);
  if (id) await openMotion(id);
}
