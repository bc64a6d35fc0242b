// Following a job's stream: its events into the frames and the store, the end of a generation
// or a reaction, a dropped stream asked for again with back-off (api/retry.ts), and a job
// followed again after a reload (`?job=…`).
import { ApiError, getJob, getMotion } from "../api/client";
import { intentKey, recalledRequest, resumeFromSearch } from "../api/intent";
import { refreshLibrary, showLibrary } from "../library";
import { initialStream, openStream, reduceStream, startStream } from "../api/stream";
import { retryStream } from "../api/retry";
import type { StreamEvent } from "../api/types";
import { fromHistory, pushVersion } from "../directing/versions";
import { useFollowed } from "../directing/followed";
import { frames, playhead, useStudio } from "../store";
import { copyCheck, resetCopyCheck, verifyCopy } from "../playback/verify";
import { fail, FROM_FRAMES, live, message } from "./live";
import { openMotion, showInUrl } from "./motions";
import { formRequest } from "./request";

export function handleEvent(ev: StreamEvent): void {
  try {
    if (ev.type === "frames" && live.pendingPersons !== null) {
      const n = live.pendingPersons === FROM_FRAMES ? ev.people.length : live.pendingPersons;
      frames.reset(n);
      if (live.pendingPersons === FROM_FRAMES) useStudio.setState({ motionPersons: n });
      live.pendingPersons = null;
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
      live.pendingPersons = useStudio.getState().stream.mode === "react" ? 2 : FROM_FRAMES;
    }
  } catch (err) {
    ev = { type: "error", message: `bad stream data: ${message(err)}` };
    live.stream?.close();
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
    live.stream = null;
  } else if (ev.type === "done") {
    live.stream = null;
    // the page's copy against the stored frames: any frame that differs is reloaded
    void verifyCopy(frames, ev, getMotion).catch((err) => fail(err));
    useStudio.setState({ motionId: ev.motion_id, versions: fromHistory([ev.motion_id], ev.motion_id) });
    showInUrl(ev.motion_id);
    void refreshLibrary();
    usePathUp();
  }
}

/** A generation that followed the drawn path is done: the path is used up (it applied to that
 * Generate only), unless a new one was drawn meanwhile. A failed or cancelled one keeps it. */
function usePathUp(): void {
  const s = useStudio.getState();
  // it stays on the floor as the path this motion followed (directing/followed.ts)
  if (live.sentPath !== null && s.motionId) {
    useFollowed.setState({ path: { motionId: s.motionId, person: Math.min(s.path.person, s.motionPersons - 1), points: live.sentPath as [number, number][] } });
  }
  if (live.sentPath !== null && s.path.points === live.sentPath) s.setPath({ points: [], preset: null });
  live.sentPath = null;
  live.sentJob = null;
}

/** The URL of the job being followed (`/?job=…`, kept across a reload) gives way to the stored
 * motion's (`/m/{id}`, in its place) or, without one, to the plain studio. */
function leaveJobUrl(motionId: string | null): void {
  if (!resumeFromSearch(window.location.search)) return;
  window.history.replaceState(motionId ? { motionId } : null, "", motionId ? `/m/${motionId}` : "/");
}

/** The end of a react job: done → the stored pair is the next version after the actor (undo
 * goes back to it); cancelled → back to the actor, as it was; failed → the actor, and the error. */
function handleReactEnd(ev: StreamEvent, actorId: string | null, intent: string | null): void {
  if (ev.type !== "done" && ev.type !== "error") return;
  live.stream = null;
  live.pendingPersons = null;
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

/** The stream of job `jobId` dropped before it ended: keep the job's URL, wait (longer each
 * time, api/retry.ts) until the server answers for the job again, then follow it again from its
 * first event (`resumeJob`: a job the restarted server runs again, a done motion, or one gone). */
export async function reconnect(jobId: string): Promise<void> {
  live.stream = null;
  const mine = live.turn; // any later action (a Generate, a motion opened, …) ends the retries
  const show = (reconnecting: { attempt: number; nextInS: number } | null) =>
    useStudio.setState((s) => ({ stream: { ...s.stream, reconnecting } }));
  await retryStream({
    current: () => live.turn === mine && useStudio.getState().stream.jobId === jobId && live.stream === null,
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
  return follow(jobId, motionId, ++live.turn);
}

/** `resumeJob` on the stage's turn `mine` (a retry follows on the turn it started in). */
async function follow(jobId: string, motionId: string | null, mine: number): Promise<void> {
  let status;
  try {
    status = await getJob(jobId);
  } catch (err) {
    if (mine !== live.turn) return; // the page moved on meanwhile (a Generate, a motion opened)
    // ApiError 0: no answer at all (api/client.ts)
    if (!(err instanceof ApiError) || err.status === 0 || err.status >= 500) {
      // the server is away (restarting): keep the job's URL and try again
      useStudio.setState({ stream: startStream(null, jobId) });
      live.stream = null;
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
    if (mine !== live.turn) return;
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
  if (mine !== live.turn) return;
  if (status.status === "done") {
    window.history.replaceState({ motionId: status.motion_id }, "", `/m/${status.motion_id}`);
    await openMotion(status.motion_id);
    // the job this page sent with the drawn path ended while its stream was away
    if (live.sentJob === jobId && useStudio.getState().motionId === status.motion_id) usePathUp();
    return;
  }
  if (status.status === "failed" || status.status === "cancelled") {
    stopFollowing(jobId);
    window.history.replaceState(null, "", "/");
    showLibrary(`The generation this page was following ended without a motion${status.reason ? ` (${status.reason})` : ""}.`);
    return;
  }
  live.stream?.close();
  live.pendingPersons = FROM_FRAMES;
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
  live.stream = openStream(status.stream, (ev) => {
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
