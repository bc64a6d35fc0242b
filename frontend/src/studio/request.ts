// The request Generate sends (the form, the seed, the drawn path) and whether sending it now
// would be one job too many.
import { intentKey } from "../api/intent";
import type { JobRequest, Trajectory } from "../api/types";
import { useStudio, type StudioState } from "../store";

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

/** The drawn (or preset) path to send with a job, when there is one. */
export function currentTrajectory(s: StudioState = useStudio.getState()): Trajectory | undefined {
  const { path, persons } = s;
  if (path.points.length < 2) return undefined;
  const person = (Math.min(path.person, persons - 1) as 0 | 1) ?? 0;
  return { person, points: path.points };
}
