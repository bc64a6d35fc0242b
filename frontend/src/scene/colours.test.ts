import { describe, expect, it } from "vitest";
import { skeleton } from "../test/fixtures";
import {
  PERSON_TINT,
  PERSON_TINT_AMOUNT,
  bones,
  contactJoints,
  jointColours,
  mixHex,
  partColour,
} from "./colours";

const J = (name: string) => skeleton.joints.indexOf(name);

describe("part colours", () => {
  it("colours each joint by its part, the second person tinted apart", () => {
    const c0 = jointColours(skeleton, 0);
    const c1 = jointColours(skeleton, 1);
    expect(c0[J("left_wrist")]).toBe(skeleton.colours.left_upper);
    expect(c0[J("right_knee")]).toBe(skeleton.colours.right_lower);
    expect(new Set(c0).size).toBe(4);
    expect(new Set(c1).size).toBe(4);
    for (const c of c1) expect(c0).not.toContain(c);
    expect(partColour(skeleton, "left_lower", 1)).toBe(mixHex(skeleton.colours.left_lower, PERSON_TINT, PERSON_TINT_AMOUNT));
  });

  it("mixes hex colours linearly", () => {
    expect(mixHex("#000000", "#ffffff", 0.5)).toBe("#808080");
    expect(mixHex("#102030", "#102030", 0.3)).toBe("#102030");
    expect(() => mixHex("red", "#fff", 0.5)).toThrow();
  });

  it("has one bone per non-root joint", () => {
    const b = bones(skeleton);
    expect(b.length).toBe(21);
    expect(b).toContainEqual([J("left_elbow"), J("left_shoulder")]);
  });

  it("maps contact highlights to a person's joints", () => {
    expect([...contactJoints([[0, 20], [1, 21], [0, 10]], 0)].sort()).toEqual([10, 20]);
    expect(contactJoints(undefined, 0).size).toBe(0);
  });
});
