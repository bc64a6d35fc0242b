// The skeleton animation of a stored motion, for the skinned character: per person the rest
// offsets, root (pelvis) positions and local joint rotations that the server's one rotation
// solver (`backend/interplay/motion/rig.py`, `solve_rig`) wrote into the version-2 Motion JSON
// (GET /api/motions/{id}/export?format=json). The front end never solves rotations: it
// interpolates the server's (root linearly, rotations by slerp) at the playback clock and fits
// the mesh to each person's bone lengths. Plain typed arrays, read by the render loop.
import { Quaternion } from "three";
import { NUM_JOINTS } from "./frameBuffer";

export const RIG_SCHEMA = "interplay.motion/2";

export interface RigPerson {
  /** Rest offsets (22 × xyz, metres): parent → child in the parent's rest frame; row 0 is the
   * rest pelvis position. */
  offsets: Float32Array;
  /** Pelvis positions, frames × xyz. */
  root: Float32Array;
  /** Local rotations, frames × 22 × (x, y, z, w) — three's order (the JSON has w first); the
   * pelvis's is global; identity is the rest pose. */
  rotations: Float32Array;
}

export interface MotionRig {
  motionId: string;
  frames: number;
  people: RigPerson[];
}

type Num3 = [number, number, number];
interface RigJson {
  offsets: Num3[];
  root: Num3[];
  rotations: [number, number, number, number][][];
}

function fail(why: string): never {
  throw new Error(`not a rigged motion: ${why}`);
}

/** The rig of every person of a version-2 Motion JSON (`people[i].rig`). Throws when the file
 * is not version 2 or a shape is wrong. */
export function parseRig(motionId: string, json: unknown): MotionRig {
  const d = json as { schema?: unknown; people?: { rig?: RigJson }[] } | null;
  if (!d || d.schema !== RIG_SCHEMA) fail(`schema ${JSON.stringify(d?.schema)}, expected ${RIG_SCHEMA}`);
  if (!Array.isArray(d.people) || d.people.length === 0) fail("no people");
  let frames = -1;
  const people = d.people.map((p, i): RigPerson => {
    const rig = p.rig;
    if (!rig || !Array.isArray(rig.offsets) || !Array.isArray(rig.root) || !Array.isArray(rig.rotations)) fail(`person ${i} has no rig`);
    const t = rig.root.length;
    if (frames >= 0 && t !== frames) fail(`people differ in length (${frames}, ${t})`);
    frames = t;
    if (rig.offsets.length !== NUM_JOINTS || rig.rotations.length !== t) fail(`person ${i}: offsets or rotations of the wrong size`);
    const offsets = new Float32Array(rig.offsets.flat());
    const root = new Float32Array(rig.root.flat());
    const rotations = new Float32Array(t * NUM_JOINTS * 4);
    for (let f = 0; f < t; f++) {
      const frame = rig.rotations[f];
      if (frame.length !== NUM_JOINTS) fail(`person ${i}, frame ${f}: ${frame.length} rotations`);
      for (let j = 0; j < NUM_JOINTS; j++) {
        const [w, x, y, z] = frame[j];
        const o = (f * NUM_JOINTS + j) * 4;
        rotations[o] = x;
        rotations[o + 1] = y;
        rotations[o + 2] = z;
        rotations[o + 3] = w;
      }
    }
    if (offsets.length !== NUM_JOINTS * 3 || root.length !== t * 3 || ![offsets, root, rotations].every((a) => a.every(Number.isFinite))) {
      fail(`person ${i}: non-numeric or misshapen rig`);
    }
    return { offsets, root, rotations };
  });
  return { motionId, frames, people };
}

/** The pose between frames t and `next` (weight 0: frame t exactly): the root lerped into
 * `root` (3 floats), each joint's rotation slerped (shorter arc) into `quats` (22 × xyzw). No
 * allocation. */
export function sampleRig(rig: RigPerson, t: number, next: number, weight: number, quats: Float32Array, root: Float32Array): void {
  const r = rig.root;
  const q = rig.rotations;
  const a = 3 * t;
  const b = 3 * next;
  for (let k = 0; k < 3; k++) root[k] = r[a + k] + (r[b + k] - r[a + k]) * weight;
  const qa = 4 * NUM_JOINTS * t;
  const qb = 4 * NUM_JOINTS * next;
  if (weight <= 0 || next === t) {
    quats.set(q.subarray(qa, qa + 4 * NUM_JOINTS));
    return;
  }
  // three's typings say number[]; it reads and writes any indexable array
  const dst = quats as unknown as number[];
  const src = q as unknown as number[];
  for (let j = 0; j < NUM_JOINTS; j++) Quaternion.slerpFlat(dst, 4 * j, src, qa + 4 * j, src, qb + 4 * j, weight);
}

/** Rest positions (22 × xyz) of a skeleton with these offsets: each joint is its parent's plus
 * its offset (the rest pose has no rotation). */
export function restJoints(offsets: ArrayLike<number>, parents: readonly number[]): Float32Array {
  const out = new Float32Array(NUM_JOINTS * 3);
  for (let j = 0; j < NUM_JOINTS; j++) {
    const p = parents[j];
    for (let k = 0; k < 3; k++) out[3 * j + k] = offsets[3 * j + k] + (p >= 0 ? out[3 * p + k] : 0);
  }
  return out;
}

/** The mesh's bind-pose positions on a person's own bones: each vertex moves by its joints'
 * (weighted) change of rest position from the template's skeleton to the person's — what
 * `humanoid.on_skeleton` does for the GLB export. skinIndex / skinWeight: 4 per vertex. */
export function fitPositions(
  positions: ArrayLike<number>,
  skinIndex: ArrayLike<number>,
  skinWeight: ArrayLike<number>,
  templateRest: ArrayLike<number>,
  personRest: ArrayLike<number>,
): Float32Array {
  const n = positions.length / 3;
  const out = new Float32Array(positions.length);
  for (let v = 0; v < n; v++) {
    let dx = 0, dy = 0, dz = 0;
    for (let k = 0; k < 4; k++) {
      const w = skinWeight[4 * v + k];
      if (!w) continue;
      const j = 3 * skinIndex[4 * v + k];
      dx += w * (personRest[j] - templateRest[j]);
      dy += w * (personRest[j + 1] - templateRest[j + 1]);
      dz += w * (personRest[j + 2] - templateRest[j + 2]);
    }
    out[3 * v] = positions[3 * v] + dx;
    out[3 * v + 1] = positions[3 * v + 1] + dy;
    out[3 * v + 2] = positions[3 * v + 2] + dz;
  }
  return out;
}

/** Per vertex of a skinned mesh: its strongest joint (contacts glow there) and the bone it lies
 * on, named by the bone's child joint as the mannequin names its bones (part colour,
 * penetration, picking): a joint with one child — that child; with several — at the root
 * (pelvis) the child weighing most in the vertex, if any does; elsewhere (spine3, the chest),
 * when `names` are given, the trunk's own child (neck: the one named without left_/right_), so
 * the chest and back stay the torso's — the collars' weights reach across the chest, and taking
 * the heaviest child there painted the chest and back in the arm's colour (issue 26); a leaf
 * (head, wrists, feet) — itself. */
export function vertexJoints(
  skinIndex: ArrayLike<number>,
  skinWeight: ArrayLike<number>,
  parents: readonly number[],
  names?: readonly string[],
): { joint: Uint8Array; bone: Uint8Array } {
  const n = skinIndex.length / 4;
  const children: number[][] = parents.map(() => []);
  parents.forEach((p, j) => p >= 0 && children[p].push(j));
  // a branching joint above the root: its child continuing the trunk (-1: the heaviest child)
  const trunkChild = parents.map((p, j) => {
    if (p < 0 || !names || children[j].length < 2) return -1;
    const centre = children[j].filter((k) => !/^(left|right)_/.test(names[k] ?? ""));
    return centre.length === 1 ? centre[0] : -1;
  });
  const joint = new Uint8Array(n);
  const bone = new Uint8Array(n);
  for (let v = 0; v < n; v++) {
    let best = 0;
    for (let k = 1; k < 4; k++) if (skinWeight[4 * v + k] > skinWeight[4 * v + best]) best = k;
    const j = skinIndex[4 * v + best];
    joint[v] = j;
    const kids = children[j];
    const trunk = trunkChild[j];
    if (kids.length === 1) bone[v] = kids[0];
    else if (kids.length === 0) bone[v] = j;
    else if (trunk >= 0) bone[v] = trunk;
    else {
      let pick = j;
      let weight = 0;
      for (let k = 0; k < 4; k++) {
        const w = skinWeight[4 * v + k];
        if (w > weight && kids.includes(skinIndex[4 * v + k])) {
          weight = w;
          pick = skinIndex[4 * v + k];
        }
      }
      bone[v] = pick;
    }
  }
  return { joint, bone };
}
