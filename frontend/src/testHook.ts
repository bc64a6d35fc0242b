// `window.__interplay`: a tiny read-only view of the studio for the end-to-end tests.
import { FPS, frames, renderStats, useStudio } from "./store";

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
  readonly persons: number;
  readonly frameCount: number;
  readonly framesReceived: number;
  readonly fps: number;
  readonly firstFrame: number[][][];
  readonly currentFrame: number;
  readonly renderCount: number;
  /** "full" or "light" (software WebGL: no MSAA, blob shadows). */
  readonly quality: string;
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
    parseBvh,
  };
  Object.defineProperty(target, "__interplay", { value: Object.freeze(hook), writable: false });
}
