import { describe, expect, it } from "vitest";
import { DEFAULT_PRESETS, describePresets, withPresets } from "./exportPresets";

const BASE = "/api/motions/abc/export?format=glb";

describe("withPresets", () => {
  it("leaves the plain download alone with the defaults", () => {
    expect(withPresets(BASE, "glb", DEFAULT_PRESETS)).toBe(BASE);
  });
  it("adds fps, units and names to a GLB, and not the up axis", () => {
    const url = withPresets(BASE, "glb", { fps: 24, units: "cm", names: "mixamo", up: "z" });
    const q = new URLSearchParams(url.split("?")[1]);
    expect(Object.fromEntries(q)).toEqual({ format: "glb", fps: "24", units: "cm", names: "mixamo" });
  });
  it("adds the up axis to a BVH and keeps its person", () => {
    const url = withPresets("/api/motions/abc/export?format=bvh&person=1", "bvh", { ...DEFAULT_PRESETS, up: "z", fps: 60 });
    const q = new URLSearchParams(url.split("?")[1]);
    expect(Object.fromEntries(q)).toEqual({ format: "bvh", person: "1", fps: "60", up: "z" });
  });
  it("never changes the JSON", () => {
    const url = "/api/motions/abc/export?format=json";
    expect(withPresets(url, "json", { fps: 30, units: "cm", names: "mixamo", up: "z" })).toBe(url);
  });
});

describe("describePresets", () => {
  it("names what the file will be", () => {
    expect(describePresets({ fps: 30, units: "cm", names: "mixamo", up: "z" }, "bvh")).toBe("30 fps, cm, Mixamo names, Z up");
    expect(describePresets(DEFAULT_PRESETS, "glb")).toBe("20 fps, m, SMPL names");
  });
});
