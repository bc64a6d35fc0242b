// `window.__interplay`: a tiny read-only view of the studio for the end-to-end tests.
import { FPS, frames, renderStats, sceneProbe, useStudio } from "./store";
import { useLibrary } from "./library";
import { shownPath, useFollowed } from "./directing/followed";
import { figureStats, useFigure } from "./figure";
import { viewStats } from "./scene/views";
import { glowStats } from "./scene/contactGlow";
import { MARK_STRIDE } from "./scene/overlaps";
import { copyCheck, type CopyCheck } from "./playback/verify";

export interface BvhSummary {
  bones: number;
  joints: string[];
  endSites: number;
  frames: number;
  duration: number;
}

export interface InterplayTestHook {
  readonly motionId: string | null;
  readonly phase: string;
  /** The job being streamed (null when none) and its kind: "generate" or "react". */
  readonly jobId: string | null;
  readonly streamMode: string;
  readonly persons: number;
  readonly frameCount: number;
  readonly framesReceived: number;
  readonly fps: number;
  readonly firstFrame: number[][][];
  readonly currentFrame: number;
  readonly renderCount: number;
  /** "full" or "light" (software WebGL: no MSAA, blob shadows). */
  readonly quality: string;
  /** The pixel ratio the scene is drawn at now (light quality: set by dynamic resolution). */
  readonly renderScale: number;
  /** The drawn / preset path ([x, z] points) and who follows it. */
  readonly path: { person: number; points: [number, number][] };
  readonly versions: { ids: string[]; index: number };
  readonly selected: { person: number; part: string } | null;
  readonly range: [number, number] | null;
  readonly playing: boolean;
  readonly agentReviews: number;
  /** The path drawn on the floor now: the pending one, or the one the motion followed (`followed`). */
  readonly shownPath: { person: number; points: [number, number][]; followed: boolean };
  /** Per person, the contact joints glowing green at the pose drawn (asked or new contacts). */
  readonly glowing: number[][];
  /** The motion ids listed in My motions, newest first. */
  readonly library: string[];
  /** Joints ([x, y, z] × 22) of person p at frame t of the buffer, or null. */
  frameJoints(person: number, frame: number): number[][] | null;
  /** The check of the page's frames against the stored motion at `done` (playback/verify.ts). */
  readonly copyCheck: CopyCheck;
  /** The figure chosen (mannequin / character), its status, what is drawn and how many
   * characters are made. */
  readonly figure: { figure: string; status: string; shown: string; characters: number };
  /** The camera: the preset view last applied (null before any), whether the user has moved
   * it since, its position and orbit target (world metres). */
  readonly view: { preset: string | null; moved: boolean; position: number[]; target: number[] };
  /** The penetration marks drawn at the pose shown: [x, y, z, radius, depth] (m) each, where
   * the two people's sphere bodies overlap (none for one person). */
  readonly penetrationMarks: number[][];
  /** Screen position (client px) of joint j of person p at the frame shown, or null. */
  project(person: number, joint: number): [number, number] | null;
  /** Screen position (client px) of a world point, or null before the viewport exists. */
  projectPoint(x: number, y: number, z: number): [number, number] | null;
  /** Ground point [x, z] under a client position, or null. */
  groundAt(x: number, y: number): [number, number] | null;
  /** Parse BVH text with three.js's BVHLoader (loaded on demand) and summarise its skeleton. */
  parseBvh(text: string): Promise<BvhSummary>;
}

async function parseBvh(text: string): Promise<BvhSummary> {
  const { BVHLoader } = await import("three/examples/jsm/loaders/BVHLoader.js");
  const { skeleton, clip } = new BVHLoader().parse(text);
  const joints = skeleton.bones.filter((b) => b.name !== "ENDSITE").map((b) => b.name);
  const track = clip.tracks[0];
  return {
    bones: skeleton.bones.length,
    joints,
    endSites: skeleton.bones.length - joints.length,
    frames: track ? track.times.length : 0,
    duration: clip.duration,
  };
}

export function installTestHook(target: Window = window): void {
  const hook: InterplayTestHook = {
    get motionId() {
      return useStudio.getState().motionId;
    },
    get phase() {
      return useStudio.getState().stream.phase;
    },
    get jobId() {
      return useStudio.getState().stream.jobId ?? null;
    },
    get streamMode() {
      return useStudio.getState().stream.mode ?? "generate";
    },
    get persons() {
      return frames.persons;
    },
    get frameCount() {
      return useStudio.getState().stream.total;
    },
    get framesReceived() {
      return frames.received;
    },
    get fps() {
      return FPS;
    },
    get firstFrame() {
      return frames.framePeople(0);
    },
    get currentFrame() {
      return useStudio.getState().frame;
    },
    get renderCount() {
      return renderStats.renders;
    },
    get quality() {
      return renderStats.quality;
    },
    get renderScale() {
      return renderStats.scale;
    },
    get path() {
      const p = useStudio.getState().path;
      return { person: p.person, points: p.points };
    },
    get versions() {
      return useStudio.getState().versions;
    },
    get selected() {
      return useStudio.getState().selected;
    },
    get range() {
      return useStudio.getState().range;
    },
    get playing() {
      return useStudio.getState().playing;
    },
    get agentReviews() {
      return Object.values(useStudio.getState().stream.agent).reduce((n, s) => n + s.reviews.length, 0);
    },
    get shownPath() {
      const s = useStudio.getState();
      const f = useFollowed.getState();
      return shownPath(s.path, f.path, f.show, s.motionId, s.versions.ids);
    },
    get glowing() {
      return glowStats.joints.map((j) => [...j]);
    },
    get library() {
      return useLibrary.getState().items.map((m) => m.id);
    },
    get copyCheck() {
      return { ...copyCheck };
    },
    frameJoints(person, t) {
      if (person >= frames.persons || t < 0 || t >= frames.received) return null;
      const f = frames.frame(person, t);
      const out: number[][] = [];
      for (let j = 0; j < f.length / 3; j++) out.push([f[3 * j], f[3 * j + 1], f[3 * j + 2]]);
      return out;
    },
    get figure() {
      const { figure, status } = useFigure.getState();
      return { figure, status, shown: figureStats.shown, characters: figureStats.characters };
    },
    get view() {
      return { preset: viewStats.view, moved: viewStats.moved, position: [...viewStats.position], target: [...viewStats.target] };
    },
    get penetrationMarks() {
      const d = viewStats.marks;
      return d ? Array.from({ length: viewStats.markCount }, (_, k) => Array.from(d.subarray(k * MARK_STRIDE, (k + 1) * MARK_STRIDE))) : [];
    },
    project(person, joint) {
      const t = useStudio.getState().frame;
      if (!sceneProbe.project || person >= frames.persons || t >= frames.received) return null;
      const f = frames.frame(person, t);
      return sceneProbe.project(f[3 * joint], f[3 * joint + 1], f[3 * joint + 2]);
    },
    projectPoint(x, y, z) {
      return sceneProbe.project ? sceneProbe.project(x, y, z) : null;
    },
    groundAt(x, y) {
      return sceneProbe.ground ? sceneProbe.ground(x, y) : null;
    },
    parseBvh,
  };
  Object.defineProperty(target, "__interplay", { value: Object.freeze(hook), writable: false });
}
