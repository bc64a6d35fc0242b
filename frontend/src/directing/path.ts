// Paths on the ground plane (x, z in metres): thinning what the pointer drew, preset shapes
// (circle, zigzag, S, heart) as editable control points, and the curve's ends.
export type Point = [number, number];
export type Preset = "circle" | "zigzag" | "s" | "heart";
export const PRESETS: Preset[] = ["circle", "zigzag", "s", "heart"];

/** Keep a drawn point only when it is at least `minStep` metres from the last one kept
 * (the pointer reports many near-duplicates); the last point is always kept. */
export function thinPoints(points: Point[], minStep = 0.08): Point[] {
  if (points.length < 2) return points.slice();
  const out: Point[] = [points[0]];
  for (let i = 1; i < points.length; i++) {
    const [x, z] = out[out.length - 1];
    if (Math.hypot(points[i][0] - x, points[i][1] - z) >= minStep) out.push(points[i]);
  }
  const last = points[points.length - 1];
  const kept = out[out.length - 1];
  if (kept !== last && Math.hypot(last[0] - kept[0], last[1] - kept[1]) > 1e-6) out.push(last);
  return out;
}

/** Total length of a polyline (m). */
export function pathLength(points: Point[]): number {
  let n = 0;
  for (let i = 1; i < points.length; i++) n += Math.hypot(points[i][0] - points[i - 1][0], points[i][1] - points[i - 1][1]);
  return n;
}

/** Control points of a preset, `size` metres across, starting at `origin` and heading +Z first
 * (the way a person stands at the start). */
export function presetPoints(shape: Preset, size: number, origin: Point = [0, 0]): Point[] {
  if (!(size > 0)) throw new Error(`size must be positive, got ${size}`);
  const r = size / 2;
  let pts: Point[];
  switch (shape) {
    case "circle": // starts at the origin, centre to the +X side, ends back near the start
      pts = Array.from({ length: 12 }, (_, i) => {
        const a = (i / 12) * 2 * Math.PI;
        return [r - r * Math.cos(a), r * Math.sin(a)] as Point;
      });
      pts.push([0, -0.05 * r]);
      break;
    case "zigzag":
      pts = Array.from({ length: 6 }, (_, i) => [i === 0 ? 0 : i % 2 ? r * 0.5 : -r * 0.5, (i / 5) * size] as Point);
      break;
    case "s":
      pts = Array.from({ length: 9 }, (_, i) => {
        const t = i / 8;
        return [r * 0.6 * Math.sin(t * 2 * Math.PI), t * size] as Point;
      });
      break;
    case "heart": {
      // the classic parametric heart, scaled to `size`, rotated to start at its bottom tip
      pts = Array.from({ length: 16 }, (_, i) => {
        const t = Math.PI + (i / 16) * 2 * Math.PI;
        const x = 16 * Math.sin(t) ** 3;
        const y = 13 * Math.cos(t) - 5 * Math.cos(2 * t) - 2 * Math.cos(3 * t) - Math.cos(4 * t);
        return [(x / 34) * size, ((y + 17) / 34) * size] as Point;
      });
      break;
    }
  }
  return pts.map(([x, z]) => [round(x + origin[0]), round(z + origin[1])] as Point);
}

function round(v: number): number {
  return Math.round(v * 1000) / 1000;
}

/** The drawn end point and the heading at the start (radians from +Z towards +X). */
export function pathEnds(points: Point[]): { start: Point; end: Point; heading: number } | null {
  if (points.length < 2) return null;
  const [a, b] = points;
  return { start: a, end: points[points.length - 1], heading: Math.atan2(b[0] - a[0], b[1] - a[1]) };
}
