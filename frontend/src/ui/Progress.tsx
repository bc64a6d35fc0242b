import { cancel } from "../studio";
import { useStudio } from "../store";

/** Generation progress: frames received / total while the stream runs (with Cancel), or the
 * edit being applied. */
export function Progress() {
  const { phase, received, total, mode } = useStudio((s) => s.stream);
  const editing = useStudio((s) => s.editing);
  if (editing) {
    return (
      <div className="progress" data-testid="progress" role="status" aria-live="polite">
        <div className="progress__label">Applying the edit…</div>
        <div className="progress__track progress__track--busy" role="progressbar">
          <div className="progress__bar" />
        </div>
      </div>
    );
  }
  if (phase !== "connecting" && phase !== "generating") return null;
  const fraction = total > 0 ? received / total : 0;
  const react = mode === "react";
  const label =
    total > 0
      ? `${react ? "B reacting" : "Generating"} · ${received} / ${total} frames`
      : react
        ? "Starting the reactor…"
        : "Planning…";
  return (
    <div className="progress" data-testid="progress" role="status" aria-live="polite">
      <div className="progress__label">
        <span>{label}</span>
        <button className="link" data-testid="cancel" onClick={() => void cancel()}>
          Cancel
        </button>
      </div>
      <div
        className="progress__track"
        role="progressbar"
        aria-valuemin={0}
        aria-valuemax={total || 1}
        aria-valuenow={received}
      >
        <div className="progress__bar" style={{ width: `${(fraction * 100).toFixed(1)}%` }} />
      </div>
    </div>
  );
}
