// The agent's progress as the job streams it: per plan segment its generation status, then each
// review round (captions, score, the reviewer's instructions) and the corrections tried.
import type { Instruction, StreamEvent } from "./types";

export interface ReviewRound {
  round: number;
  captions: Record<string, string>;
  /** The reviewer's one-sentence caption of what the motion shows. */
  summary?: string;
  score: number;
  /** ok | correct (needs correction: corrections follow) | failed | not_covered. */
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
  /** Why it was rejected or could not be applied (absent when accepted). */
  reason?: string;
}

/** What made a version's own review of a segment (its stored review's `edit`): the part edit,
 * "Redo in place" (a whole-body edit of frames) or a segment re-run. */
export interface VersionEdit {
  kind: "edit" | "rerun" | string;
  part?: string | null;
  prompt?: string | null;
  frames?: [number, number] | null;
  segment?: number;
  seed?: number | null;
}

export interface SegmentProgress {
  status: string;
  generator?: string;
  reviews: ReviewRound[];
  corrections: Correction[];
  /** Set when these rounds are the review of the edit that made the version on screen. */
  edit?: VersionEdit;
}

/** "left arm: “raises the left arm” (frames 20–40)", "re-run with a new seed (seed 11)". */
export function describeVersionEdit(e: VersionEdit): string {
  if (e.kind === "rerun") return `re-run with a new seed${typeof e.seed === "number" ? ` (seed ${e.seed})` : ""}`;
  const frames = e.frames ? ` (frames ${e.frames[0]}–${e.frames[1]})` : "";
  if (!e.part || e.part === "whole_body") return `${e.prompt ? `whole body: “${e.prompt}”` : "redone in place"}${frames}`;
  return `${partWords(e.part)}: “${e.prompt ?? "edit"}”${frames}`;
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
        ...(ev.summary ? { summary: ev.summary } : {}),
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
        ...(ev.reason ? { reason: ev.reason } : {}),
      };
      return { ...state, [ev.segment]: { ...s, corrections: [...s.corrections, c] } };
    }
    default:
      return state;
  }
}

/** A part name in words: "left_arm" → "left arm", "left_upper" → "left arm" (the model's parts). */
export function partWords(part: string | undefined): string {
  if (!part) return "the body";
  const model: Record<string, string> = {
    left_upper: "left arm",
    right_upper: "right arm",
    left_lower: "left leg",
    right_lower: "right leg",
    whole_body: "whole body",
    body: "body",
  };
  return model[part] ?? part.replace(/_/g, " ");
}

const span = (f?: [number, number]) => (f ? `frames ${f[0]}–${f[1]}` : "");

/** A reviewer instruction in plain English, e.g. "left arm: “wave the hand” (frames 20–40)",
 * "redraw frames 51–60", "re-generate with a new seed". */
export function describeInstruction(i: Instruction): string {
  const frames = i.frames ? ` (${span(i.frames)})` : "";
  switch (i.kind) {
    case "edit_part":
      return `${partWords(i.part)}: “${i.prompt ?? "edit"}”${frames}`;
    case "inbetween":
      return i.frames ? `redraw ${span(i.frames)}` : "redraw the frames";
    case "regenerate":
      return "re-generate with a new seed";
    default:
      return `${i.kind.replace(/_/g, " ")}${i.prompt ? `: “${i.prompt}”` : ""}${frames}`;
  }
}

/** What a correction did, in the past tense: "left arm edited (“wave the hand”)",
 * "frames 51–60 redrawn (foot skating)", "re-generated with a new seed". */
export function describeFix(i: Instruction): string {
  switch (i.kind) {
    case "edit_part":
      return `${partWords(i.part)} edited (“${i.prompt ?? "edit"}”)`;
    case "inbetween": {
      const why = i.reason?.match(/^(.+?) in frames \d+/)?.[1];
      return `${i.frames ? span(i.frames) : "frames"} redrawn${why ? ` (${why})` : ""}`;
    }
    case "regenerate":
      return "re-generated with a new seed";
    default:
      return describeInstruction(i);
  }
}

/** Metric keys the reviewer names ("worse skating_ratio, foot_skating") in words. */
const METRIC_WORDS: Record<string, string> = {
  skating_ratio: "foot skating",
  foot_skating: "foot skating",
  floating: "floating",
  ground_penetration: "ground penetration",
  com_lean: "balance",
  bone_deviation: "bone lengths",
  intersection_volume: "body overlap",
  intersection_frequency: "body overlap frames",
  penetration: "body overlap",
};

/** The reviewer's reason (why it asked, or why a correction was rejected) in plain words. */
export function plainReason(reason: string | undefined): string {
  if (!reason) return "";
  let m = reason.match(/^the plan says '(.+)', the (?:body )?caption says '(.*)'$/s);
  if (m) return `asked for “${m[1]}”, the motion shows “${m[2] || "nothing"}”`;
  m = reason.match(/^the captions \('(.*)'\) hardly agree with '(.+)'$/s);
  if (m) return `the motion hardly matches “${m[2]}” (it shows “${m[1]}”)`;
  m = reason.match(/^'(.+)' needs a touch, but the hands never reach the other person$/s);
  if (m) return `hands never meet (“${m[1]}” needs a touch)`;
  m = reason.match(/^worse (.+)$/);
  if (m) {
    const words = [...new Set(m[1].split(/,\s*/).map((k) => METRIC_WORDS[k] ?? k.replace(/_/g, " ")))];
    const list = words.length > 1 ? `${words.slice(0, -1).join(", ")} and ${words[words.length - 1]}` : words[0];
    return `it made ${list} worse`;
  }
  return reason;
}

const score = (x: number | null, digits = 2) => (x === null || !Number.isFinite(x) ? "–" : x.toFixed(digits));

/** "score 0.24 → 0.31"; three places where two would read the same number twice. */
function scores(c: Correction): string {
  const digits = c.scoreAfter !== null && score(c.scoreBefore) === score(c.scoreAfter) && c.scoreBefore !== c.scoreAfter ? 3 : 2;
  return `score ${score(c.scoreBefore, digits)} → ${score(c.scoreAfter, digits)}`;
}

/** Whether an applied correction raised the score. */
export const improved = (c: Correction) => c.scoreAfter !== null && c.scoreAfter > c.scoreBefore + 1e-6;

/** Whether a correction counts as a fix: kept, and it raised the score or the review after it
 * passed (a check it was asked for passes now). */
export const fixed = (c: Correction, passedAfter: boolean) => c.accepted && (improved(c) || passedAfter);

export type OutcomeKind = "accepted" | "rejected" | "not-applied" | "not-tried" | "pending";

export interface Outcome {
  kind: OutcomeKind;
  text: string;
}

/** What became of one correction: "accepted (score 0.12 → 0.16)", "rejected: the score
 * dropped (0.14 → 0.11)", "could not apply: part edits need the SPAM model …". One the reviewer
 * kept without raising the score is "rejected: the score did not improve", unless the review
 * after it passed (`passedAfter`: then what it was asked for shows now, and it says so). */
export function correctionOutcome(c: Correction, passedAfter = false): Outcome {
  if (c.accepted && improved(c)) return { kind: "accepted", text: `accepted (${scores(c)})` };
  if (c.accepted && passedAfter) return { kind: "accepted", text: `accepted: the review passes now (${scores(c)})` };
  if (c.accepted) return { kind: "rejected", text: `rejected: the score did not improve (${scores(c)})` };
  if (c.scoreAfter === null) return { kind: "not-applied", text: `could not apply: ${plainReason(c.reason) || "no reason given"}` };
  return { kind: "rejected", text: `rejected: ${plainReason(c.reason) || "it did not help"} (${scores(c)})` };
}

/** Whether the review after correction round `round` (the round's own review) passed. */
function passedAfter(seg: SegmentProgress, round: number): boolean {
  return seg.reviews.find((r) => r.round === round)?.verdict === "ok";
}

const sameInstruction = (a: Instruction, b: Instruction) =>
  a.kind === b.kind && a.part === b.part && a.prompt === b.prompt && String(a.frames ?? "") === String(b.frames ?? "");

/** Each instruction of review round `r` with its outcome: the corrections of round r + 1 try
 * the instructions of review round r (the reviewer's loop); one not tried says why. */
export function instructionOutcomes(
  seg: SegmentProgress,
  r: ReviewRound,
  finished: boolean,
): { instruction: Instruction; outcome: Outcome }[] {
  const tried = seg.corrections.filter((c) => c.round === r.round + 1);
  const rejected = tried.some((c) => !c.accepted && c.scoreAfter !== null);
  const passed = passedAfter(seg, r.round + 1);
  const used = new Set<Correction>();
  return r.instructions.map((instruction) => {
    const c = tried.find((x) => !used.has(x) && sameInstruction(x.instruction, instruction));
    if (c) {
      used.add(c);
      return { instruction, outcome: correctionOutcome(c, passed) };
    }
    if (rejected) return { instruction, outcome: { kind: "not-tried", text: "not tried: an earlier correction in this round was rejected" } };
    if (!finished) return { instruction, outcome: { kind: "pending", text: "waiting…" } };
    return { instruction, outcome: { kind: "not-tried", text: "not tried: no correction rounds left" } };
  });
}

export type VerdictKind = "passed" | "corrected" | "failed" | "not-covered" | "unconfirmed" | "pending";

export interface Verdict {
  kind: VerdictKind;
  text: string;
}

/** A review round's badge: the reviewer's verdict in words ("correct" means needs correction). */
export function roundBadge(verdict: string): { kind: string; text: string } {
  if (verdict === "ok") return { kind: "ok", text: "passed" };
  if (verdict === "failed") return { kind: "failed", text: "failed" };
  if (verdict === "not_covered") return { kind: "not-covered", text: "not in the library" };
  if (verdict === "unconfirmed") return { kind: "unconfirmed", text: "unconfirmed" };
  return { kind: "correct", text: "needs correction" };
}

/** What a round says the motion shows: its summary, else the body's caption. */
function showing(r: ReviewRound): string {
  return (r.summary || r.captions.body || "").trim();
}

/** A segment's review outcome in words: "passed", "corrected: left arm edited (…)",
 * "failed: hands never meet (…) — it shows “…”" or "not in the library — showing the nearest:
 * …"; pending while it is still generated or reviewed. The reviewer's own verdict "correct"
 * means "needs correction", so it is never shown as is. A correction counts as a fix only if
 * it raised the score or the review after it passed (`fixed`).
 * `finished`: the job is over (a stored motion, or done / failed), so no more rounds come.
 * `shown`: what the plan says was shown for the segment (its `coverage.shown`), if anything. */
export function segmentVerdict(seg: SegmentProgress | undefined, finished: boolean, shown?: string): Verdict {
  const last = seg?.reviews[seg.reviews.length - 1];
  if (!seg || !last) {
    if (finished || seg?.status === "done") return { kind: "pending", text: "not reviewed" };
    return { kind: "pending", text: seg?.status === "generating" ? "generating…" : "waiting…" };
  }
  const fixes = seg.corrections.filter((c) => fixed(c, passedAfter(seg, c.round))).map((c) => describeFix(c.instruction));
  if (last.verdict === "ok") return fixes.length ? { kind: "corrected", text: `corrected: ${fixes.join("; ")}` } : { kind: "passed", text: "passed" };
  if (last.verdict === "not_covered") {
    const nearest = (shown ?? "").trim() || showing(last);
    return { kind: "not-covered", text: `not in the library — showing the nearest${nearest ? `: ${nearest}` : ""}` };
  }
  if (last.verdict === "unconfirmed") {
    // words the reviewer's calibration does not hold for: neither passed nor failed
    const seen = showing(last);
    const partly = fixes.length ? ` — after ${fixes.join("; ")}` : "";
    return { kind: "unconfirmed", text: `unconfirmed: the reviewer cannot judge these words${seen ? ` — it shows “${seen}”` : ""}${partly}` };
  }
  // still needs correction: the segment is not done while its correction rounds run
  if (last.verdict !== "failed" && !finished && seg.status !== "done") return { kind: "pending", text: "needs correction — correcting…" };
  const why = plainReason(last.instructions[0]?.reason) || describeInstruction(last.instructions[0] ?? { kind: "regenerate" });
  const more = last.instructions.length > 1 ? ` (+${last.instructions.length - 1} more)` : "";
  const partly = fixes.length ? ` — after ${fixes.join("; ")}` : "";
  const seen = showing(last);
  const shows = seen && !why.includes(seen) ? ` — it shows “${seen}”` : "";
  return { kind: "failed", text: `failed: ${why}${more}${partly}${shows}` };
}

interface StoredReview {
  segments?: { segment: number; reviews?: unknown[]; corrections?: unknown[]; edit?: VersionEdit }[];
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
    if (seg.edit) state = { ...state, [seg.segment]: { ...state[seg.segment], edit: seg.edit } };
  }
  return state;
}
