// Digests of the frames the page holds, the same as the server's (backend/interplay/api/digest.py):
// per frame, 32-bit FNV-1a over every coordinate as an integer number of 0.1 mm
// (round(x × 10000)), person by person, joint by joint, x y z; 8 hex digits. At `done` the page
// compares them with the stored motion's (the done event's `frame_digests`) and reloads the
// frames that differ.
const OFFSET = 0x811c9dc5;
const PRIME = 0x01000193;
const STRIDE = 22 * 3;

function mix(h: number, word: number): number {
  return Math.imul(h ^ word, PRIME) >>> 0;
}

const hex = (h: number) => h.toString(16).padStart(8, "0");

/** The digest of frame `t` of `positions` (one Float32Array per person, 22 × 3 a frame). */
export function frameDigest(positions: Float32Array[], t: number): string {
  let h = OFFSET;
  for (const p of positions) {
    const o = t * STRIDE;
    for (let k = 0; k < STRIDE; k++) h = mix(h, Math.round(p[o + k] * 10000) | 0);
  }
  return hex(h);
}

/** The motion's digest from its frames' digests. */
export function motionDigest(frames: string[]): string {
  let h = OFFSET;
  for (const d of frames) h = mix(h, parseInt(d, 16) | 0);
  return hex(h);
}

/** The frames whose digest differs from `want` (every frame of `want` the page lacks too), as
 * [start, end) runs. */
export function differingRuns(positions: Float32Array[], received: number, want: string[]): [number, number][] {
  const runs: [number, number][] = [];
  for (let t = 0; t < want.length; t++) {
    const bad = t >= received || frameDigest(positions, t) !== want[t];
    if (!bad) continue;
    const last = runs[runs.length - 1];
    if (last && last[1] === t) last[1] = t + 1;
    else runs.push([t, t + 1]);
  }
  return runs;
}
