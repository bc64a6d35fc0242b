// The studio's actions: generate a motion (job + stream), open a stored one, start up.
// They write per-frame data into `frames` and UI state into the store. Edits, undo/redo and
// re-runs are in directing/actions.ts. The actions are in studio/: generate.ts (starting jobs),
// request.ts (what Generate sends), follow.ts (their streams, reconnecting, resuming),
// motions.ts (stored motions on stage), live.ts (the stage they share).
import { getSkeleton, motionIdFromPath } from "./api/client";
import { resumeFromSearch } from "./api/intent";
import { watchLibrary } from "./library";
import { useStudio } from "./store";
import { fail } from "./studio/live";
import { resumeJob } from "./studio/follow";
import { openMotion } from "./studio/motions";

export { fail, message } from "./studio/live";
export { openMotion, showInUrl, showMotion } from "./studio/motions";
export { resumeJob } from "./studio/follow";
export { cancel, generate, react } from "./studio/generate";
export { currentTrajectory, formRequest, generateBlocked } from "./studio/request";

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
