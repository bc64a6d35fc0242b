import { describeInstruction, type SegmentProgress } from "../api/agent";
import type { PlanSegment } from "../api/types";
import { rerunSegment } from "../directing/actions";
import { FPS } from "../store";

function peopleCount(persons: PlanSegment["persons"]): number {
  return Array.isArray(persons) ? persons.length : Number(persons) || 0;
}

/** Part edits of a planned segment ({part: text}), as the planner wrote them. */
function partEdits(seg: PlanSegment): [string, string][] {
  const edits = (seg as { edits?: Record<string, unknown> }).edits ?? {};
  return Object.entries(edits).filter((e): e is [string, string] => typeof e[1] === "string" && e[1].trim() !== "");
}

interface Props {
  index: number;
  seg: PlanSegment;
  progress?: SegmentProgress;
  canRerun: boolean;
  canInbetween: boolean;
}

/** One plan segment in the agent timeline: prompt, part edits, status, review rounds, corrections. */
export function SegmentCard({ index, seg, progress, canRerun, canInbetween }: Props) {
  const n = peopleCount(seg.persons);
  const base = (seg as { base?: string }).base;
  return (
    <li className="segment" data-testid={`segment-${index}`}>
      <div className="segment__head">
        <span className="segment__prompt">{base || seg.prompt}</span>
        {progress && (
          <span className={`badge badge--${progress.status}`} data-testid={`segment-status-${index}`}>
            {progress.status}
            {progress.generator ? ` · ${progress.generator}` : ""}
          </span>
        )}
      </div>
      <span className="muted small">
        {(seg.start / FPS).toFixed(1)}–{(seg.end / FPS).toFixed(1)} s · {n === 1 ? "1 person" : `${n} people`}
      </span>
      {partEdits(seg).map(([part, text]) => (
        <span key={part} className="small segment__edit">
          + {part.replace("_", " ")}: {text}
        </span>
      ))}
      {progress?.reviews.map((r) => (
        <div key={r.round} className="review" data-testid="review">
          <div className="review__head small">
            <span>round {r.round}</span>
            <span className={`badge badge--${r.verdict}`}>{r.verdict}</span>
            <span className="muted">score {Number.isFinite(r.score) ? r.score.toFixed(2) : "–"}</span>
          </div>
          {Object.entries(r.captions).map(([part, text]) => (
            <p key={part} className="small review__caption">
              <span className="muted">{part}:</span> {text}
            </p>
          ))}
          {r.instructions.map((ins, k) => (
            <p key={k} className="small review__instruction" title={ins.reason}>
              → {describeInstruction(ins)}
            </p>
          ))}
          {progress.corrections
            .filter((c) => c.round === r.round)
            .map((c, k) => (
              <p key={k} className="small" data-testid="correction">
                {c.accepted ? "✓ accepted" : "✗ rejected"} {describeInstruction(c.instruction)} ·{" "}
                {c.scoreBefore.toFixed(2)} → {c.scoreAfter === null ? "—" : c.scoreAfter.toFixed(2)}
              </p>
            ))}
        </div>
      ))}
      <div className="button-row segment__actions">
        <button className="small-button" data-testid={`rerun-${index}`} disabled={!canRerun} onClick={() => void rerunSegment(index, "job")}>
          Re-run (new seed)
        </button>
        <button
          className="small-button"
          data-testid={`inbetween-${index}`}
          disabled={!canInbetween}
          title="Re-generate this segment's frames in place (one-person motions)"
          onClick={() => void rerunSegment(index, "inbetween")}
        >
          Redo in place
        </button>
      </div>
    </li>
  );
}
