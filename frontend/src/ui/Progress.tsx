import { useEffect, useRef, useState } from "react";
import { describeProgress } from "../api/progress";
import { cancel } from "../studio";
import { useStudio } from "../store";

/** Seconds since `stage` last changed, ticking once a second while `on`. */
function useStageSeconds(stage: string, on: boolean): number {
  const since = useRef({ stage, at: Date.now() });
  const [, tick] = useState(0);
  if (since.current.stage !== stage) since.current = { stage, at: Date.now() };
  useEffect(() => {
    if (!on) return;
    const t = window.setInterval(() => tick((n) => n + 1), 1000);
    return () => window.clearInterval(t);
  }, [on]);
  return Math.floor((Date.now() - since.current.at) / 1000);
}

/** Generation progress: what the job is doing now (planning, generating segment 2 of 3,
 * reviewing it, correcting, the path, storing) with the share of the whole job done and
 * Cancel; or the edit being applied. */
export function Progress() {
  const stream = useStudio((s) => s.stream);
  const editing = useStudio((s) => s.editing);
  const editLabel = useStudio((s) => s.editLabel);
  const active = stream.phase === "connecting" || stream.phase === "generating";
  const view = describeProgress(stream, Boolean(stream.path));
  const seconds = useStageSeconds(editing ? `edit:${editLabel}` : view.stage, editing || active);
  if (editing) {
    return (
      <div className="progress" data-testid="progress" role="status" aria-live="polite">
        <div className="progress__label">
          <span data-testid="progress-label">{editLabel ?? "Applying the edit…"}</span>
          {seconds >= 2 && <span className="muted small">{seconds} s</span>}
        </div>
        <div className="progress__track progress__track--busy" role="progressbar">
          <div className="progress__bar" />
        </div>
      </div>
    );
  }
  if (!active) return null;
  return (
    <div className="progress" data-testid="progress" data-stage={view.stage} role="status" aria-live="polite">
      <div className="progress__label">
        <span data-testid="progress-label">
          {view.label}
          {view.busy && seconds >= 2 ? <span className="muted"> · {seconds} s</span> : null}
        </span>
        <button className="link" data-testid="cancel" onClick={() => void cancel()}>
          Cancel
        </button>
      </div>
      <div
        className={`progress__track${view.busy ? " progress__track--working" : ""}`}
        role="progressbar"
        aria-valuemin={0}
        aria-valuemax={100}
        aria-valuenow={Math.round(view.fraction * 100)}
        aria-valuetext={view.label}
      >
        <div className="progress__bar" style={{ width: `${(view.fraction * 100).toFixed(1)}%` }} />
      </div>
    </div>
  );
}
