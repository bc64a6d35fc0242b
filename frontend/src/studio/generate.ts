// Starting jobs from the page: a generation (one job per intent: a changed request replaces the
// running job), a reactor added to the motion on stage, and cancelling the running job.
import { cancelJob, createJob } from "../api/client";
import { intentKey, rememberRequest, resumeUrl } from "../api/intent";
import { openStream, startStream } from "../api/stream";
import type { JobRequest } from "../api/types";
import { reactRequest } from "../directing/react";
import { frames, playhead, useStudio } from "../store";
import { resetCopyCheck } from "../playback/verify";
import { dropStream, fail, live } from "./live";
import { handleEvent, reconnect } from "./follow";
import { formRequest } from "./request";

/** Start a generation job (the form's prompt, or `override`) and stream its frames into the scene. */
export async function generate(override: Partial<JobRequest> = {}): Promise<void> {
  // One job per intent: nothing while a Generate is starting, nothing for the request already
  // running; a changed request replaces the running job (which is cancelled, not left to run).
  const req = formRequest(override);
  const key = intentKey(req);
  const before = useStudio.getState();
  const running = before.stream.phase === "connecting" || before.stream.phase === "generating";
  if (live.starting || (running && (before.intent?.key === key || before.stream.mode === "react"))) return;
  live.starting = true;
  const mine = ++live.turn;
  useStudio.setState({ intent: { key, starting: true } });
  if (running && before.stream.jobId) void cancelJob(before.stream.jobId).catch(() => undefined);
  live.stream?.close();
  live.stream = null;
  live.pendingPersons = null;
  useStudio.setState({ error: null, selected: null, range: null, edit: null });
  let job;
  try {
    job = await createJob(req);
  } catch (err) {
    useStudio.setState({ intent: null });
    // the running job was cancelled and its stream closed above: it ends here (its own last
    // event will not come), so the stage does not wait on it
    if (running && mine === live.turn) handleEvent({ type: "error", message: "cancelled", cancelled: true });
    fail(err);
    return;
  } finally {
    live.starting = false;
  }
  live.turn++; // the new job takes the stage, also from a job followed while its POST was in flight
  dropStream();
  live.sentPath = req.trajectory && !override.trajectory ? useStudio.getState().path.points : null;
  live.sentJob = job.job_id;
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
  live.stream = openStream(job.stream, handleEvent, () => void reconnect(job.job_id));
}

/** Add a reactor (Person 2, generated frame by frame) to the current one-person motion, with an
 * optional intent. The actor stays on stage until the pair's first frames arrive; the pair
 * then grows as it streams, and ends as a new version whose parent is the actor. */
export async function react(intent: string): Promise<void> {
  const { motionId, motionPersons } = useStudio.getState();
  if (!motionId || motionPersons !== 1) return;
  live.turn++;
  live.stream?.close();
  live.stream = null;
  useStudio.setState({ error: null, selected: null, range: null });
  let job;
  try {
    job = await createJob(reactRequest(motionId, intent));
  } catch (err) {
    fail(err);
    return;
  }
  live.pendingPersons = 2;
  window.history.pushState(null, "", resumeUrl(job.job_id, job.motion_id));
  useStudio.setState({ stream: startStream(null, job.job_id, "react", motionId) });
  live.stream = openStream(job.stream, handleEvent, () => void reconnect(job.job_id));
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
