import { useEffect } from "react";
import { create } from "zustand";
import { listJobs } from "../api/client";
import type { ClientJob, JobRequest } from "../api/types";
import { useLibrary } from "../library";
import { generate, openMotion, react, resumeJob } from "../studio";
import { useStudio } from "../store";
import { ago } from "./thumbnail";
import "./agent.css";

/** This browser's generations that made no motion (yet): running ones to follow, failed and
 * cancelled ones to try again (issue 26.2). Refreshed with My motions' list and when a job ends. */
export const useJobs = create<{ jobs: ClientJob[] }>()(() => ({ jobs: [] }));

export async function refreshJobs(): Promise<void> {
  try {
    useJobs.setState({ jobs: await listJobs() });
  } catch {
    /* the list is a convenience: My motions says when the server cannot be reached */
  }
}

const WORDS: Record<ClientJob["status"], string> = { queued: "waiting", running: "running", failed: "failed", cancelled: "cancelled" };

/** Send the job's request again (a react job: open its actor, then add the reactor again). */
async function retry(job: ClientJob): Promise<void> {
  const body = job.request;
  if (body.mode === "react") {
    await openMotion(String(body.actor_motion_id));
    await react(typeof body.prompt === "string" ? body.prompt : "");
  } else {
    const req = body as unknown as JobRequest;
    useStudio.setState({ prompt: req.prompt, persons: req.persons, seconds: req.seconds, seed: req.seed ?? null });
    await generate(req);
  }
  void refreshJobs();
}

function follow(job: ClientJob): void {
  window.history.pushState(null, "", `/?job=${job.job_id}&motion=${job.motion_id}`);
  void resumeJob(job.job_id, job.motion_id);
}

export function MyJobs() {
  const jobs = useJobs((s) => s.jobs);
  const items = useLibrary((s) => s.items);
  const phase = useStudio((s) => s.stream.phase);
  const following = useStudio((s) => s.stream.jobId);
  useEffect(() => {
    void refreshJobs();
  }, [items, phase]);
  if (!jobs.length) return null;
  return (
    <ol className="library__jobs" data-testid="library-jobs">
      {jobs.map((j) => (
        <li key={j.job_id} className="library__job small" data-testid="library-job" data-job-id={j.job_id} data-status={j.status}>
          <span className="library__prompt">{j.mode === "react" ? `Person 2 reacts${j.prompt ? `: ${j.prompt}` : ""}` : j.prompt}</span>
          <span className={`muted job--${j.status}`}>
            {WORDS[j.status]}
            {j.attempts > 1 ? ` · attempt ${j.attempts}` : ""}
            {j.created_at ? ` · ${ago(j.created_at)}` : ""}
            {j.reason && j.status === "failed" ? ` — ${j.reason}` : ""}
          </span>
          {j.status === "queued" || j.status === "running" ? (
            j.job_id !== following && (
              <button className="small-button" data-testid="job-follow" onClick={() => follow(j)}>
                Follow
              </button>
            )
          ) : (
            <button className="small-button" data-testid="job-retry" onClick={() => void retry(j)}>
              Retry
            </button>
          )}
        </li>
      ))}
    </ol>
  );
}
