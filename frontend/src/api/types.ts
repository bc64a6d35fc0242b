// Types of the HTTP/WebSocket contract (see the studio issue #3 and backend/interplay/api).
// Joints are always [x, y, z] in metres, Y up, 20 fps.

export type Vec3 = [number, number, number];
/** One person's frames: T × 22 × [x, y, z]. */
export type PersonFrames = Vec3[][];

export interface JobRequest {
  prompt: string;
  persons: 1 | 2;
  seconds: number;
  seed?: number;
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
}

export interface Skeleton {
  joints: string[];
  parents: number[];
  parts: Record<string, number[]>;
  joint_part: string[];
  colours: Record<string, string>;
}

export type StreamEvent =
  | { type: "plan"; plan: Plan }
  | { type: "frames"; start: number; total: number; people: PersonFrames[] }
  | {
      type: "highlights";
      start: number;
      contacts: [number, number][][];
      penetration: [number, string][][];
      min_distance: number[] | null;
    }
  | { type: "metrics"; metrics: Metrics }
  | { type: "done"; motion_id: string; frames: number }
  | { type: "error"; message: string };

export type ExportFormat = "bvh" | "json";
