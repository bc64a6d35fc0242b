// "Person 2 reacts to Person 1": which motions can get a reactor, and the job request that adds one.
// Pure (no store, no network): studio.ts runs the job, ui/ReactorPanel.tsx offers it.
import type { ReactRequest } from "../api/types";
import type { StreamState } from "../api/stream";

/** The longest intent the API takes (schemas.MAX_PROMPT). */
export const MAX_INTENT = 500;

/** A reactor can be added to a stored, finished ONE-person motion while nothing else runs. */
export function canReact(s: { stream: StreamState; motionId: string | null; motionPersons: number; editing: boolean }): boolean {
  return s.stream.phase === "done" && Boolean(s.motionId) && s.motionPersons === 1 && !s.editing;
}

/** POST /api/jobs body for a reactor to `actorId`'s person 0: the intent trimmed and sent only
 * when there is one (the API takes none as "react unprompted"). */
export function reactRequest(actorId: string, intent: string, seed?: number): ReactRequest {
  const req: ReactRequest = { mode: "react", actor_motion_id: actorId };
  const text = intent.split(/\s+/).filter(Boolean).join(" ").slice(0, MAX_INTENT);
  if (text) req.prompt = text;
  if (seed !== undefined) req.seed = seed;
  return req;
}

/** What a react version says about itself: "Person 2 reacts to Person 1: shake hands". */
export function describeReaction(prompt: string | null | undefined): string {
  return prompt ? `Person 2 reacts to Person 1: ${prompt}` : "Person 2 reacts to Person 1";
}
