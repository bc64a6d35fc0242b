// @vitest-environment node
import { describe, expect, it } from "vitest";
import { MAX_GROUND_DISTANCE, usableGroundHit } from "./Picker";
import { PALETTES, luminance } from "./palette";

describe("floor hits for drawing", () => {
  it("takes hits near the camera, not the metres-per-pixel floor near the horizon", () => {
    const camera = { x: 2.4, y: 1.8, z: 5.2 };
    expect(usableGroundHit({ x: 0, y: 0, z: 0 }, camera)).toBe(true);
    expect(usableGroundHit({ x: 0, y: 0, z: -15 }, camera)).toBe(true);
    expect(usableGroundHit({ x: 0, y: 0, z: 5.2 - MAX_GROUND_DISTANCE - 1 }, camera)).toBe(false);
    expect(usableGroundHit(null, camera)).toBe(false);
  });
});

describe("stage palettes", () => {
  it("the light theme lights the viewport: a light floor and background, grid lines still visible", () => {
    for (const k of ["background", "floor"] as const) expect(luminance(PALETTES.light[k])).toBeGreaterThan(0.6);
    for (const k of ["background", "floor"] as const) expect(luminance(PALETTES.dark[k])).toBeLessThan(0.02);
    // the lines differ from the floor in both themes
    for (const p of Object.values(PALETTES)) expect(Math.abs(luminance(p.major) - luminance(p.floor))).toBeGreaterThan(0.01);
  });
});
