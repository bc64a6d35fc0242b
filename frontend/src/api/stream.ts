// The generation stream: a pure reducer over the contract's events (plan → frames/highlights
// … → metrics → done | error) and a thin WebSocket client that feeds it.
import { initialAgent, reduceAgent, type AgentState } from "./agent";
import type { Metrics, Plan, StreamEvent } from "./types";

export type StreamPhase = "idle" | "connecting" | "generating" | "done" | "error";
/** generate: a new motion from the prompt; react: a reactor streamed next to a stored actor. */
export type StreamMode = "generate" | "react";

export interface StreamState {
  phase: StreamPhase;
  plan: Plan | null;
  /** Frames received so far (end of the furthest frames chunk). */
  received: number;
  /** Frames expected in all (0 until the first frames event says). */
  total: number;
  metrics: Metrics | null;
  motionId: string | null;
  error: string | null;
  /** Segment statuses, review rounds and corrections (the agent timeline). */
  agent: AgentState;
  /** The job being streamed (to cancel it). */
  jobId?: string | null;
  cancelled?: boolean;
  mode?: StreamMode;
  /** react: the stored motion whose person 0 is the actor (the new version's parent). */
  actorId?: string | null;
  /** The job was sent with a drawn path (its progress then names the path stage). */
  path?: boolean;
  /** The stream dropped before the job ended (the server went away): the page is trying to
   * reach it again, `attempt` tries so far, the next in `nextInS` seconds. */
  reconnecting?: { attempt: number; nextInS: number } | null;
  /** The job's attempt after a `restart` (its process died and it runs again), else absent. */
  attempt?: number;
}

export const initialStream: StreamState = {
  phase: "idle",
  plan: null,
  received: 0,
  total: 0,
  metrics: null,
  motionId: null,
  error: null,
  agent: initialAgent,
  jobId: null,
  cancelled: false,
  mode: "generate",
  actorId: null,
};

export function startStream(
  motionId: string | null = null,
  jobId: string | null = null,
  mode: StreamMode = "generate",
  actorId: string | null = null,
): StreamState {
  return { ...initialStream, phase: "connecting", motionId, jobId, mode, actorId };
}

/** Next state after one event. Events after `done` or `error` are ignored; frames and
 * highlights data themselves go to the FrameBuffer, the reducer only counts. */
export function reduceStream(state: StreamState, event: StreamEvent): StreamState {
  if (state.phase === "done" || state.phase === "error") return state;
  switch (event.type) {
    case "plan":
      return { ...state, phase: "generating", plan: event.plan };
    case "frames": {
      const n = event.people[0]?.length ?? 0;
      return {
        ...state,
        phase: "generating",
        received: Math.max(state.received, event.start + n),
        total: Math.max(event.total, event.start + n),
      };
    }
    case "highlights":
    case "replace":
      return state;
    case "restart":
      // the job runs again from its start: its stream follows with a new plan, new frames
      return { ...startStream(state.motionId, state.jobId, state.mode, state.actorId), phase: "generating", path: state.path, attempt: event.attempt };
    case "metrics":
      return { ...state, metrics: event.metrics };
    case "done":
      return {
        ...state,
        phase: "done",
        motionId: event.motion_id,
        total: event.frames,
        received: Math.min(state.received, event.frames),
      };
    case "error": {
      // Cancelled: the job made nothing, so its plan and every badge go with it. Failed: the
      // plan stays (what was tried), but no segment still says it is generating.
      const cancelled = Boolean(event.cancelled);
      return {
        ...state,
        phase: "error",
        error: event.message || "generation failed",
        cancelled,
        plan: cancelled ? null : state.plan,
        agent: cancelled ? initialAgent : stopped(state.agent),
      };
    }
    case "segment":
    case "review":
    case "correction":
      return { ...state, phase: "generating", agent: reduceAgent(state.agent, event) };
    default:
      return state;
  }
}

/** The agent state with every segment still generating marked stopped. */
function stopped(agent: AgentState): AgentState {
  const out: AgentState = {};
  for (const [k, v] of Object.entries(agent)) out[Number(k)] = v.status === "generating" ? { ...v, status: "stopped" } : v;
  return out;
}

/** Parse one message; a malformed one becomes an error event rather than a throw. */
export function parseEvent(data: string): StreamEvent {
  try {
    const ev = JSON.parse(data) as StreamEvent;
    if (ev && typeof ev === "object" && typeof ev.type === "string") return ev;
  } catch {
    /* fall through */
  }
  return { type: "error", message: "the server sent a malformed stream message" };
}

export function streamSocketUrl(path: string, loc: Location = window.location): string {
  const scheme = loc.protocol === "https:" ? "wss:" : "ws:";
  return `${scheme}//${loc.host}${path}`;
}

export interface StreamHandle {
  close(): void;
}

/** Open the job's stream; every event goes to onEvent. If the socket drops before `done` or
 * `error`: `onLost()` when given (the caller reconnects), else a synthetic error event. */
export function openStream(path: string, onEvent: (ev: StreamEvent) => void, onLost?: () => void): StreamHandle {
  const ws = new WebSocket(streamSocketUrl(path));
  let finished = false;
  const emit = (ev: StreamEvent) => {
    if (finished) return;
    if (ev.type === "done" || ev.type === "error") finished = true;
    onEvent(ev);
  };
  ws.onmessage = (msg) => emit(parseEvent(String(msg.data)));
  const lost = (message: string) => {
    if (finished) return;
    if (onLost) {
      finished = true;
      onLost();
    } else emit({ type: "error", message });
  };
  ws.onerror = () => lost("the generation stream failed");
  ws.onclose = (e) => (e.code === 4404 ? emit({ type: "error", message: e.reason || "the job is not on the server" }) : lost("the stream closed before the motion was done"));
  return {
    close() {
      finished = true;
      ws.close();
    },
  };
}
