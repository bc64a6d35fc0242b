import { useShallow } from "zustand/react/shallow";
import { useStudio } from "../store";
import { SegmentCard } from "./SegmentCard";

/** The agent timeline: what the planner decided (segments, part edits, trajectory), then each
 * segment's generation, review rounds and corrections as they stream; re-run a segment. */
export function PlanPanel() {
  const s = useStudio(
    useShallow((s) => ({
      plan: s.stream.plan,
      agent: s.stream.agent,
      phase: s.stream.phase,
      persons: s.motionPersons,
      editing: s.editing,
      motionId: s.motionId,
    })),
  );
  const { plan } = s;
  const segments = plan?.segments ?? [];
  const busy = s.phase === "connecting" || s.phase === "generating" || s.editing;
  const trajectory = plan?.trajectory as { shape?: string; person?: number } | undefined;
  return (
    <section className="panel" aria-labelledby="plan-title" data-testid="plan">
      <h2 id="plan-title">Agent timeline</h2>
      {!segments.length ? (
        <p className="muted small">The plan and each review round appear here while a motion generates.</p>
      ) : (
        <ol className="plan__segments">
          {segments.map((seg, i) => (
            <SegmentCard
              key={i}
              index={i}
              seg={seg}
              progress={s.agent[i]}
              canRerun={!busy}
              canInbetween={!busy && s.phase === "done" && s.persons === 1 && Boolean(s.motionId)}
            />
          ))}
        </ol>
      )}
      {trajectory && (
        <p className="small plan__meta" data-testid="plan-trajectory">
          path: {trajectory.shape ?? "drawn"}
          {typeof trajectory.person === "number" ? ` · person ${trajectory.person === 0 ? "A" : "B"}` : ""}
        </p>
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
