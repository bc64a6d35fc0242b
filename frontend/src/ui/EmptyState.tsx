import { useStudio } from "../store";

/** What to do on an empty stage (no motion yet, nothing generating), and after a cancelled
 * generation (the stage is cleared: the job stored nothing). */
export function EmptyState() {
  const cancelled = useStudio((s) => s.stream.phase === "error" && s.stream.cancelled);
  const show = useStudio((s) => (s.stream.phase === "idle" || cancelled) && !s.motionId && !s.error);
  if (!show) return null;
  return (
    <div className="empty-state" data-testid="empty-state" role="status">
      {cancelled ? (
        <p data-testid="cancelled-notice">
          <strong>Generation cancelled.</strong> Nothing was saved; change the prompt or press Generate again.
        </p>
      ) : (
        <p>
          <strong>No motion yet.</strong> Describe one above and press Generate.
        </p>
      )}
      <p className="muted small">
        Draw a path on the floor first to have the person follow it; after generating, click a body part to edit it.
      </p>
    </div>
  );
}
