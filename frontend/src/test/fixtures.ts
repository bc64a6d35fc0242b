// Test data: the skeleton payload (from interplay.motion.skeleton, see scripts/skeleton_fixture.py)
// and walking frames made by translating its rest pose.
import type { PersonFrames, Skeleton, Vec3 } from "../api/types";
import data from "./skeleton.json";

export const skeleton: Skeleton = data;
export const rest = data.rest as Vec3[];

/** n frames of the rest pose moving forward (+Z) at `speed` m/s from x offset `x0`, 20 fps. */
export function walkFrames(n: number, x0 = 0, speed = 1.2, from = 0): PersonFrames {
  return Array.from({ length: n }, (_, i) =>
    rest.map(([x, y, z]) => [x + x0, y, z + ((from + i) * speed) / 20] as Vec3),
  );
}
