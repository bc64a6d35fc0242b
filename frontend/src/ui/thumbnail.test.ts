import { describe, expect, it } from "vitest";
import skeleton from "../test/skeleton.json";
import type { Vec3 } from "../api/types";
import { ago, thumbnail } from "./thumbnail";

const rest = skeleton.rest as Vec3[];
const parents: number[] = skeleton.parents;

/** The rest pose (facing +Z) turned by `yaw` about Y and moved by (dx, dz). */
function posed(yaw: number, dx = 0, dz = 0): Vec3[] {
  const c = Math.cos(yaw), s = Math.sin(yaw);
  return rest.map(([x, y, z]) => [c * x + s * z + dx, y, -s * x + c * z + dz] as Vec3);
}

function width(people: Vec3[][]): number {
  const t = thumbnail(people, parents);
  const xs = t.lines.flatMap((l) => [l.x1, l.x2]);
  return Math.max(...xs) - Math.min(...xs);
}

describe("thumbnail", () => {
  it("draws every bone of every person, head up", () => {
    const t = thumbnail([rest, posed(0, 1.2)], parents);
    expect(t.lines).toHaveLength(2 * 21);
    expect(new Set(t.lines.map((l) => l.person))).toEqual(new Set([0, 1]));
    // SVG y grows downwards: the head (joint 15) above the feet (10, 11)
    // (line j − 1 starts at joint j of person 0: the root has no bone)
    const y = (j: number) => t.lines[j - 1].y1;
    expect(y(15)).toBeLessThan(y(10) - 1);
    const [x, yy, w, h] = t.viewBox.split(" ").map(Number);
    for (const l of t.lines) {
      expect(l.x1).toBeGreaterThanOrEqual(x);
      expect(l.x1).toBeLessThanOrEqual(x + w);
      expect(l.y1).toBeGreaterThanOrEqual(yy);
      expect(l.y1).toBeLessThanOrEqual(yy + h);
    }
  });
  it("turns the person to face the viewer whichever way they face", () => {
    const front = width([rest]);
    for (const yaw of [Math.PI / 2, Math.PI, -2.2]) expect(width([posed(yaw, 3, -4)])).toBeCloseTo(front, 6);
  });
  it("shows two people side by side, whichever way the pair stands", () => {
    for (const yaw of [0, Math.PI / 2, 2.5]) {
      // facing each other 1.2 m apart along the pair's own axis, turned by yaw
      const c = Math.cos(yaw), s = Math.sin(yaw);
      const a = posed(yaw, 0, 0);
      const b = posed(yaw + Math.PI, 1.2 * s, 1.2 * c);
      const t = thumbnail([a, b], parents);
      const mid = (p: number) => {
        const xs = t.lines.filter((l) => l.person === p).flatMap((l) => [l.x1, l.x2]);
        return (Math.min(...xs) + Math.max(...xs)) / 2;
      };
      expect(mid(1) - mid(0)).toBeCloseTo(1.2, 1);
    }
  });
  it("copes with no people", () => {
    expect(thumbnail([], parents)).toEqual({ lines: [], viewBox: "-1 -2 2 2" });
  });
});

describe("ago", () => {
  const now = Date.parse("2026-12-01T12:00:00Z");
  it("says how long ago, coarsely", () => {
    expect(ago("2026-12-01T11:59:30Z", now)).toBe("just now");
    expect(ago("2026-12-01T11:55:00Z", now)).toBe("5 min ago");
    expect(ago("2026-12-01T09:00:00Z", now)).toBe("3 h ago");
    expect(ago(null, now)).toBe("");
    expect(ago("nonsense", now)).toBe("");
  });
});
