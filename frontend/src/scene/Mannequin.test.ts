import * as THREE from "three";
import { describe, expect, it } from "vitest";
import type { Skeleton } from "../api/types";
import skeletonJson from "../test/skeleton.json";
import { debugFlags } from "./debugFlags";
import { HOVER_COLOUR, Mannequin } from "./Mannequin";
import { QUALITY } from "./quality";

const skeleton = skeletonJson as unknown as Skeleton;
const rest = new Float32Array(skeletonJson.rest.flat());
const LEFT_ELBOW = skeleton.joints.indexOf("left_elbow");
const LEFT_WRIST = skeleton.joints.indexOf("left_wrist");

/** The joint a ray from in front (+z, looking down -z) through (x, y) picks, or null. */
function pickAt(m: Mannequin, x: number, y: number): number | null {
  m.group.updateMatrixWorld(true);
  const ray = new THREE.Raycaster(new THREE.Vector3(x, y, 5), new THREE.Vector3(0, 0, -1));
  const hit = ray.intersectObjects(m.pickable, false)[0];
  return hit?.face ? (hit.object.userData.vertexJoint as Uint8Array)[hit.face.a] : null;
}

describe("Mannequin (one merged mesh)", () => {
  it("draws a person as one mesh and picks the joint under a ray", () => {
    const m = new Mannequin(skeleton, 0, QUALITY.full);
    m.setPose(rest, new Set());
    expect(m.pickable).toHaveLength(1);
    const [x, y] = [rest[3 * LEFT_ELBOW], rest[3 * LEFT_ELBOW + 1]];
    expect(pickAt(m, x, y)).toBe(LEFT_ELBOW);
    // the forearm between elbow and wrist is the bone ending at the wrist
    const mid = [0, 1].map((k) => (rest[3 * LEFT_ELBOW + k] + rest[3 * LEFT_WRIST + k]) / 2);
    expect(pickAt(m, mid[0], mid[1])).toBe(LEFT_WRIST);
    // after a new pose the bounds follow: the same joint 3 m to the side is picked there
    const moved = rest.map((v, i) => (i % 3 === 0 ? v + 3 : v));
    m.setPose(moved, new Set());
    expect(pickAt(m, x + 3, y)).toBe(LEFT_ELBOW);
    expect(pickAt(m, x, y)).toBeNull();
    m.dispose();
  });

  it("light quality: under 1,000 shared vertices per person, still picking joint and bone", () => {
    // (shadowMap on: no blob shadows, which need a canvas; the tessellation is light quality's)
    const m = new Mannequin(skeleton, 0, { ...QUALITY.light, shadowMap: true });
    m.setPose(rest, new Set());
    const geometry = (m.pickable[0] as THREE.Mesh).geometry;
    expect(geometry.getAttribute("position").count).toBeLessThan(1000);
    const [x, y] = [rest[3 * LEFT_ELBOW], rest[3 * LEFT_ELBOW + 1]];
    expect(pickAt(m, x, y)).toBe(LEFT_ELBOW);
    const mid = [0, 1].map((k) => (rest[3 * LEFT_ELBOW + k] + rest[3 * LEFT_WRIST + k]) / 2);
    expect(pickAt(m, mid[0], mid[1])).toBe(LEFT_WRIST);
    // every vertex's normal is a unit vector (welding kept the shapes' normals)
    const n = geometry.getAttribute("normal");
    for (let k = 0; k < n.count; k += 7) expect(Math.hypot(n.getX(k), n.getY(k), n.getZ(k))).toBeCloseTo(1, 3);
    m.dispose();
  });

  it("paints hovered joints and contact joints per instance", () => {
    const m = new Mannequin(skeleton, 1, QUALITY.full);
    m.hovered = new Set([LEFT_ELBOW]);
    m.setPose(rest, new Set([LEFT_WRIST]));
    expect(m.jointPaint(LEFT_ELBOW).colour).toBe(HOVER_COLOUR);
    expect(m.jointPaint(LEFT_WRIST)).toEqual({ colour: "#39ff88", glow: expect.any(Number) });
    expect(m.jointPaint(LEFT_WRIST).glow).toBeGreaterThan(0);
    expect(m.jointPaint(0).glow).toBe(0);
    m.hovered = new Set();
    m.setPose(rest, new Set());
    expect(m.jointPaint(LEFT_ELBOW).colour).not.toBe(HOVER_COLOUR);
    expect(m.jointPaint(LEFT_WRIST).glow).toBe(0);
    m.dispose();
  });
});

describe("debug flags", () => {
  it("reads ?hide= and ?pixelRatio=, ignoring bad values", () => {
    expect(debugFlags("?hide=ground,people&pixelRatio=0.5")).toEqual({
      hide: new Set(["ground", "people"]), pixelRatio: 0.5, dynamicResolution: false, alpha: false, tess: null, detail: null, skinning: null,
    });
    expect(debugFlags("?pixelRatio=-1")).toEqual({ hide: new Set(), pixelRatio: null, dynamicResolution: true, alpha: false, tess: null, detail: null, skinning: null });
    expect(debugFlags("")).toEqual({ hide: new Set(), pixelRatio: null, dynamicResolution: true, alpha: false, tess: null, detail: null, skinning: null });
    expect(debugFlags("?tess=8x6,8,6x4,6").tess).toEqual([8, 6, 8, 6, 4, 6]);
    expect(debugFlags("?tess=old").tess).toBe("old");
    expect(debugFlags("?tess=8x6,8").tess).toBeNull();
    expect(debugFlags("?dynres=0&alpha=1")).toMatchObject({ dynamicResolution: false, alpha: true });
    expect(debugFlags("?detail=full").detail).toBe("full");
    expect(debugFlags("?detail=0.3").detail).toBeNull();
    expect(debugFlags("?skin=gpu").skinning).toBe("gpu");
  });
});
