// What a running generation is doing, in words, with a fraction that moves: derived only from
// the stream's events (plan → per segment: segment generating, frames, review rounds,
// corrections, segment done → the path → metrics → done). Between two events the stage is
// known from the last one: frames of a segment all in and no review yet means the reviewer is
// at work; a review asking for corrections means they are being applied; all segments done
// means the path (if any) and the metrics; metrics in means the motion is being stored.
import { describeInstruction } from "./agent";
import type { StreamState } from "./stream";

export interface ProgressView {
  /** A key of the stage (changes when the stage does; the label's counts may change within). */
  stage: string;
  label: string;
  /** 0…1, over the whole job. */
  fraction: number;
  /** No frames move in this stage (reviewing, storing…): the bar shows activity. */
  busy: boolean;
}

const GENERATE = 0.6; // share of a segment's progress that is its frames (the rest: review)
const FINISH = 0.08; // share of the whole job after the last segment (path, metrics, store)

function clamp(x: number): number {
  return Math.max(0, Math.min(1, Number.isFinite(x) ? x : 0));
}

export function describeProgress(s: StreamState, hasPath = false): ProgressView {
  const plan = s.plan;
  if (s.mode === "react") {
    if (s.total > 0)
      return { stage: "react", label: `Person 2 reacting · ${s.received} / ${s.total} frames`, fraction: clamp(s.received / s.total), busy: false };
    return { stage: "react-start", label: "Starting the reactor…", fraction: 0, busy: true };
  }
  if (s.reconnecting) {
    const { attempt, nextInS } = s.reconnecting;
    return { stage: "reconnecting", label: `The server is not answering — trying again${nextInS > 0 ? ` in ${nextInS} s` : "…"} (try ${attempt})`, fraction: 0, busy: true };
  }
  const segments = plan?.segments ?? [];
  if (!plan || !segments.length) {
    return { stage: "planning", label: "Planning the motion…", fraction: 0, busy: true };
  }
  const n = segments.length;
  const total = Math.max(1, segments[n - 1].end, s.total);
  let fraction = 0;
  let current = -1;
  for (let i = 0; i < n; i++) {
    const seg = segments[i];
    const p = s.agent[i];
    const w = (seg.end - seg.start) / total;
    if (p?.status === "done") fraction += w;
    else if (p?.status === "generating") {
      current = current < 0 ? i : current;
      const frames = clamp((s.received - seg.start) / Math.max(1, seg.end - seg.start));
      const steps = p.reviews.length + p.corrections.length;
      fraction += w * (GENERATE * frames + (1 - GENERATE) * clamp(steps / (steps + 2)));
    }
  }
  fraction *= 1 - FINISH;
  const of = `segment ${current + 1} of ${n}`;
  if (current >= 0) {
    const seg = segments[current];
    const p = s.agent[current]!;
    if (s.received < seg.end && !p.reviews.length) {
      return { stage: `generate-${current}`, label: `Generating ${of} · ${s.received} / ${total} frames`, fraction, busy: false };
    }
    const last = p.reviews[p.reviews.length - 1];
    if (!last) return { stage: `review-${current}-0`, label: `Reviewing ${of} · round 1`, fraction, busy: true };
    if (last.verdict !== "ok") {
      const round = last.round + 1;
      const tried = p.corrections.filter((c) => c.round === round).length;
      const todo = last.instructions.length;
      if (tried < todo) {
        const what = describeInstruction(last.instructions[tried]);
        const count = todo > 1 ? ` (${tried + 1} of ${todo})` : "";
        return { stage: `correct-${current}-${round}-${tried}`, label: `Correcting ${of} · round ${round}${count}: ${what}`, fraction, busy: true };
      }
      return { stage: `review-${current}-${round}`, label: `Reviewing ${of} · round ${round + 1}`, fraction, busy: true };
    }
    return { stage: `finish-${current}`, label: `Finishing ${of}`, fraction, busy: true };
  }
  const allDone = segments.every((_, i) => s.agent[i]?.status === "done");
  if (!allDone) {
    // between a segment's end and the next one's start (or before the first)
    const next = segments.findIndex((_, i) => s.agent[i]?.status !== "done");
    return { stage: `generate-${next}`, label: `Generating segment ${next + 1} of ${n} · ${s.received} / ${total} frames`, fraction: fraction, busy: false };
  }
  const path = hasPath || Boolean(plan.trajectory) || segments.some((seg) => (seg as { trajectory?: unknown }).trajectory);
  if (!s.metrics) {
    return path
      ? { stage: "path", label: "Applying the path…", fraction: 1 - FINISH, busy: true }
      : { stage: "metrics", label: "Measuring the motion…", fraction: 1 - FINISH / 2, busy: true };
  }
  return { stage: "store", label: "Storing the motion…", fraction: 1 - FINISH / 4, busy: true };
}
