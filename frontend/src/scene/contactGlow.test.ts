// @vitest-environment node
import { describe, expect, it } from "vitest";
import { skeleton } from "../test/fixtures";
import { footJoints, glowingContacts, NEW_FRAMES } from "./contactGlow";

const J = (n: string) => skeleton.joints.indexOf(n);
const feet = footJoints(skeleton.joints);
const LF = J("left_foot"), RF = J("right_foot"), LW = J("left_wrist");

describe("contact glow", () => {
  it("knows the feet", () => {
    expect([...feet].sort((a, b) => a - b)).toEqual([J("left_ankle"), J("right_ankle"), LF, RF].sort((a, b) => a - b));
  });

  it("does not light feet planted since the first frame (a person standing)", () => {
    const standing = Array.from({ length: 40 }, () => [[0, LF], [0, RF]] as [number, number][]);
    for (let t = 0; t < 40; t++) expect(glowingContacts(standing, t, 0, feet).size).toBe(0);
  });

  it("lights a foot that comes down, for NEW_FRAMES frames", () => {
    // the left foot lifts at 10 and lands at 20 (a step), the right stays down
    const walk = Array.from({ length: 40 }, (_, t) => [...(t < 10 || t >= 20 ? [[0, LF]] : []), [0, RF]] as [number, number][]);
    const lit = (t: number) => [...glowingContacts(walk, t, 0, feet)];
    expect(lit(5)).toEqual([]);
    expect(lit(19)).toEqual([]);
    for (let t = 20; t < 20 + NEW_FRAMES; t++) expect(lit(t)).toEqual([LF]);
    expect(lit(20 + NEW_FRAMES)).toEqual([]);
  });

  it("always lights a hand on the other person (what the prompt asked), for that person only", () => {
    const shake = Array.from({ length: 30 }, () => [[0, LF], [0, LW], [1, LW]] as [number, number][]);
    expect([...glowingContacts(shake, 25, 0, feet)]).toEqual([LW]);
    expect([...glowingContacts(shake, 0, 1, feet)]).toEqual([LW]);
    expect(glowingContacts([], 3, 0, feet).size).toBe(0);
  });
});
