// The studio's actions: generate a motion (job + stream), open a stored one, start up.
// They write per-frame data into `frames` and UI state into the store.
import { ApiError, createJob, getMotion, getSkeleton, motionIdFromPath } from "./api/client";
import { openStream, reduceStream, startStream, type StreamHandle } from "./api/stream";
import type { StreamEvent } from "./api/types";
import { FPS, frames, playhead, useStudio } from "./store";

let stream: StreamHandle | null = null;

function message(err: unknown): string {
  if (err instanceof ApiError || err instanceof Error) return err.message;
  return String(err);
}

function fail(err: unknown): void {
  useStudio.setState({ error: message(err) });
}

function handleEvent(ev: StreamEvent): void {
  try {
    if (ev.type === "frames") frames.setFrames(ev.start, ev.people, ev.total);
    else if (ev.type === "highlights") frames.setHighlights(ev);
  } catch (err) {
    ev = { type: "error", message: `bad stream data: ${message(err)}` };
    stream?.close();
  }
  useStudio.setState((s) => ({ stream: reduceStream(s.stream, ev) }));
  if (ev.type === "error") {
    useStudio.setState({ error: ev.message });
    stream = null;
  } else if (ev.type === "done") {
    stream = null;
    useStudio.setState({ motionId: ev.motion_id });
    const path = `/m/${ev.motion_id}`;
    if (window.location.pathname !== path) window.history.pushState({ motionId: ev.motion_id }, "", path);
  }
}

/** Start a generation job with the form's prompt and stream its frames into the scene. */
export async function generate(): Promise<void> {
  const { prompt, persons, seconds } = useStudio.getState();
  stream?.close();
  stream = null;
  useStudio.setState({ error: null });
  let job;
  try {
    job = await createJob({ prompt, persons, seconds });
  } catch (err) {
    fail(err);
    return;
  }
  frames.reset(persons);
  playhead.pos = 0;
  useStudio.setState({
    stream: startStream(),
    motionId: null,
    motionPersons: persons,
    frame: 0,
    playing: true,
  });
  stream = openStream(job.stream, handleEvent);
}

/** Load a stored motion (a share link) into the scene. */
export async function openMotion(id: string): Promise<void> {
  stream?.close();
  stream = null;
  try {
    const motion = await getMotion(id);
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
      },
      motionId: motion.id,
      motionPersons: motion.people.length,
      prompt: motion.prompt,
      persons: motion.people.length === 2 ? 2 : 1,
      seconds: Math.max(1, Math.min(20, Math.round(n / FPS))),
      frame: 0,
      playing: true,
    });
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
