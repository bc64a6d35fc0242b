// At `done`, the page checks its copy of the streamed frames against the stored motion: the done
// event carries the stored frames' digests (api/digest.ts); frames that differ are reloaded from
// GET /api/motions/{id}. Replacements (`replace` events) should leave nothing to reload: what
// this reports (the test hook's `copyCheck`) says whether they did.
import { differingRuns, frameDigest, motionDigest } from "../api/digest";
import type { Motion, StreamEvent } from "../api/types";
import type { FrameBuffer } from "./frameBuffer";

type Done = Extract<StreamEvent, { type: "done" }>;

export interface CopyCheck {
  /** The motion checked (null before the first done). */
  motionId: string | null;
  /** Frames that differed from the stored ones at `done`, and whether they were reloaded. */
  differing: number;
  reloaded: number;
  /** The page's digest after the check, and whether it is the stored motion's. */
  digest: string | null;
  matches: boolean | null;
  /** Frames replaced by `replace` events during the stream. */
  replaced: number;
}

export const copyCheck: CopyCheck = { motionId: null, differing: 0, reloaded: 0, digest: null, matches: null, replaced: 0 };

/** A new stream starts: nothing replaced yet. */
export function resetCopyCheck(): void {
  Object.assign(copyCheck, { motionId: null, differing: 0, reloaded: 0, digest: null, matches: null, replaced: 0 });
}

/** The page's digest of frames [0, n). */
export function bufferDigest(buf: FrameBuffer, n: number): string {
  return motionDigest(Array.from({ length: n }, (_, t) => frameDigest(buf.positions, t)));
}

/** Compare `buf` with the done event's digests; reload the frames that differ (`load`: the
 * stored motion). Without digests (an older server) nothing is checked. */
export async function verifyCopy(buf: FrameBuffer, ev: Done, load: (id: string) => Promise<Motion>): Promise<CopyCheck> {
  copyCheck.motionId = ev.motion_id;
  const want = ev.frame_digests;
  if (!want || !ev.digest) return copyCheck;
  const runs = differingRuns(buf.positions, buf.received, want);
  copyCheck.differing = runs.reduce((n, [a, b]) => n + b - a, 0);
  if (runs.length) {
    const motion = await load(ev.motion_id);
    if (motion.people.length !== buf.persons) buf.loadMotion(motion);
    else
      for (const [a, b] of runs) {
        buf.setFrames(a, motion.people.map((p) => p.joints.slice(a, b)));
        if (motion.highlights) {
          const h = motion.highlights;
          buf.setHighlights({
            start: a,
            contacts: h.contacts.slice(a, b),
            penetration: h.penetration.slice(a, b),
            min_distance: h.min_distance ? h.min_distance.slice(a, b) : null,
          });
        }
      }
    copyCheck.reloaded = copyCheck.differing;
  }
  copyCheck.digest = bufferDigest(buf, want.length);
  copyCheck.matches = copyCheck.digest === ev.digest;
  return copyCheck;
}
