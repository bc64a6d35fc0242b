// @vitest-environment node
import { describe, expect, it } from "vitest";
import { keptPosition } from "./keep";

describe("keptPosition", () => {
  it("keeps the playhead where it was on a version as long", () => {
    expect(keptPosition(57.4, 120)).toBe(57.4);
    expect(keptPosition(0, 120)).toBe(0);
  });
  it("clamps it into a shorter version, and to 0 on an empty or bad one", () => {
    expect(keptPosition(150, 120)).toBe(119);
    expect(keptPosition(-2, 120)).toBe(0);
    expect(keptPosition(40, 0)).toBe(0);
    expect(keptPosition(NaN, 120)).toBe(0);
  });
});
