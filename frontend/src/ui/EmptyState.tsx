import { useStudio } from "../store";

/** What to do on an empty stage (no motion yet, nothing generating). */
export function EmptyState() {
  const show = useStudio((s) => s.stream.phase === "idle" && !s.motionId && !s.error);
  if (!show) return null;
  return (
    <div className="empty-state" data-testid="empty-state">
      <p>
        <strong>No motion yet.</strong> Describe one above and press Generate.
      </p>
      <p className="muted small">
        Draw a path on the floor first to have the person follow it; after generating, click a body part to edit it.
      </p>
    </div>
  );
}
