import { describeInstruction, describeVersionEdit, instructionOutcomes, partWords, plainReason, roundBadge, segmentVerdict, type SegmentProgress } from "../api/agent";
import "./agent.css";
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
  /** The job is over (or the motion is stored): no more review rounds will come. */
  finished?: boolean;
}

/** One plan segment in the agent timeline: prompt, part edits, status, review rounds, corrections. */
export function SegmentCard({ index, seg, progress, canRerun, canInbetween, finished = false }: Props) {
  const n = peopleCount(seg.persons);
  const base = (seg as { base?: string }).base;
  const shown = (seg as { coverage?: { shown?: string } }).coverage?.shown;
  const verdict = progress ? segmentVerdict(progress, finished, shown) : null;
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
      {verdict && (
        <p className={`small verdict verdict--${verdict.kind}`} data-testid={`segment-verdict-${index}`}>
          {verdict.text}
        </p>
      )}
      {progress?.edit && (
        <p className="small muted review__version" data-testid={`version-review-${index}`}>
          This version's own review, after its edit: {describeVersionEdit(progress.edit)}
        </p>
      )}
      {progress?.reviews.map((r) => (
        <div key={r.round} className="review" data-testid="review">
          <div className="review__head small">
            <span>{r.round === 0 ? "review" : `review after round ${r.round}`}</span>
            <span className={`badge badge--${roundBadge(r.verdict).kind}`}>{roundBadge(r.verdict).text}</span>
            <span className="muted" title="How well the motion matches the text (−1 … 1)">
              score {Number.isFinite(r.score) ? r.score.toFixed(2) : "–"}
            </span>
          </div>
          {Object.entries(r.captions).map(([part, text]) => (
            <p key={part} className="small review__caption">
              <span className="muted">{partWords(part)}:</span> {text}
            </p>
          ))}
          {instructionOutcomes(progress, r, finished || progress.status === "done").map(({ instruction, outcome }, k) => (
            <div key={k} className="small review__instruction" data-testid="instruction">
              <p>
                → {describeInstruction(instruction)}
                {instruction.reason && <span className="muted"> · why: {plainReason(instruction.reason)}</span>}
              </p>
              <p className={`outcome outcome--${outcome.kind}`} data-testid="correction" data-outcome={outcome.kind}>
                {outcome.kind === "accepted" ? "✓ " : outcome.kind === "rejected" || outcome.kind === "not-applied" ? "✗ " : "· "}
                {outcome.text}
              </p>
            </div>
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
