import { describe, expect, it } from "vitest";
import skeleton from "../test/skeleton.json";
import { timelineMarks, runs } from "./marks";
import { editPartOfJoint, jointsOfPart } from "./parts";
import { PRESETS, pathEnds, pathLength, presetPoints, thinPoints, type Point } from "./path";
import { canRedo, canUndo, current, fromHistory, moveTo, noVersions, pushVersion, redo, undo } from "./versions";

describe("paths", () => {
  it("thins a dense stroke but keeps both ends", () => {
    const dense: Point[] = Array.from({ length: 101 }, (_, i) => [i * 0.01, 0]);
    const thin = thinPoints(dense, 0.1);
    expect(thin[0]).toEqual([0, 0]);
    expect(thin[thin.length - 1]).toEqual([1, 0]);
    expect(thin.length).toBeGreaterThan(9);
    expect(thin.length).toBeLessThan(13);
    expect(pathLength(thin)).toBeCloseTo(1, 6);
  });

  it("presets start at the origin, head forward first and scale with size", () => {
    for (const shape of PRESETS) {
      const small = presetPoints(shape, 2);
      const big = presetPoints(shape, 4);
      expect(small[0][0]).toBeCloseTo(0, 2);
      expect(small[0][1]).toBeCloseTo(0, 2);
      const extent = (pts: Point[]) => Math.max(...pts.flatMap(([x, z]) => [Math.abs(x), Math.abs(z)]));
      expect(extent(big) / extent(small)).toBeCloseTo(2, 1);
      expect(Math.abs(pathEnds(small)!.heading)).toBeLessThan(Math.PI / 2 + 0.01); // not backwards
    }
    expect(() => presetPoints("circle", 0)).toThrow(/positive/);
  });

  it("a circle preset closes near its start", () => {
    const c = presetPoints("circle", 3);
    const { start, end } = pathEnds(c)!;
    expect(Math.hypot(end[0] - start[0], end[1] - start[1])).toBeLessThan(0.2);
    expect(pathLength(c)).toBeGreaterThan(Math.PI * 3 * 0.9);
  });
});

describe("parts", () => {
  it("maps joints to the edit endpoint's parts", () => {
    expect(editPartOfJoint("left_elbow")).toBe("left_arm");
    expect(editPartOfJoint("right_collar")).toBe("right_arm");
    expect(editPartOfJoint("left_foot")).toBe("left_leg");
    expect(editPartOfJoint("spine2")).toBe("whole_body");
    expect(editPartOfJoint("head")).toBe("head");
    expect(editPartOfJoint("neck")).toBe("whole_body");
    const arm = jointsOfPart(skeleton.joints, "left_arm").map((j) => skeleton.joints[j]);
    expect(arm).toEqual(["left_collar", "left_shoulder", "left_elbow", "left_wrist"]);
    expect(jointsOfPart(skeleton.joints, "whole_body")).toHaveLength(22);
  });
});

describe("versions", () => {
  it("undo / redo walk the chain and a new edit drops the redo tail", () => {
    let v = pushVersion(pushVersion(pushVersion(noVersions, "a"), "b"), "c");
    expect(current(v)).toBe("c");
    v = undo(undo(v));
    expect([current(v), canUndo(v), canRedo(v)]).toEqual(["a", false, true]);
    expect(undo(v)).toBe(v);
    v = redo(v);
    expect(current(v)).toBe("b");
    v = pushVersion(v, "d");
    expect(v.ids).toEqual(["a", "b", "d"]);
    expect(canRedo(v)).toBe(false);
  });

  it("positions an opened motion in its history", () => {
    const v = fromHistory(["r", "x", "y"], "x");
    expect([current(v), canUndo(v), canRedo(v)]).toEqual(["x", true, true]);
    expect(fromHistory(["p"], "q").ids).toEqual(["p", "q"]);
    expect(current(moveTo(v, "y"))).toBe("y");
    expect(moveTo(v, "zz").ids).toEqual(["zz"]);
  });
});

describe("timeline marks", () => {
  it("groups frames into runs", () => {
    expect(runs(6, (t) => t === 1 || t === 2 || t === 5)).toEqual([
      [1, 3],
      [5, 6],
    ]);
  });

  it("marks penetration runs and close two-person contacts, nothing for one person", () => {
    const pen: ([number, string][] | undefined)[] = [[], [[0, "left_upper"]], [[1, "right_upper"]], [], [], []];
    const con: ([number, number][] | undefined)[] = [[], [], [], [[0, 20], [1, 21]], [[0, 10]], []];
    const dist = [0.5, 0, 0, 0.02, 0.02, 0.4];
    const marks = timelineMarks(6, pen, con, dist, 2);
    expect(marks).toEqual([
      { kind: "penetration", start: 1, end: 3 },
      { kind: "contact", start: 3, end: 4 }, // frame 4: only a foot on the floor
    ]);
    expect(timelineMarks(6, pen, con, dist, 1)).toEqual([]);
  });
});
