// @vitest-environment node
import { describe, expect, it } from "vitest";
import { followedOf, shownPath } from "./followed";

const drawn: [number, number][] = [[0, 0], [1, 0.5], [2, 0]];
const none = { person: 0, points: [] as [number, number][] };

describe("the path a motion followed", () => {
  it("is its path edit's, else its plan's drawn path; a preset shape or none is no path", () => {
    expect(followedOf({ id: "a", plan: { segments: [], trajectory: { person: 1, points: drawn } } })).toEqual({ motionId: "a", person: 1, points: drawn });
    const edit = { trajectory: { person: 0 as const, points: [[5, 5], [6, 6]] as [number, number][] } };
    expect(followedOf({ id: "b", plan: { segments: [], trajectory: { person: 1, points: drawn } }, edit })?.points).toEqual([[5, 5], [6, 6]]);
    expect(followedOf({ id: "c", plan: { segments: [], trajectory: { person: 0, shape: "circle" } } })).toBeNull();
    expect(followedOf({ id: "d", plan: { segments: [] } })).toBeNull();
    expect(followedOf({ id: "e", plan: { segments: [], trajectory: { points: [[0, "x"], [1, 1]] } } })).toBeNull();
  });

  it("stays on the floor with its motion and its versions, unless hidden", () => {
    const f = { motionId: "m1", person: 0, points: drawn };
    expect(shownPath(none, f, true, "m1", ["m1"])).toEqual({ person: 0, points: drawn, followed: true });
    expect(shownPath(none, f, true, "m2", ["m1", "m2"]).followed).toBe(true); // an edit of it
    expect(shownPath(none, f, false, "m1", ["m1"])).toEqual({ ...none, followed: false }); // toggled off
    expect(shownPath(none, f, true, "other", ["other"]).points).toEqual([]); // another motion
    expect(shownPath(none, f, true, null, []).points).toEqual([]); // a cleared stage
  });

  it("gives way to a path being drawn or waiting for the next Generate", () => {
    const pending = { person: 1, points: [[3, 3]] as [number, number][] };
    expect(shownPath(pending, { motionId: "m1", person: 0, points: drawn }, true, "m1", ["m1"])).toEqual({ ...pending, followed: false });
  });
});
