import { describe, expect, it } from "vitest";
import { skeleton, rest } from "../test/fixtures";
import rigData from "../test/rig.json";
import { NUM_SPHERES, TEMPLATE_SIZE, bodyScale, placeSpheres, sizeOf, sphereLayout } from "./sphereBody";

// Reference values from the backend (interplay.motion.pair.body), computed with
// `.venv/bin/python` on the same fixtures: body_spheres(rest[None]).centres[0, s] and .radii[s],
// body_scale of the rig fixture's squat, body_spheres(squat).centres[3, 30], _TEMPLATE_SIZE.
const PYTHON_REST: [number, [number, number, number], number][] = [
  [0, [0.0293, 0.90885, -0.00885], 0.1], // pelvis → left hip
  [7, [-0.00479, 1.44826, -0.037175], 0.06], // spine3 → neck at 0.85 (the neck)
  [20, [0.0947, 0.26775, -0.0284], 0.05], // left knee → ankle at 0.5 (the shank)
  [44, [-0.79953, 1.42224, -0.08], 0.045], // right elbow → wrist at 1.3 (the hand)
];
const PYTHON_SQUAT_SCALE = 0.9999698165705343;
const PYTHON_SQUAT_F3_S30: [number, number, number] = [-0.19025, 0.067425, -0.0973];

const flat = (frames: number[][][]) => Float32Array.from(frames.flat(2));

describe("the 45-sphere body (as body.py)", () => {
  const layout = sphereLayout(skeleton);

  it("has body.py's 45 spheres and template size", () => {
    expect(layout.radius.length).toBe(NUM_SPHERES);
    expect(sizeOf(flat([rest]), 0, layout.sizeBones)).toBeCloseTo(TEMPLATE_SIZE, 5);
    expect(bodyScale(layout, flat([rest]), 1)).toBeCloseTo(1, 5);
  });

  it("places the spheres where the Python function does", () => {
    const out = placeSpheres(layout, flat([rest]), 1, new Float32Array(NUM_SPHERES * 4));
    for (const [s, centre, radius] of PYTHON_REST) {
      centre.forEach((v, k) => expect(out[4 * s + k], `sphere ${s}[${k}]`).toBeCloseTo(v, 5));
      expect(out[4 * s + 3]).toBeCloseTo(radius, 6);
    }
  });

  it("scales by the person's size: the median over frames, clipped to [0.5, 1.5]", () => {
    const squat = rigData.people[0].joints as number[][][];
    const joints = flat(squat);
    const scale = bodyScale(layout, joints, squat.length);
    expect(scale).toBeCloseTo(PYTHON_SQUAT_SCALE, 5);
    const out = placeSpheres(layout, joints.subarray(3 * 66, 4 * 66), scale, new Float32Array(NUM_SPHERES * 4));
    PYTHON_SQUAT_F3_S30.forEach((v, k) => expect(out[4 * 30 + k]).toBeCloseTo(v, 5));
    expect(out[4 * 30 + 3]).toBeCloseTo(0.04 * PYTHON_SQUAT_SCALE, 6);
    // a giant and a child are clipped
    expect(bodyScale(layout, flat([rest.map(([x, y, z]) => [3 * x, 3 * y, 3 * z])]), 1)).toBe(1.5);
    expect(bodyScale(layout, flat([rest.map(([x, y, z]) => [0.2 * x, 0.2 * y, 0.2 * z])]), 1)).toBe(0.5);
  });
});
