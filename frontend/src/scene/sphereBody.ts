// The 45-sphere body of one person, mirroring the backend's `interplay.motion.pair.body`
// (`body_spheres`, `body_scale`): the model the server's penetration highlights and metrics are
// computed on, so the studio can show *where* two bodies overlap (overlaps.ts) from the joints
// it already has. Each sphere sits at a fraction f of a bone from its parent joint p to its
// child c, centre = p + f (c - p); radii (m) are for the SMPL template's build, scaled by the
// person's size (legs + spine) relative to that template. Keep the table equal to body.py's
// `_TABLE` (sphereBody.test.ts compares values the Python functions computed).

/** The joints a layout is resolved against: names (GET /api/skeleton order) and parents. */
export interface JointTree {
  joints: string[];
  parents: number[];
}

// (parent, child, fractions along the bone, radii) per bone; "{s}" expands to left and right.
const TABLE: [string, string, number[], number[]][] = [
  ["pelvis", "{s}_hip", [0.5], [0.1]],
  ["pelvis", "spine1", [0.0, 0.6], [0.105, 0.11]],
  ["spine1", "spine2", [0.5], [0.12]],
  ["spine2", "spine3", [0.5], [0.12]],
  ["spine3", "neck", [0.3, 0.85], [0.11, 0.06]],
  ["spine3", "{s}_collar", [0.6], [0.07]],
  ["neck", "head", [1.5], [0.1]],
  ["{s}_collar", "{s}_shoulder", [0.5], [0.065]],
  ["{s}_hip", "{s}_knee", [0.2, 0.5, 0.8], [0.085, 0.07, 0.06]],
  ["{s}_knee", "{s}_ankle", [0.2, 0.5, 0.8], [0.055, 0.05, 0.045]],
  ["{s}_ankle", "{s}_foot", [-0.25, 0.25, 0.75], [0.04, 0.045, 0.04]],
  ["{s}_shoulder", "{s}_elbow", [0.15, 0.5, 0.85], [0.055, 0.05, 0.045]],
  ["{s}_elbow", "{s}_wrist", [0.2, 0.5, 0.8, 1.3], [0.045, 0.04, 0.035, 0.045]],
];

/** Joints whose bone (from the parent) measures a person's size: legs and spine, head to heel. */
const SIZE_JOINTS = ["left_knee", "left_ankle", "right_knee", "right_ankle", "spine1", "spine2", "spine3", "neck", "head"];

export const NUM_SPHERES = 45;
/** The template's size: the SMPL rest pose's size bones summed (m), body.py's `_TEMPLATE_SIZE`
 * (GET /api/skeleton has no rest pose; the test checks it against the fixture's). */
export const TEMPLATE_SIZE = 2.2702089930906553;

/** The spheres resolved to joint indices: parent, child and fraction per sphere, the template
 * radii (m), and the [child, parent] bones whose summed length is the person's size. */
export interface SphereLayout {
  parent: Uint8Array;
  child: Uint8Array;
  fraction: Float32Array;
  radius: Float32Array;
  sizeBones: [number, number][];
}

export function sphereLayout(tree: JointTree): SphereLayout {
  const index = (name: string) => {
    const j = tree.joints.indexOf(name);
    if (j < 0) throw new Error(`no joint ${name} for the sphere body`);
    return j;
  };
  const parent: number[] = [], child: number[] = [], fraction: number[] = [], radius: number[] = [];
  for (const [p, c, fs, rs] of TABLE) {
    const sides = (p + c).includes("{s}") ? ["left", "right"] : [""];
    for (const s of sides) {
      fs.forEach((f, k) => {
        parent.push(index(p.replace("{s}", s)));
        child.push(index(c.replace("{s}", s)));
        fraction.push(f);
        radius.push(rs[k]);
      });
    }
  }
  const sizeBones = SIZE_JOINTS.map((name) => [index(name), tree.parents[index(name)]] as [number, number]);
  return {
    parent: Uint8Array.from(parent),
    child: Uint8Array.from(child),
    fraction: Float32Array.from(fraction),
    radius: Float32Array.from(radius),
    sizeBones,
  };
}

/** Summed length of the size bones of the frame at `offset` in a flat joints array. */
export function sizeOf(joints: ArrayLike<number>, offset: number, bones: [number, number][]): number {
  let size = 0;
  for (const [c, p] of bones) {
    const a = offset + 3 * c, b = offset + 3 * p;
    size += Math.hypot(joints[a] - joints[b], joints[a + 1] - joints[b + 1], joints[a + 2] - joints[b + 2]);
  }
  return size;
}

/** A person's size relative to the template: the median over `frames` frames of a flat
 * (frames × 22 × 3) array, clipped to [0.5, 1.5], as body.py's `body_scale`. */
export function bodyScale(layout: SphereLayout, joints: ArrayLike<number>, frames: number): number {
  if (frames <= 0) return 1;
  const sizes = new Float64Array(frames);
  for (let t = 0; t < frames; t++) sizes[t] = sizeOf(joints, t * 66, layout.sizeBones);
  sizes.sort();
  const mid = frames >> 1;
  const median = frames % 2 ? sizes[mid] : (sizes[mid - 1] + sizes[mid]) / 2;
  return Math.min(1.5, Math.max(0.5, median / TEMPLATE_SIZE));
}

/** Place one frame's spheres: `joints` is 22 × xyz (66 floats); writes [x, y, z, radius] per
 * sphere into `out` (45 × 4 floats), radii times `scale`. No allocation. */
export function placeSpheres(layout: SphereLayout, joints: ArrayLike<number>, scale: number, out: Float32Array): Float32Array {
  for (let s = 0; s < layout.radius.length; s++) {
    const p = 3 * layout.parent[s], c = 3 * layout.child[s], f = layout.fraction[s];
    out[4 * s] = joints[p] + f * (joints[c] - joints[p]);
    out[4 * s + 1] = joints[p + 1] + f * (joints[c + 1] - joints[p + 1]);
    out[4 * s + 2] = joints[p + 2] + f * (joints[c + 2] - joints[p + 2]);
    out[4 * s + 3] = layout.radius[s] * scale;
  }
  return out;
}
