import { useShallow } from "zustand/react/shallow";
import { useStudio } from "../store";
import type { EditInfo } from "../api/types";
import { describeReaction } from "../directing/react";
import { SegmentCard } from "./SegmentCard";
import { personName } from "./format";

/** "left_arm: wave · frames 10–51" or "path (Person 1)". */
export function describeEdit(e: EditInfo): string {
  if (e.mode === "react") return describeReaction(e.prompt);
  if (e.mode === "rerun") return `segment ${(e.segment ?? 0) + 1} generated again with a new seed${e.prompt ? ` (“${e.prompt}”)` : ""}`;
  const parts = [
    e.prompt ? `${e.part ?? "whole_body"}: ${e.prompt}` : null,
    e.frames ? `frames ${e.frames[0]}–${e.frames[1]}` : null,
    e.trajectory ? `path (${personName(e.trajectory.person)})` : null,
  ].filter(Boolean);
  return parts.join(" · ") || "an edit";
}

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
      edit: s.edit,
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
        // a version with no segments of its own (a reactor pair) says what it is below instead
        !s.edit && <p className="muted small">The plan and each review round appear here while a motion generates.</p>
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
              finished={s.phase === "done" || s.phase === "error"}
            />
          ))}
        </ol>
      )}
      {s.edit && (
        <p className="small plan__meta" data-testid="version-edit">
          This version: {describeEdit(s.edit)}
        </p>
      )}
      {trajectory && (
        <p className="small plan__meta" data-testid="plan-trajectory">
          path: {trajectory.shape ?? "drawn"}
          {typeof trajectory.person === "number" ? ` · ${personName(trajectory.person)}` : ""}
        </p>
      )}
      {plan && (plan.planner || plan.generator) && (
        <p className="muted small plan__meta" data-testid="plan-meta">
          {[
            plan.planner && `planner: ${plan.planner}`,
            plan.generator && `generator: ${plan.generator}`,
            typeof plan.seed === "number" && `seed ${plan.seed}`,
          ]
            .filter(Boolean)
            .join(" · ")}
        </p>
      )}
    </section>
  );
}
