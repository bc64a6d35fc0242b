// Where two sphere bodies (sphereBody.ts) overlap at one pose: a mark per overlapping region,
// for the studio to draw penetration where it happens instead of painting whole parts red.
//
// Two spheres A (centre a, radius ra) and B (b, rb) at distance d < ra + rb share a lens. Along
// the line of centres the lens spans from B's near surface (d - rb from a) to A's (ra from a);
// its mark sits at the middle of that span, sized by the lens: its thickness along the line
// (ra + rb - d, at most the smaller diameter) and the radius of the circle where the surfaces
// meet. Overlaps of neighbouring sphere pairs (a hug's chest against chest is a dozen of them)
// closer than MERGE_M are one mark, the deepest pair's, so a region reads as one blob. A pair
// counts when it overlaps at all (gap < 0), as the server's `pair_geometry` with
// `overlap_depth` 0: the frames with marks are the frames the server lists penetration for.

/** Marks kept per pose (a full-body overlap of two people is far fewer regions than this). */
export const MAX_MARKS = 48;
/** Marks whose centres are closer than this (m) are merged into the deeper one. */
export const MERGE_M = 0.06;
/** A mark's drawn radius (m) stays within these bounds (a graze is still visible). */
export const MARK_RADIUS: [number, number] = [0.025, 0.07];

/** Marks of one pose: `count` of them, each [x, y, z, radius, depth] in `data`
 * (MAX_MARKS × 5 floats). Reused between poses. */
export interface OverlapMarks {
  count: number;
  data: Float32Array;
}

export const MARK_STRIDE = 5;

export function emptyMarks(): OverlapMarks {
  return { count: 0, data: new Float32Array(MAX_MARKS * MARK_STRIDE) };
}

/** Fill `out` with the overlaps of spheres `a` and `b` ([x, y, z, r] × n each, sphereBody's
 * `placeSpheres`); returns out.count. No allocation. */
export function findOverlaps(a: Float32Array, b: Float32Array, out: OverlapMarks): number {
  out.count = 0;
  for (let i = 0; i < a.length; i += 4) {
    const ax = a[i], ay = a[i + 1], az = a[i + 2], ra = a[i + 3];
    for (let j = 0; j < b.length; j += 4) {
      const dx = b[j] - ax, dy = b[j + 1] - ay, dz = b[j + 2] - az, rb = b[j + 3];
      const reach = ra + rb;
      const dist2 = dx * dx + dy * dy + dz * dz;
      if (dist2 >= reach * reach) continue;
      const dist = Math.sqrt(dist2);
      const depth = reach - dist;
      // the middle of the overlap along the line of centres (a's centre when they coincide)
      const along = dist > 1e-9 ? (dist - rb + ra) / 2 / dist : 0;
      const x = ax + dx * along, y = ay + dy * along, z = az + dz * along;
      // the circle where the surfaces meet; one sphere inside the other: the smaller sphere
      const foot = dist > 1e-9 ? (dist2 + ra * ra - rb * rb) / (2 * dist) : 0;
      const rim = dist <= Math.abs(ra - rb) ? Math.min(ra, rb) : Math.sqrt(Math.max(0, ra * ra - foot * foot));
      // the lens's thickness along the line of centres is at most the smaller sphere's diameter
      const thickness = Math.min(depth, 2 * Math.min(ra, rb));
      const radius = Math.min(MARK_RADIUS[1], Math.max(MARK_RADIUS[0], 0.5 * Math.max(rim, thickness)));
      add(out, x, y, z, radius, depth);
    }
  }
  return out.count;
}

/** Add a mark, or merge it into one within MERGE_M (the deeper one stays, grown to cover both
 * sizes); beyond MAX_MARKS the shallowest is replaced. */
function add(out: OverlapMarks, x: number, y: number, z: number, radius: number, depth: number): void {
  const d = out.data;
  let shallowest = -1;
  for (let k = 0; k < out.count; k++) {
    const o = k * MARK_STRIDE;
    if ((d[o] - x) ** 2 + (d[o + 1] - y) ** 2 + (d[o + 2] - z) ** 2 < MERGE_M * MERGE_M) {
      const r = Math.max(d[o + 3], radius);
      if (depth > d[o + 4]) write(d, o, x, y, z, r, depth);
      else d[o + 3] = r;
      return;
    }
    if (shallowest < 0 || d[o + 4] < d[shallowest * MARK_STRIDE + 4]) shallowest = k;
  }
  if (out.count < MAX_MARKS) write(d, out.count++ * MARK_STRIDE, x, y, z, radius, depth);
  else if (depth > d[shallowest * MARK_STRIDE + 4]) write(d, shallowest * MARK_STRIDE, x, y, z, radius, depth);
}

function write(d: Float32Array, o: number, x: number, y: number, z: number, r: number, depth: number): void {
  d[o] = x;
  d[o + 1] = y;
  d[o + 2] = z;
  d[o + 3] = r;
  d[o + 4] = depth;
}
