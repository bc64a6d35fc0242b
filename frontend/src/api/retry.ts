// A job's stream dropped before the job ended (the server restarted, the network went away):
// wait, longer each time, until the server answers for the job again, then follow it again from
// its first event. The studio's `reconnect` fills in the hooks; the loop is here, testable.

/** Seconds between tries: 1, 1, 2, 3, then every 5 s; about 5 minutes in all. */
export const RETRY_S = [1, 1, 2, 3, 5];
export const MAX_TRIES = 64;

export interface RetryHooks {
  /** Whether the page still follows this job (the user may have moved on). */
  current(): boolean;
  /** Show the state: try `attempt`, the next in `nextInS` s (0: asking now); null: done. */
  show(state: { attempt: number; nextInS: number } | null): void;
  /** Ask the server about the job: true when it answered (the job or a 404), false when away. */
  reachable(): Promise<boolean>;
  /** Follow the job again (its stream replays from the first event). */
  resume(): Promise<void>;
  /** The server did not come back within MAX_TRIES. */
  giveUp(): void;
  sleep?: (ms: number) => Promise<void>;
}

const wait = (ms: number) => new Promise<void>((ok) => window.setTimeout(ok, ms));

export async function retryStream(h: RetryHooks): Promise<void> {
  const sleep = h.sleep ?? wait;
  for (let attempt = 1; attempt <= MAX_TRIES; attempt++) {
    for (let left = RETRY_S[Math.min(attempt - 1, RETRY_S.length - 1)]; left > 0; left--) {
      if (!h.current()) return;
      h.show({ attempt, nextInS: left });
      await sleep(1000);
    }
    if (!h.current()) return;
    h.show({ attempt, nextInS: 0 });
    if (await h.reachable()) {
      if (!h.current()) return;
      h.show(null);
      await h.resume();
      return;
    }
  }
  h.show(null);
  if (h.current()) h.giveUp();
}
