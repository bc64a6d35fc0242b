// One job per intent: the key of a generation request (what the server would make the same
// from), so the studio can tell "the same request again" (a double click, Enter twice) from a
// changed one, and the job id of the running generation kept in the URL across a reload.
import type { JobRequest } from "./types";

/** A stable key of a request: the prompt as the server reads it (trimmed, spaces collapsed),
 * people, seconds, the seed if one was asked for, and the path. */
export function intentKey(req: JobRequest): string {
  const prompt = req.prompt.trim().replace(/\s+/g, " ");
  return JSON.stringify([prompt, req.persons, req.seconds, req.seed ?? null, req.trajectory ?? null]);
}

export interface ResumeTarget {
  job: string;
  /** The motion the job will store (a fallback when the job itself has expired). */
  motion: string | null;
}

const ID = /^[A-Za-z0-9_-]{1,64}$/;

/** `?job=…&motion=…` of the page URL, or null. */
export function resumeFromSearch(search: string): ResumeTarget | null {
  const q = new URLSearchParams(search);
  const job = q.get("job");
  if (!job || !ID.test(job)) return null;
  const motion = q.get("motion");
  return { job, motion: motion && ID.test(motion) ? motion : null };
}

/** The URL of a page following job `job` (which will store `motion`). */
export function resumeUrl(job: string, motion: string | null): string {
  const q = new URLSearchParams({ job });
  if (motion) q.set("motion", motion);
  return `/?${q}`;
}

const REQUEST_KEY = "interplay-job-request";

/** Remember the request of job `job` (the last one only), so a reload can show it at once. */
export function rememberRequest(job: string, req: JobRequest, storage: Pick<Storage, "setItem"> | null = local()): void {
  try {
    storage?.setItem(REQUEST_KEY, JSON.stringify({ job, req }));
  } catch {
    /* not kept: the form fills in from the job's plan instead */
  }
}

/** The request remembered for job `job`, or null. */
export function recalledRequest(job: string, storage: Pick<Storage, "getItem"> | null = local()): JobRequest | null {
  try {
    const v = JSON.parse(storage?.getItem(REQUEST_KEY) ?? "null") as { job?: string; req?: JobRequest } | null;
    const req = v?.job === job ? v.req : null;
    return req && typeof req.prompt === "string" && (req.persons === 1 || req.persons === 2) && typeof req.seconds === "number" ? req : null;
  } catch {
    return null;
  }
}

function local(): Storage | null {
  try {
    return typeof localStorage === "undefined" ? null : localStorage;
  } catch {
    return null;
  }
}
