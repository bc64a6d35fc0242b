import type { PlanSegment } from "../api/types";
import { FPS, useStudio } from "../store";

function peopleCount(persons: PlanSegment["persons"]): number {
  return Array.isArray(persons) ? persons.length : Number(persons) || 0;
}

/** What the planner decided: the segments of the motion (frames shown as seconds). */
export function PlanPanel() {
  const plan = useStudio((s) => s.stream.plan);
  const segments = plan?.segments ?? [];
  return (
    <section className="panel" aria-labelledby="plan-title" data-testid="plan">
      <h2 id="plan-title">Plan</h2>
      {!segments.length ? (
        <p className="muted small">What the planner decided appears here.</p>
      ) : (
        <ol className="plan__segments">
          {segments.map((seg, i) => {
            const n = peopleCount(seg.persons);
            return (
              <li key={i}>
                <span>{seg.prompt}</span>
                <span className="muted small">
                  {(seg.start / FPS).toFixed(1)}–{(seg.end / FPS).toFixed(1)} s · {n === 1 ? "1 person" : `${n} people`}
                </span>
              </li>
            );
          })}
        </ol>
      )}
      {plan && (plan.planner || plan.generator) && (
        <p className="muted small plan__meta">
          {[plan.planner && `planner: ${plan.planner}`, plan.generator && `generator: ${plan.generator}`]
            .filter(Boolean)
            .join(" · ")}
        </p>
      )}
    </section>
  );
}
