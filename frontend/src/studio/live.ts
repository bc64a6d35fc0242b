// The studio's shared stage (the stream followed, what its actions keep between them) and how
// an action reports a failure.
import { ApiError } from "../api/client";
import type { StreamHandle } from "../api/stream";
import { useStudio } from "../store";

/** The studio's stage, shared by its actions: the stream followed now, and what the actions
 * that take the stage keep between them. */
export const live: {
  stream: StreamHandle | null;
  /** A react job keeps the actor on stage until its first frames arrive; then the buffer is
   * reset to this many people (so the stage never goes blank between the two). */
  pendingPersons: number | null;
  /** A Generate whose POST is in flight (a second one is ignored until it answers). */
  starting: boolean;
  /** Counts the actions that take the stage (a Generate, a reactor, a motion opened, a job
   * followed): one still waiting on the server when a later one came leaves the stage alone. */
  turn: number;
  /** The drawn path the running job was sent with (it applies to that one Generate), and that job. */
  sentPath: unknown;
  sentJob: string | null;
} = { stream: null, pendingPersons: null, starting: false, turn: 0, sentPath: null, sentJob: null };

/** A job reattached after a reload: its people are known from its first frames. */
export const FROM_FRAMES = -1;

/** Close the stream followed now, if any (an action that waited on the server may find one
 * opened meanwhile). */
export function dropStream(): void {
  live.stream?.close();
  live.stream = null;
}

export function message(err: unknown): string {
  if (err instanceof ApiError || err instanceof Error) return err.message;
  return String(err);
}

export function fail(err: unknown): void {
  useStudio.setState({ error: message(err) });
}
