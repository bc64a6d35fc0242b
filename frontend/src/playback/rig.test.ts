import { Quaternion, Vector3 } from "three";
import { describe, expect, it } from "vitest";
import rigJson from "../test/rig.json";
import { rest as restPose, skeleton } from "../test/fixtures";
import { NUM_JOINTS } from "./frameBuffer";
import { fitPositions, parseRig, restJoints, sampleRig, vertexJoints, type RigPerson } from "./rig";

const J = (name: string) => skeleton.joints.indexOf(name);
const rig = parseRig("m", rigJson);
const person = rig.people[0];
const joints = rigJson.people[0].joints;

/** Joint positions (22 × xyz) of a pose by forward kinematics: the root, then each joint its
 * parent's position plus the parent's global rotation of its offset. */
function fk(p: RigPerson, quats: Float32Array, root: Float32Array): number[][] {
  const glob: Quaternion[] = [];
  const pos: Vector3[] = [];
  for (let j = 0; j < NUM_JOINTS; j++) {
    const q = new Quaternion().fromArray(quats, 4 * j);
    const parent = skeleton.parents[j];
    if (parent < 0) {
      glob[j] = q;
      pos[j] = new Vector3().fromArray(root);
    } else {
      glob[j] = glob[parent].clone().multiply(q);
      pos[j] = new Vector3().fromArray(p.offsets, 3 * j).applyQuaternion(glob[parent]).add(pos[parent]);
    }
  }
  return pos.map((v) => v.toArray());
}

function sample(p: RigPerson, t: number, next = t, weight = 0) {
  const quats = new Float32Array(NUM_JOINTS * 4);
  const root = new Float32Array(3);
  sampleRig(p, t, next, weight, quats, root);
  return { quats, root };
}

describe("the rig of a version-2 Motion JSON", () => {
  it("reads offsets, root and rotations, the quaternions reordered to three's x, y, z, w", () => {
    expect(rig.frames).toBe(rigJson.frames.length);
    expect(rig.people).toHaveLength(1);
    expect(person.offsets).toHaveLength(66);
    expect(person.root).toHaveLength(3 * rig.frames);
    const [w, x, y, z] = rigJson.people[0].rig.rotations[3][J("left_knee")];
    const o = (3 * NUM_JOINTS + J("left_knee")) * 4;
    expect(Array.from(person.rotations.subarray(o, o + 4))).toEqual([x, y, z, w].map(Math.fround));
  });

  it("refuses a version-1 file and a misshapen rig", () => {
    expect(() => parseRig("m", { people: [{ joints: [] }] })).toThrow(/schema/);
    const bad = structuredClone(rigJson) as { people: { rig: { rotations: unknown[] } }[] };
    bad.people[0].rig.rotations.pop();
    expect(() => parseRig("m", bad)).toThrow(/wrong size/);
  });

  it("gives the motion's joints back by forward kinematics at every frame (within 1 mm)", () => {
    let worst = 0;
    for (let t = 0; t < rig.frames; t++) {
      const { quats, root } = sample(person, t);
      const got = fk(person, quats, root);
      got.forEach((xyz, j) => xyz.forEach((v, k) => (worst = Math.max(worst, Math.abs(v - joints[t][j][k])))));
    }
    expect(worst).toBeLessThan(1e-3);
  });
});

describe("sampling the rig at the playback clock", () => {
  it("weight 0 is the frame exactly; in between, the root is lerped and each rotation slerped", () => {
    const a = sample(person, 1);
    expect(Array.from(a.root)).toEqual(Array.from(person.root.subarray(3, 6)));
    // frames 5 → 6 of the fixture: rising from the squat (the knees turn by tens of degrees)
    const mid = sample(person, 5, 6, 0.25);
    for (let k = 0; k < 3; k++) expect(mid.root[k]).toBeCloseTo(person.root[15 + k] + 0.25 * (person.root[18 + k] - person.root[15 + k]), 6);
    for (const name of ["left_knee", "right_hip", "pelvis", "spine3"]) {
      const j = J(name);
      const q0 = new Quaternion().fromArray(person.rotations, (5 * NUM_JOINTS + j) * 4);
      const q1 = new Quaternion().fromArray(person.rotations, (6 * NUM_JOINTS + j) * 4);
      const q = new Quaternion().fromArray(mid.quats, 4 * j);
      expect(q.length()).toBeCloseTo(1, 6);
      // (components, not angleTo: acos near 1 magnifies float32 rounding)
      const want = new Quaternion().slerpQuaternions(q0, q1, 0.25);
      const sign = Math.sign(q.dot(want));
      q.toArray().forEach((v, k) => expect(v).toBeCloseTo(sign * want.toArray()[k], 5));
      // a quarter of the way along the arc
      if (name === "left_knee") expect(q0.angleTo(q1)).toBeGreaterThan(0.3);
      expect(q0.angleTo(q)).toBeCloseTo(0.25 * q0.angleTo(q1), 2);
    }
  });

  it("takes the shorter arc: q and -q are one rotation, no flip in between", () => {
    const q = new Quaternion().setFromAxisAngle(new Vector3(1, 0, 0), 1.2);
    const rotations = new Float32Array(2 * NUM_JOINTS * 4);
    for (let j = 0; j < NUM_JOINTS; j++) {
      q.toArray(rotations, 4 * j);
      rotations.set([-q.x, -q.y, -q.z, -q.w], (NUM_JOINTS + j) * 4);
    }
    const p: RigPerson = { offsets: person.offsets, root: new Float32Array(6), rotations };
    const { quats } = sample(p, 0, 1, 0.5);
    expect(new Quaternion().fromArray(quats, 0).angleTo(q)).toBeLessThan(1e-6);
  });

  it("a blended pose lies between the two frames' poses", () => {
    const { quats, root } = sample(person, 4, 5, 0.5);
    const got = fk(person, quats, root);
    const wrist = J("left_wrist");
    const a = new Vector3(...joints[4][wrist]);
    const b = new Vector3(...joints[5][wrist]);
    const m = new Vector3(...got[wrist]);
    // no farther from either end than the two frames are apart
    expect(m.distanceTo(a)).toBeLessThanOrEqual(a.distanceTo(b) + 1e-3);
    expect(m.distanceTo(b)).toBeLessThanOrEqual(a.distanceTo(b) + 1e-3);
  });
});

describe("fitting the mesh to a person's bones", () => {
  it("rest joints chain the offsets from the root", () => {
    const rest = restJoints(person.offsets, skeleton.parents);
    const wrist = J("left_wrist");
    let sum = [0, 0, 0];
    for (let j = wrist; j >= 0; j = skeleton.parents[j]) sum = sum.map((s, k) => s + person.offsets[3 * j + k]);
    sum.forEach((s, k) => expect(rest[3 * wrist + k]).toBeCloseTo(s, 6));
  });

  it("moves each vertex by its joints' weighted change of rest position", () => {
    // the template skeleton's offsets: each rest joint minus its parent's
    const offsets = restPose.flatMap((xyz, j) => xyz.map((v, k) => v - (skeleton.parents[j] >= 0 ? restPose[skeleton.parents[j]][k] : 0)));
    const template = restJoints(offsets, skeleton.parents);
    restPose.flat().forEach((v, i) => expect(template[i]).toBeCloseTo(v, 5));
    const rest = restJoints(person.offsets, skeleton.parents);
    const [knee, ankle] = [J("left_knee"), J("left_ankle")];
    // one vertex all on the knee, one halfway between knee and ankle
    const positions = new Float32Array([0.1, 0.5, 0, 0.1, 0.3, 0]);
    const skinIndex = new Uint8Array([knee, 0, 0, 0, knee, ankle, 0, 0]);
    const skinWeight = new Float32Array([1, 0, 0, 0, 0.5, 0.5, 0, 0]);
    const out = fitPositions(positions, skinIndex, skinWeight, template, rest);
    for (let k = 0; k < 3; k++) {
      expect(out[k]).toBeCloseTo(positions[k] + rest[3 * knee + k] - template[3 * knee + k], 6);
      const half = 0.5 * (rest[3 * knee + k] - template[3 * knee + k]) + 0.5 * (rest[3 * ankle + k] - template[3 * ankle + k]);
      expect(out[3 + k]).toBeCloseTo(positions[3 + k] + half, 6);
    }
    // the template's own skeleton leaves the mesh as it is
    expect(Array.from(fitPositions(positions, skinIndex, skinWeight, template, template))).toEqual(Array.from(positions));
  });

  it("names each vertex's strongest joint and the bone it lies on, as the mannequin does", () => {
    const [pelvis, rhip, knee, ankle, wrist, elbow] = ["pelvis", "right_hip", "left_knee", "left_ankle", "left_wrist", "left_elbow"].map(J);
    const skinIndex = new Uint8Array([
      knee, ankle, 0, 0, // knee strongest: the shin (the bone ending at the ankle)
      pelvis, rhip, 0, 0, // pelvis, leaning to the right hip: the bone ending there
      pelvis, 0, 0, 0, // the pelvis alone: itself
      elbow, wrist, 0, 0, // the wrist strongest, a leaf: itself
    ]);
    const skinWeight = new Float32Array([0.7, 0.3, 0, 0, 0.6, 0.4, 0, 0, 1, 0, 0, 0, 0.2, 0.8, 0, 0]);
    const { joint, bone } = vertexJoints(skinIndex, skinWeight, skeleton.parents);
    expect(Array.from(joint)).toEqual([knee, pelvis, pelvis, wrist]);
    expect(Array.from(bone)).toEqual([ankle, rhip, pelvis, wrist]);
  });

  it("keeps the chest on the trunk's bone when the joint names are given (no collar bleed)", () => {
    const [spine3, neck, rcollar, pelvis, rhip] = ["spine3", "neck", "right_collar", "pelvis", "right_hip"].map(J);
    const skinIndex = new Uint8Array([spine3, rcollar, 0, 0, pelvis, rhip, 0, 0]);
    const skinWeight = new Float32Array([0.6, 0.4, 0, 0, 0.6, 0.4, 0, 0]);
    // without names, the heaviest child: the chest vertex lies on the right collar's bone (the arm's)
    expect(Array.from(vertexJoints(skinIndex, skinWeight, skeleton.parents).bone)).toEqual([rcollar, rhip]);
    // with them, the trunk's (neck); the root still takes its heaviest child (the leg's)
    expect(Array.from(vertexJoints(skinIndex, skinWeight, skeleton.parents, skeleton.joints).bone)).toEqual([neck, rhip]);
  });
});
