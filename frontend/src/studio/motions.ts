// Stored motions on stage: open one (a share link, a version, a finished job) with its version
// history, show one already fetched, and name it in the address bar.
import { getHistory, getMotion } from "../api/client";
import { agentFromReview } from "../api/agent";
import type { Motion } from "../api/types";
import { fromHistory, moveTo } from "../directing/versions";
import { followedOf, useFollowed } from "../directing/followed";
import { FPS, frames, playhead, useStudio } from "../store";
import { fail, live } from "./live";

/** Put a URL in the address bar for the current version (push: a new version; replace: undo/redo). */
export function showInUrl(id: string, mode: "push" | "replace" = "push"): void {
  const path = `/m/${id}`;
  if (window.location.pathname === path) return;
  if (mode === "push") window.history.pushState({ motionId: id }, "", path);
  else window.history.replaceState({ motionId: id }, "", path);
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
  const mine = ++live.turn;
  live.stream?.close();
  live.stream = null;
  live.pendingPersons = null;
  try {
    const motion = await getMotion(id);
    if (mine !== live.turn) return; // a later action took the stage meanwhile
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
