import { useStudio } from "../store";

/** What the planner decided: the segments of the motion. */
export function PlanPanel() {
  const plan = useStudio((s) => s.stream.plan);
  const prompt = useStudio((s) => s.motionPrompt);
  return (
    <section className="panel" aria-labelledby="plan-title" data-testid="plan">
      <h2 id="plan-title">Plan</h2>
      {prompt && <p className="plan__prompt">“{prompt}”</p>}
      {!plan?.segments?.length ? (
        <p className="muted small">The planner's segments appear here.</p>
      ) : (
        <ol className="plan__segments">
          {plan.segments.map((seg, i) => (
            <li key={i}>
              <span>{seg.prompt}</span>
              <span className="muted small">
                {Number(seg.start).toFixed(1)}–{Number(seg.end).toFixed(1)} s ·{" "}
                {seg.persons === 2 ? "2 people" : "1 person"}
              </span>
            </li>
          ))}
        </ol>
      )}
    </section>
  );
}
