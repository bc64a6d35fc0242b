// The agent's progress as the job streams it: per plan segment its generation status, then each
// review round (captions, score, the reviewer's instructions) and the corrections tried.
import type { Instruction, StreamEvent } from "./types";

export interface ReviewRound {
  round: number;
  captions: Record<string, string>;
  score: number;
  verdict: string;
  instructions: Instruction[];
}

export interface Correction {
  round: number;
  instruction: Instruction;
  accepted: boolean;
  scoreBefore: number;
  /** null when the instruction could not be applied. */
  scoreAfter: number | null;
}

export interface SegmentProgress {
  status: string;
  generator?: string;
  reviews: ReviewRound[];
  corrections: Correction[];
}

/** Segment index → progress (indices as the plan numbers them). */
export type AgentState = Record<number, SegmentProgress>;

export const initialAgent: AgentState = {};

function segment(state: AgentState, i: number): SegmentProgress {
  return state[i] ?? { status: "planned", reviews: [], corrections: [] };
}

/** Next agent state after one stream event (other event types leave it as it is). */
export function reduceAgent(state: AgentState, ev: StreamEvent): AgentState {
  switch (ev.type) {
    case "segment": {
      const s = segment(state, ev.index);
      return { ...state, [ev.index]: { ...s, status: ev.status, generator: ev.generator ?? s.generator } };
    }
    case "review": {
      const s = segment(state, ev.segment);
      const round: ReviewRound = {
        round: ev.round,
        captions: ev.captions ?? {},
        score: ev.score,
        verdict: ev.verdict,
        instructions: ev.instructions ?? [],
      };
      const reviews = [...s.reviews.filter((r) => r.round !== ev.round), round].sort((a, b) => a.round - b.round);
      return { ...state, [ev.segment]: { ...s, reviews } };
    }
    case "correction": {
      const s = segment(state, ev.segment);
      const c: Correction = {
        round: ev.round,
        instruction: ev.instruction,
        accepted: ev.accepted,
        scoreBefore: ev.score_before,
        scoreAfter: ev.score_after,
      };
      return { ...state, [ev.segment]: { ...s, corrections: [...s.corrections, c] } };
    }
    default:
      return state;
  }
}

/** A one-line description of a reviewer instruction, e.g. "edit left_arm: raise it (frames 20–40)". */
export function describeInstruction(i: Instruction): string {
  const head = i.kind === "edit_part" ? `edit ${i.part ?? "part"}` : i.kind;
  const what = i.prompt ? `: ${i.prompt}` : "";
  const span = i.frames ? ` (frames ${i.frames[0]}–${i.frames[1]})` : "";
  return `${head}${what}${span}`;
}

interface StoredReview {
  segments?: { segment: number; reviews?: unknown[]; corrections?: unknown[] }[];
}

/** The agent timeline of a stored motion (its `review`: the rounds per segment), replayed
 * through the same reducer as the live events. */
export function agentFromReview(review: unknown): AgentState {
  const segs = (review as StoredReview | null)?.segments;
  if (!Array.isArray(segs)) return initialAgent;
  let state = initialAgent;
  for (const seg of segs) {
    // A stored review does not say which generator ran the segment.
    state = reduceAgent(state, { type: "segment", index: seg.segment, status: "done" } as StreamEvent);
    for (const r of seg.reviews ?? []) state = reduceAgent(state, { type: "review", ...(r as object), segment: seg.segment } as StreamEvent);
    for (const c of seg.corrections ?? [])
      state = reduceAgent(state, { type: "correction", ...(c as object), segment: seg.segment } as StreamEvent);
  }
  return state;
}
