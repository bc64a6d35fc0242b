// Types of the HTTP/WebSocket contract (see the studio issue #3 and backend/interplay/api).
// Joints are always [x, y, z] in metres, Y up, 20 fps.

export type Vec3 = [number, number, number];
/** One person's frames: T × 22 × [x, y, z]. */
export type PersonFrames = Vec3[][];

/** A path on the ground for one person: drawn points [x, z] (metres) or a preset shape. */
export type Trajectory =
  | { person: 0 | 1; points: [number, number][] }
  | { person: 0 | 1; shape: { shape: string; size_m?: number; clockwise?: boolean; [key: string]: unknown } };

export interface JobRequest {
  prompt: string;
  persons: 1 | 2;
  seconds: number;
  seed?: number;
  trajectory?: Trajectory;
}

/** A react job: a reactor (person 1, ARFlow, frame by frame) for a stored motion's person 0,
 * with an optional intent ("shake hands"); stored as a new two-person version. */
export interface ReactRequest {
  mode: "react";
  actor_motion_id: string;
  prompt?: string;
  seed?: number;
}

/** Body parts the edit endpoint takes (aliases of CoMA's four parts, or the whole body). */
export type EditPart = "left_arm" | "right_arm" | "left_leg" | "right_leg" | "head" | "whole_body";

export interface EditRequest {
  part?: EditPart;
  prompt?: string;
  frames?: [number, number];
  seed?: number;
  trajectory?: Trajectory;
}

/** What made a version: the edit applied to its parent (null for a generated motion). */
export interface EditInfo {
  part?: string | null;
  prompt?: string | null;
  frames?: [number, number] | null;
  trajectory?: Trajectory | null;
  /** "react" for a reactor added to the parent's person; "rerun" for a segment generated
   * again in place (with `segment` and `seed`). */
  mode?: string | null;
  segment?: number | null;
  seed?: number | null;
}

/** One entry of "My motions" (GET /api/motions?client=…), newest first. */
export interface MotionListItem {
  id: string;
  prompt: string;
  persons: number;
  seconds: number;
  frames: number;
  created_at: string | null;
  parent_id: string | null;
  edit: EditInfo | null;
  /** The first frame per person: 22 × [x, y, z]. */
  first_frame: Vec3[][];
}

/** GET /api/motions?client=…: one page of My motions. */
export interface MotionPage {
  motions: MotionListItem[];
  /** The `after` of the next page; null on the last. */
  next: string | null;
  /** How many motions the client made in all. */
  total: number;
}

/** One of this browser's generations that made no motion (yet): GET /api/jobs?client=…. */
export interface ClientJob {
  job_id: string;
  motion_id: string;
  status: "queued" | "running" | "failed" | "cancelled";
  reason: string | null;
  attempts: number;
  mode: string;
  prompt: string | null;
  persons: number;
  seconds: number;
  created_at: string | null;
  stream: string;
  /** The body to POST /api/jobs again (Retry). */
  request: Record<string, unknown>;
}

/** GET /api/jobs/{id}. */
export interface JobStatus {
  job_id: string;
  motion_id: string;
  status: "queued" | "running" | "done" | "failed" | "cancelled";
  events: number;
  stream: string;
  reason?: string | null;
}


export interface Version {
  id: string;
  parent_id: string | null;
  created_at?: string;
  prompt?: string;
  edit?: EditInfo | null;
}

/** A reviewer's instruction (issue #7 contract). */
export interface Instruction {
  kind: "edit_part" | "inbetween" | "regenerate" | string;
  part?: string;
  prompt?: string;
  frames?: [number, number];
  reason?: string;
}

export interface JobCreated {
  job_id: string;
  motion_id: string;
  stream: string;
}

/** A planned segment; start/end are frame indices (20 fps), persons the people it moves
 * (a count or a list of person indices). */
export interface PlanSegment {
  prompt: string;
  start: number;
  end: number;
  persons: number | number[];
}

export interface Plan {
  segments: PlanSegment[];
  planner?: string;
  generator?: string;
  rewritten?: string;
  [key: string]: unknown;
}

/** Clip metrics; non-finite values arrive as null. */
export type Metrics = Record<string, number | null>;

/** Per-frame highlights: contacts are [person, joint], penetration is [person, part]. */
export interface Highlights {
  contacts: [number, number][][];
  penetration: [number, string][][];
  min_distance: number[] | null;
}

export interface Motion {
  id: string;
  prompt: string;
  persons: number;
  seconds: number;
  seed: number | null;
  fps: number;
  skeleton: string;
  people: { joints: PersonFrames }[];
  plan: Plan | null;
  metrics: Metrics | null;
  highlights: Highlights | null;
  created_at: string;
  parent_id?: string | null;
  edit?: EditInfo | null;
  /** The reviewer's rounds per segment ({segments: [{segment, reviews, corrections}]}). */
  review?: unknown;
}

export interface Skeleton {
  joints: string[];
  parents: number[];
  parts: Record<string, number[]>;
  joint_part: string[];
  colours: Record<string, string>;
}

/** One job-stream event; mirrors the pydantic models in backend/interplay/api/events.py
 * (`EVENTS`), checked field by field by tests/api/test_events.py. Optional (`?`) exactly
 * where the server may leave a field out (its `OMIT_NONE`); `| null` where it may send null. */
export type StreamEvent =
  | { type: "plan"; plan: Plan }
  | { type: "segment"; index: number; status: "generating" | "done"; generator: string }
  | { type: "frames"; start: number; total: number; people: PersonFrames[] }
  /** Frames already streamed, changed (a correction, the pair pass, a path, …): they take the
   * old ones' place. `cause`: correction | pair_pass | interaction | trajectory | sync. */
  | { type: "replace"; start: number; people: PersonFrames[]; cause: string; segment: number | null }
  | {
      type: "highlights";
      start: number;
      contacts: [number, number][][];
      penetration: [number, string][][];
      min_distance: (number | null)[] | null;
    }
  | {
      type: "review";
      segment: number;
      round: number;
      /** Part → caption text (person 0). */
      captions: Record<string, string>;
      summary: string;
      score: number;
      /** "evaluator" | "caption_agreement". */
      score_kind: string;
      /** Planned part → whether its caption confirms the edit. */
      confirmed: Record<string, boolean>;
      checks: Record<string, unknown>;
      instructions: Instruction[];
      verdict: "ok" | "correct" | "failed" | "not_covered" | "unconfirmed" | string;
    }
  | {
      type: "correction";
      segment: number;
      round: number;
      instruction: Instruction;
      accepted: boolean;
      score_before: number;
      /** null when the instruction could not be applied. */
      score_after: number | null;
      reason?: string;
    }
  | { type: "metrics"; metrics: Metrics }
  /** The motion is stored; the digests are the stored frames' (api/digest.ts). */
  | { type: "done"; motion_id: string; frames: number; digest?: string; frame_digests?: string[] }
  /** The job's process stopped and the job runs again from its start (attempt `attempt`). */
  | { type: "restart"; attempt: number; reason: string }
  | { type: "error"; message: string; stage?: string; cancelled?: boolean };

export type ExportFormat = "bvh" | "glb" | "json";
