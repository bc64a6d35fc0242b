// Typed REST client for the studio API. Every non-2xx answer becomes an ApiError
// carrying the server's readable `detail` message.
import type { ClientJob, EditRequest, ExportFormat, JobCreated, JobRequest, JobStatus, Motion, MotionListItem, MotionPage, ReactRequest, Skeleton, Version } from "./types";
import { CLIENT_HEADER, clientId } from "./clientId";

export class ApiError extends Error {
  constructor(
    readonly status: number,
    message: string,
  ) {
    super(message);
    this.name = "ApiError";
  }
}

/** The readable message of an error body: FastAPI's `detail` is a string, or a list of
 * validation errors ({loc, msg}) for 422s. */
export function errorMessage(body: unknown, status: number): string {
  const detail = (body as { detail?: unknown } | null)?.detail;
  if (typeof detail === "string" && detail) return detail;
  if (Array.isArray(detail) && detail.length) {
    return detail
      .map((d: { loc?: unknown[]; msg?: string }) => {
        const field = Array.isArray(d.loc) ? d.loc.filter((x) => x !== "body").join(".") : "";
        return field ? `${field}: ${d.msg ?? "invalid"}` : (d.msg ?? "invalid request");
      })
      .join("; ");
  }
  return `request failed (HTTP ${status})`;
}

async function request<T>(path: string, init?: RequestInit): Promise<T> {
  let res: Response;
  try {
    res = await fetch(path, init);
  } catch {
    throw new ApiError(0, "cannot reach the Interplay server");
  }
  const text = await res.text();
  let body: unknown = null;
  try {
    body = text ? JSON.parse(text) : null;
  } catch {
    body = null;
  }
  if (!res.ok) throw new ApiError(res.status, errorMessage(body, res.status));
  return body as T;
}

/** Headers of a request that makes a motion: JSON, and this browser's id (its "My motions"). */
function making(): Record<string, string> {
  return { "Content-Type": "application/json", [CLIENT_HEADER]: clientId() };
}

export function createJob(req: JobRequest | ReactRequest): Promise<JobCreated> {
  return request<JobCreated>("/api/jobs", {
    method: "POST",
    headers: making(),
    body: JSON.stringify(req),
  });
}

/** A job's state (to reattach to it after a reload); 404 once it is unknown or expired. */
export function getJob(jobId: string): Promise<JobStatus> {
  return request<JobStatus>(`/api/jobs/${encodeURIComponent(jobId)}`);
}

/** The motions this browser made, newest first (at most `limit`, 1–50). */
/** This browser's generations that made no motion yet (queued, running, failed, cancelled). */
export async function listJobs(limit = 10): Promise<ClientJob[]> {
  const q = new URLSearchParams({ client: clientId(), limit: String(limit) });
  return (await request<{ jobs: ClientJob[] }>(`/api/jobs?${q}`)).jobs;
}

export async function listMotions(limit = 20): Promise<MotionListItem[]> {
  return (await listMotionPage(limit)).motions;
}

/** One page of the motions this browser made, newest first: `limit` (1–50) of them after the
 * motion `after` (the previous page's `next`); `next` is null on the last page, `total` counts
 * them all. */
export function listMotionPage(limit = 20, after: string | null = null): Promise<MotionPage> {
  const q = new URLSearchParams({ client: clientId(), limit: String(limit) });
  if (after) q.set("after", after);
  return request<MotionPage>(`/api/motions?${q}`);
}

/** Generate plan segment `index` of a stored motion again (a new seed), in place: the new
 * version (201), the other segments' frames unchanged. */
export function rerunSegment(id: string, index: number, seed?: number): Promise<Motion> {
  return request<Motion>(`/api/motions/${encodeURIComponent(id)}/segments/${index}/rerun`, {
    method: "POST",
    headers: making(),
    body: JSON.stringify(seed === undefined ? {} : { seed }),
  });
}

export function getMotion(id: string): Promise<Motion> {
  return request<Motion>(`/api/motions/${encodeURIComponent(id)}`);
}

/** Apply an edit (part, frames, trajectory) to a stored motion: the new version (201). */
export function editMotion(id: string, req: EditRequest): Promise<Motion> {
  return request<Motion>(`/api/motions/${encodeURIComponent(id)}/edit`, {
    method: "POST",
    headers: making(),
    body: JSON.stringify(req),
  });
}

/** The versions from the root to this motion. */
export async function getHistory(id: string): Promise<Version[]> {
  const body = await request<{ versions: Version[] }>(`/api/motions/${encodeURIComponent(id)}/history`);
  return body.versions;
}

/** Cancel a running job (its stream then ends with a cancelled error). */
export async function cancelJob(jobId: string): Promise<void> {
  await request<unknown>(`/api/jobs/${encodeURIComponent(jobId)}`, { method: "DELETE" });
}

export function getSkeleton(): Promise<Skeleton> {
  return request<Skeleton>("/api/skeleton");
}

export function exportUrl(id: string, format: ExportFormat, person?: number): string {
  const q = new URLSearchParams({ format });
  if (format === "bvh" && person !== undefined) q.set("person", String(person));
  return `/api/motions/${encodeURIComponent(id)}/export?${q}`;
}

export function shareUrl(id: string, origin: string = window.location.origin): string {
  return `${origin}/m/${encodeURIComponent(id)}`;
}

/** The motion id in a `/m/{id}` path, or null. */
export function motionIdFromPath(pathname: string): string | null {
  const m = /^\/m\/([A-Za-z0-9_-]+)\/?$/.exec(pathname);
  return m ? m[1] : null;
}
