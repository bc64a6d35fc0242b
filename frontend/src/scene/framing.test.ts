import * as THREE from "three";
import { describe, expect, it } from "vitest";
import { rest, skeleton } from "../test/fixtures";
import { FIT_MARGIN, SIDE_CLEAR, facing, fitView, groupFrame, pairSideTurn, viewDirection, type Vec3 } from "./framing";
import { NUM_SPHERES, placeSpheres, sphereLayout } from "./sphereBody";

const LH = skeleton.joints.indexOf("left_hip");
const RH = skeleton.joints.indexOf("right_hip");
const layout = sphereLayout(skeleton);

/** The rest pose (facing +Z) turned by `yaw` (radians, about +Y) and moved to (x, z). */
function pose(yaw: number, x: number, z: number): Float32Array {
  const c = Math.cos(yaw), s = Math.sin(yaw);
  return Float32Array.from(rest.flatMap(([px, py, pz]) => [c * px + s * pz + x, py, -s * px + c * pz + z]));
}

/** Two people facing each other `gap` m apart (pelvis to pelvis) on a line at `angle` from +X. */
function facingPair(gap: number, angle: number): Float32Array[] {
  const [dx, dz] = [Math.cos(angle) * gap / 2, Math.sin(angle) * gap / 2];
  const towards = (fx: number, fz: number) => Math.atan2(fx, fz); // the yaw that faces (fx, fz)
  return [pose(towards(dx, dz), -dx, -dz), pose(towards(-dx, -dz), dx, dz)];
}

const spheres = (poses: Float32Array[]) => {
  const out = new Float32Array(poses.length * NUM_SPHERES * 4);
  poses.forEach((p, k) => placeSpheres(layout, p, 1, out.subarray(k * NUM_SPHERES * 4, (k + 1) * NUM_SPHERES * 4)));
  return out;
};

/** Each pose's projected box (NDC x and y ranges) of its joints and sphere silhouettes seen
 * from a camera at the fit, as three projects them. */
function boxes(poses: Float32Array[], position: Vec3, target: Vec3, aspect: number) {
  const camera = new THREE.PerspectiveCamera(40, aspect, 0.05, 200);
  camera.position.set(...position);
  camera.lookAt(...target);
  camera.updateMatrixWorld();
  const right = new THREE.Vector3().setFromMatrixColumn(camera.matrixWorld, 0);
  const up = new THREE.Vector3().setFromMatrixColumn(camera.matrixWorld, 1);
  return poses.map((p) => {
    const s = spheres([p]);
    const box = { x: [Infinity, -Infinity], y: [Infinity, -Infinity] };
    for (let i = 0; i < s.length; i += 4) {
      const c = new THREE.Vector3(s[i], s[i + 1], s[i + 2]);
      for (const [axis, sign] of [[right, 1], [right, -1], [up, 1], [up, -1]] as const) {
        const v = c.clone().addScaledVector(axis, sign * s[i + 3]).project(camera);
        box.x = [Math.min(box.x[0], v.x), Math.max(box.x[1], v.x)];
        box.y = [Math.min(box.y[0], v.y), Math.max(box.y[1], v.y)];
      }
    }
    return box;
  });
}

describe("framing the people", () => {
  it("reads a pose's facing from its hips", () => {
    expect(facing(pose(0, 0, 0), LH, RH).map((v) => +v.toFixed(3))).toEqual([0.035, 0.999]);
    const [fx, fz] = facing(pose(Math.PI / 2, 0, 0), LH, RH); // turned to face +X
    expect(fx).toBeCloseTo(1, 2);
    expect(Math.abs(fz)).toBeLessThan(0.04); // (the rest pose's hips are 2° off square)
  });

  for (const angle of [0, Math.PI / 2, 0.6, -2.2]) {
    for (const aspect of [16 / 9, 1.1]) {
      it(`sees a facing pair 1.5 m apart from the side of their line (${angle.toFixed(1)} rad, aspect ${aspect.toFixed(2)}): both inside the view, apart`, () => {
        const pair = facingPair(1.5, angle);
        const g = groupFrame(pair, LH, RH);
        const line = [Math.cos(angle), Math.sin(angle)];
        expect(g.pair).toBe(true);
        expect(Math.abs(g.front[0] * line[0] + g.front[1] * line[1])).toBeLessThan(1e-6); // ⟂ the line
        const dir = viewDirection("default", g);
        const fit = fitView(dir, spheres(pair), 40, aspect);
        const [a, b] = boxes(pair, fit.position, fit.target, aspect);
        // inside the view, and off the bottom band the legend covers (with a little slack:
        // parts nearer than the middle are drawn larger)
        for (const box of [a, b]) {
          expect(box.x[0]).toBeGreaterThan(-1);
          expect(box.x[1]).toBeLessThan(1);
          expect(box.y[1]).toBeLessThan(1 - FIT_MARGIN.top + 0.05);
          expect(box.y[0]).toBeGreaterThan(-1 + FIT_MARGIN.bottom - 0.05);
        }
        // Person 1 on the left, Person 2 on the right, with a gap between their boxes
        expect(b.x[0] - a.x[1]).toBeGreaterThan(0.1);
        // and not far: the group fills most of the free window on one axis (the T-posed arms
        // reach 0.8 m towards and away from the camera, so it stands back 1.5 × that depth)
        const width = (b.x[1] - a.x[0]) / (2 * (1 - FIT_MARGIN.side));
        const height = (Math.max(a.y[1], b.y[1]) - Math.min(a.y[0], b.y[0])) / (2 - FIT_MARGIN.top - FIT_MARGIN.bottom);
        expect(Math.max(width, height)).toBeGreaterThan(0.6);
      });
    }
  }

  it("would hide one person behind the other looking along their line (the old default)", () => {
    const pair = facingPair(1.5, 0.6);
    const dir: Vec3 = [Math.cos(0.6), 0.25, Math.sin(0.6)];
    const fit = fitView(dir, spheres(pair), 40, 16 / 9);
    const [a, b] = boxes(pair, fit.position, fit.target, 16 / 9);
    expect(Math.min(a.x[1], b.x[1]) - Math.max(a.x[0], b.x[0])).toBeGreaterThan(0); // overlapping
  });

  it("gives one person a 3/4 view from their front, as the old default for +Z", () => {
    const g = groupFrame([pose(0, 0, 0)], LH, RH);
    const [x, y, z] = viewDirection("default", g);
    const old = new THREE.Vector3(0.42, 0.3, 1).normalize();
    expect(x * old.x + y * old.y + z * old.z).toBeGreaterThan(0.99);
    // turned to face -X, the view turns with them
    const [tx, , tz] = viewDirection("default", groupFrame([pose(-Math.PI / 2, 2, 1)], LH, RH));
    expect(tx).toBeLessThan(-0.8);
    expect(Math.abs(tz)).toBeLessThan(0.45);
  });

  it("has front, side and top presets in the group's frame", () => {
    const pair = facingPair(1.5, 0);
    const g = groupFrame(pair, LH, RH);
    const front = viewDirection("front", g);
    const side = viewDirection("side", g);
    const top = viewDirection("top", g);
    expect(Math.abs(front[0])).toBeLessThan(1e-6); // the pair's line is X: the front is ±Z
    // from Person 2's end (+X), turned off the line towards the front: both apart (below)
    expect(side[0]).toBeGreaterThan(0.4);
    expect(Math.abs(side[0])).toBeLessThan(0.9);
    expect(top[1]).toBeGreaterThan(0.999);
    // both face -Z (side by side, say): the front view looks at their faces
    const both = [pose(Math.PI, -0.4, 0), pose(Math.PI, 0.4, 0)];
    expect(viewDirection("front", groupFrame(both, LH, RH))[2]).toBeLessThan(-0.9);
  });

  // issue 26: the side view looked exactly along a pair's line, one person behind the other
  const UPPER = ["pelvis", "spine1", "spine2", "spine3", "neck", "head", "left_shoulder", "right_shoulder", "left_hip", "right_hip"].map((n) => skeleton.joints.indexOf(n));
  /** Each pose's projected x range (NDC) of its trunk, head and shoulders. */
  function trunkX(poses: Float32Array[], fit: { position: Vec3; target: Vec3 }, aspect: number): [number, number][] {
    const camera = new THREE.PerspectiveCamera(40, aspect, 0.05, 200);
    camera.position.set(...fit.position);
    camera.lookAt(...fit.target);
    camera.updateMatrixWorld();
    return poses.map((p) => {
      const xs = UPPER.map((j) => new THREE.Vector3(p[3 * j], p[3 * j + 1], p[3 * j + 2]).project(camera).x);
      return [Math.min(...xs), Math.max(...xs)];
    });
  }
  for (const gap of [0.7, 1, 1.5]) {
    for (const angle of [0, 2.1]) {
      it(`the side view frames both of a pair ${gap} m apart, apart on screen (line at ${angle} rad)`, () => {
        const pair = facingPair(gap, angle);
        const g = groupFrame(pair, LH, RH);
        expect(g.span).toBeCloseTo(gap, 6);
        const dir = viewDirection("side", g);
        const line = [Math.cos(angle), Math.sin(angle)];
        const along = (dir[0] * line[0] + dir[2] * line[1]) / Math.hypot(dir[0], dir[2]);
        expect(along).toBeGreaterThan(Math.cos(pairSideTurn(gap)) - 1e-6); // from Person 2's end
        expect(along).toBeLessThan(Math.cos((30 * Math.PI) / 180) + 1e-6); // never along the line
        const fit = fitView(dir, spheres(pair), 40, 16 / 9);
        const [a, b] = trunkX(pair, fit, 16 / 9);
        expect(Math.max(b[0] - a[1], a[0] - b[1]), "trunks apart on screen").toBeGreaterThan(0);
        // the old side view, along the line: one trunk covered the other
        const old: Vec3 = [line[0] * 0.99, 0.14, line[1] * 0.99];
        const [c, d] = trunkX(pair, fitView(old, spheres(pair), 40, 16 / 9), 16 / 9);
        expect(Math.min(c[1], d[1]) - Math.max(c[0], d[0])).toBeGreaterThan(0);
      });
    }
  }

  it("turns the side view just enough: 30° for a pair far apart, up to 65° for a close one", () => {
    expect(pairSideTurn(3)).toBeCloseTo((30 * Math.PI) / 180, 6);
    expect(Math.sin(pairSideTurn(0.8)) * 0.8).toBeCloseTo(SIDE_CLEAR, 6);
    expect(pairSideTurn(0.3)).toBeCloseTo((65 * Math.PI) / 180, 6);
    // one person: the side view is their left, level
    const one = viewDirection("side", groupFrame([pose(0, 0, 0)], LH, RH));
    expect(Math.abs(one[0])).toBeGreaterThan(0.98);
  });

  it("stands far enough back for a spread group and never closer than the minimum", () => {
    const near = fitView([0, 0, 1], spheres([pose(0, 0, 0)]), 40, 16 / 9);
    const far = fitView([0, 0, 1], spheres(facingPair(4, 0)), 40, 16 / 9);
    expect(far.distance).toBeGreaterThan(near.distance + 1);
    expect(fitView([0, 0, 1], Float32Array.of(0, 1, 0, 0.01), 40, 1, 0.8).distance).toBe(0.8);
  });

  it("looks down from far enough that the heads are not drawn much larger than the feet", () => {
    const pair = facingPair(1.5, 0.3);
    const fit = fitView(viewDirection("top", groupFrame(pair, LH, RH)), spheres(pair), 40, 16 / 9);
    const head = fit.position[1] - 1.7;
    const feet = fit.position[1] - 0.05;
    expect(feet / head).toBeLessThan(2);
  });
});
