// Camera framing, pure math: which way the preset views look at the people, and how far back
// the camera must stand for everyone to fit. Vectors are [x, y, z] (Y up); directions on the
// floor are [x, z]. A view is the unit direction from the orbit target to the camera.
//
// Two people: the default view looks at the pair from the SIDE of the line between them, so
// both are seen next to each other (looking along the line, one hides the other); one person:
// a 3/4 view from the front. The presets:
//   front   the group's front, nearly level (8° above);  side  from the front view's right;
//   top     straight down, the front at the bottom of the screen;
//   fit     the current direction, moved to fit everyone;  default  the opening view (reset).
// "The group's front" is one person's facing; for two, the perpendicular to the line between
// them on the side both face, or where they face each other (or away), the side from which
// Person 1 is on the left and Person 2 on the right. The side view's camera stands at the front
// view's screen right (as Blender's "Right" view): one person's left; for a pair, from Person 2's
// end but turned off their line towards the front (`pairSideTurn`) just enough that the two
// stand apart on screen — exactly along the line one stood behind the other (issue 26).

export type Vec3 = [number, number, number];
export type ViewPreset = "default" | "front" | "side" | "top" | "fit";

const DEG = Math.PI / 180;

/** The group's horizontal frame, unit [x, z] vectors from the group: `front`, where a front
 * view's camera stands, and `side`, the front view's screen right; `pair` for two people. */
export interface GroupFrame {
  front: [number, number];
  side: [number, number];
  pair: boolean;
  /** A pair's distance between the pelvises on the floor (m); 0 for one person. */
  span: number;
}

/** How far apart (m, across the screen) a pair's pelvises must be drawn in the side view so
 * that their bodies (about 0.45 m across at the shoulders) do not cover each other. */
export const SIDE_CLEAR = 0.5;
const SIDE_TURN = { min: 30 * DEG, max: 65 * DEG };

/** The side view's turn off a pair's line towards the front (radians) for pelvises `span`
 * metres apart: the least at which they are SIDE_CLEAR apart across the screen (span × sin),
 * at least 30° (depth still reads) and at most 65° (a hug, close together, is seen mostly from
 * the front: no side view keeps them apart). */
export function pairSideTurn(span: number): number {
  const need = span > SIDE_CLEAR ? Math.asin(SIDE_CLEAR / span) : SIDE_TURN.max;
  return Math.min(SIDE_TURN.max, Math.max(SIDE_TURN.min, need));
}

const ELEVATION = { default: 14 * DEG, front: 8 * DEG, side: 8 * DEG };
/** The default view turns this far from the front towards the side: one person in 3/4 (the
 * old world-fixed default's 23°, for a person facing +Z), a pair a little, to read depth
 * while both stay apart. */
const YAW = { one: 23 * DEG, pair: 15 * DEG };
/** Top view: the camera's tilt off vertical towards the front (orbit controls need one). */
const TOP_TILT = 1e-3;
/** Share of the view's half-width (sides) and half-height (top, bottom) left free around the
 * people. The bottom keeps more: the colour legend lies over the canvas's lower left. */
export const FIT_MARGIN = { side: 0.12, top: 0.12, bottom: 0.36 };
/** The camera stands at least this many times the group's depth (along the view) back, so the
 * near parts are not drawn much larger than the far ones (from above at a tight fit the heads
 * came out three times the size of the feet; at 1.5 they are under twice). */
const DEPTH_RATIO = 1.5;

function unit2(x: number, z: number): [number, number] | null {
  const n = Math.hypot(x, z);
  return n > 1e-6 ? [x / n, z / n] : null;
}

/** Where a pose faces on the floor: the hips' left-to-right line turned a quarter (the SMPL
 * rest pose, left hip at +X, faces +Z). `joints`: 22 × xyz; lh, rh: the hip joints. */
export function facing(joints: ArrayLike<number>, lh: number, rh: number): [number, number] {
  const ax = joints[3 * lh] - joints[3 * rh], az = joints[3 * lh + 2] - joints[3 * rh + 2];
  // (across × up) on the floor: [x, z] = [-az, ax]
  return unit2(-az, ax) ?? [0, 1];
}

/** The frame of one or two poses (each 22 × xyz; joint 0 the pelvis). */
export function groupFrame(poses: ArrayLike<number>[], lh: number, rh: number): GroupFrame {
  const faces = poses.map((p) => facing(p, lh, rh));
  const line = poses.length === 2 ? unit2(poses[1][0] - poses[0][0], poses[1][2] - poses[0][2]) : null;
  // the front view's screen right, for a camera at `front`: (front × up) on the floor
  const screenRight = ([fx, fz]: [number, number]): [number, number] => [fz, -fx];
  if (!line) {
    const front = faces[0] ?? [0, 1];
    return { front, side: screenRight(front), pair: false, span: 0 };
  }
  // the perpendicular from which the line runs left to right (Person 1 left, Person 2 right)
  let front: [number, number] = [-line[1], line[0]];
  const lean = (faces[0][0] + faces[1][0]) * front[0] + (faces[0][1] + faces[1][1]) * front[1];
  if (lean < -0.5) front = [-front[0], -front[1]]; // both face the other side: see their fronts
  const span = Math.hypot(poses[1][0] - poses[0][0], poses[1][2] - poses[0][2]);
  return { front, side: screenRight(front), pair: true, span };
}

/** The unit direction from the target to the camera for a preset (not "fit": that keeps the
 * camera's own). */
export function viewDirection(preset: Exclude<ViewPreset, "fit">, g: GroupFrame): Vec3 {
  const [fx, fz] = g.front;
  const [sx, sz] = g.side;
  const level = (x: number, z: number, el: number): Vec3 => [x * Math.cos(el), Math.sin(el), z * Math.cos(el)];
  if (preset === "front") return level(fx, fz, ELEVATION.front);
  if (preset === "side") {
    // a pair: from Person 2's end, turned towards the front until both are apart on screen
    const turn = g.pair ? pairSideTurn(g.span) : 0;
    return level(sx * Math.cos(turn) + fx * Math.sin(turn), sz * Math.cos(turn) + fz * Math.sin(turn), ELEVATION.side);
  }
  if (preset === "top") return normalise([fx * TOP_TILT, 1, fz * TOP_TILT]);
  const yaw = g.pair ? YAW.pair : YAW.one; // default: from the front, turned towards the side
  return level(fx * Math.cos(yaw) + sx * Math.sin(yaw), fz * Math.cos(yaw) + sz * Math.sin(yaw), ELEVATION.default);
}

export function normalise(v: Vec3): Vec3 {
  const n = Math.hypot(v[0], v[1], v[2]) || 1;
  return [v[0] / n, v[1] / n, v[2] / n];
}

const cross = (a: Vec3, b: Vec3): Vec3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

export interface Fit {
  target: Vec3;
  position: Vec3;
  distance: number;
}

/** The target and camera position that fit `spheres` ([x, y, z, radius] × n, world metres:
 * the people's bodies over the frames to show) in a perspective view looking along `-dir`,
 * with `fovY` (degrees, vertical) and `aspect` (width / height), leaving FIT_MARGIN free. The
 * spheres' box's middle is fitted into the middle of the free window: the distance is the
 * least at which every sphere's silhouette (its centre's offset plus its radius, on the
 * screen's axes) is inside that window's half-extents at its depth — at least `minDistance`
 * and DEPTH_RATIO × the group's depth —, and the target is moved down the screen so that the
 * middle is drawn at the window's middle (above the screen's, the bottom margin being wider). */
export function fitView(dir: Vec3, spheres: Float32Array, fovY: number, aspect: number, minDistance = 0.8): Fit {
  const lo: Vec3 = [Infinity, Infinity, Infinity], hi: Vec3 = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < spheres.length; i += 4) {
    for (let k = 0; k < 3; k++) {
      lo[k] = Math.min(lo[k], spheres[i + k] - spheres[i + 3]);
      hi[k] = Math.max(hi[k], spheres[i + k] + spheres[i + 3]);
    }
  }
  const target: Vec3 = spheres.length ? [0, 1, 2].map((k) => (lo[k] + hi[k]) / 2) as Vec3 : [0, 0.9, 0];
  const back = normalise(dir);
  const forward: Vec3 = [-back[0], -back[1], -back[2]];
  // the screen's axes, as three's lookAt makes them with the world's up
  const sideways = cross(forward, [0, 1, 0]);
  const right = Math.hypot(...sideways) > 1e-9 ? normalise(sideways) : ([1, 0, 0] as Vec3);
  const up = cross(right, forward);
  const tan = Math.tan((fovY * DEG) / 2);
  const { side, top, bottom } = FIT_MARGIN;
  const tanY = tan * (1 - (top + bottom) / 2); // the free window's half-height …
  const tanX = tan * aspect * (1 - side);
  const lift = (bottom - top) / 2; // … and its middle, above the screen's (NDC)
  let distance = minDistance;
  let near = Infinity, far = -Infinity;
  for (let i = 0; i < spheres.length; i += 4) {
    const rel: Vec3 = [spheres[i] - target[0], spheres[i + 1] - target[1], spheres[i + 2] - target[2]];
    const r = spheres[i + 3];
    const depth = dot(rel, forward); // beyond the target (> 0) or before it
    near = Math.min(near, depth - r);
    far = Math.max(far, depth + r);
    // at camera distance D the sphere is D + depth away: |offset| + r must fit tan × that
    distance = Math.max(distance, (Math.abs(dot(rel, right)) + r) / tanX - depth, (Math.abs(dot(rel, up)) + r) / tanY - depth);
  }
  if (spheres.length) distance = Math.max(distance, DEPTH_RATIO * (far - near));
  // look at a point below the middle, by `lift` of the half-height at the middle's distance
  const drop = lift * tan * distance;
  const aim: Vec3 = [0, 1, 2].map((k) => target[k] - up[k] * drop) as Vec3;
  return { target: aim, position: [0, 1, 2].map((k) => aim[k] + back[k] * distance) as Vec3, distance };
}
