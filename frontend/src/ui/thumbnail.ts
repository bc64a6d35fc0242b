// A first-frame pose as 2-D line segments for a small SVG, feet at the bottom: one person seen
// from the front (turned about the vertical to face the viewer), two people side by side.
import type { Vec3 } from "../api/types";

export interface ThumbLine {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
  person: number;
}

export interface Thumb {
  lines: ThumbLine[];
  /** SVG viewBox "minX minY width height" (y grows downwards). */
  viewBox: string;
}

// SMPL-22 indices (motion/skeleton.py): hips 1/2, shoulders 16/17.
const L_HIP = 1, R_HIP = 2, L_SHOULDER = 16, R_SHOULDER = 17;

/** The yaw that turns person `p`'s facing to +Z (towards a camera on +Z). */
function facingYaw(p: Vec3[]): number {
  if (p.length < 18) return 0;
  // across = right − left (hips + shoulders); forward = up × across, on the ground
  const ax = p[R_HIP][0] - p[L_HIP][0] + p[R_SHOULDER][0] - p[L_SHOULDER][0];
  const az = p[R_HIP][2] - p[L_HIP][2] + p[R_SHOULDER][2] - p[L_SHOULDER][2];
  const fx = az, fz = -ax; // (0,1,0) × (ax, 0, az) = (az, 0, −ax)
  if (Math.hypot(fx, fz) < 1e-6) return 0;
  return Math.atan2(fx, fz);
}

/** The (cos, sin) of the turn about the vertical the thumbnail is seen after: two people apart
 * side by side (the line between their pelvises across the picture, person 1 on the left),
 * else person 1 facing the viewer. */
function viewTurn(people: Vec3[][]): [number, number] {
  if (people.length > 1 && people[0].length && people[1].length) {
    const dx = people[1][0][0] - people[0][0][0], dz = people[1][0][2] - people[0][0][2];
    const d = Math.hypot(dx, dz);
    if (d > 0.25) return [dx / d, dz / d];
  }
  const yaw = people.length ? facingYaw(people[0]) : 0;
  return [Math.cos(-yaw), Math.sin(-yaw)];
}

/** Bones (child → parent) of every person, projected, fitted into a square with a margin. */
export function thumbnail(people: Vec3[][], parents: number[]): Thumb {
  const [c, s] = viewTurn(people);
  const pts = people.map((p) => p.map(([x, y, z]) => [c * x + s * z, -y] as [number, number]));
  const lines: ThumbLine[] = [];
  pts.forEach((p, person) => {
    for (let j = 0; j < p.length; j++) {
      const k = parents[j];
      if (k === undefined || k < 0 || k >= p.length) continue;
      lines.push({ x1: p[j][0], y1: p[j][1], x2: p[k][0], y2: p[k][1], person });
    }
  });
  const xs = pts.flat().map((q) => q[0]);
  const ys = pts.flat().map((q) => q[1]);
  if (!xs.length) return { lines, viewBox: "-1 -2 2 2" };
  const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  const size = Math.max(x1 - x0, y1 - y0, 0.5) * 1.15;
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const r = (v: number) => Number(v.toFixed(3));
  return { lines, viewBox: `${r(cx - size / 2)} ${r(cy - size / 2)} ${r(size)} ${r(size)}` };
}

/** "just now", "5 min ago", "3 h ago", or the date. */
export function ago(iso: string | null, now: number = Date.now()): string {
  if (!iso) return "";
  const t = Date.parse(iso);
  if (Number.isNaN(t)) return "";
  const s = Math.max(0, (now - t) / 1000);
  if (s < 60) return "just now";
  if (s < 3600) return `${Math.floor(s / 60)} min ago`;
  if (s < 86400) return `${Math.floor(s / 3600)} h ago`;
  return new Date(t).toLocaleDateString();
}
