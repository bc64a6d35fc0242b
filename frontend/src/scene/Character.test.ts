import { readFileSync } from "node:fs";
import * as THREE from "three";
import { beforeAll, describe, expect, it } from "vitest";
import rigJson from "../test/rig.json";
import { skeleton } from "../test/fixtures";
import { parseRig } from "../playback/rig";
import { Character, parseHumanoid, type HumanoidTemplate } from "./Character";
import { CONTACT_COLOUR, PENETRATION_COLOUR, jointColours } from "./colours";
import { QUALITY } from "./quality";
import { SELECT_COLOUR } from "./Mannequin";

const J = (name: string) => skeleton.joints.indexOf(name);
const rig = parseRig("m", rigJson);
const person = rig.people[0];
const joints = rigJson.people[0].joints;
let template: HumanoidTemplate;

beforeAll(async () => {
  const b = readFileSync(new URL("../../public/humanoid.glb", import.meta.url));
  template = await parseHumanoid(b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength));
});

/** The skinned vertices of the character's body now (world space). */
function skinned(c: Character): Float32Array {
  c.group.updateMatrixWorld(true);
  c.mesh.skeleton.update();
  const n = c.mesh.geometry.getAttribute("position").count;
  const out = new Float32Array(3 * n);
  const v = new THREE.Vector3();
  for (let i = 0; i < n; i++) c.mesh.getVertexPosition(i, v).applyMatrix4(c.mesh.matrixWorld).toArray(out, 3 * i);
  return out;
}

function make(p = 0): Character {
  return new Character(template, skeleton, p, person.offsets, QUALITY.light);
}

describe("the skinned character (humanoid.glb, cloned per person)", () => {
  it("poses its bones on the server's rotations: the joints come back within 1 mm", () => {
    const c = make();
    let worst = 0;
    const v = new THREE.Vector3();
    for (let t = 0; t < rig.frames; t++) {
      c.setPose(person, t, t, 0, new Set());
      c.group.updateMatrixWorld(true);
      for (let j = 0; j < 22; j++) {
        c.jointPosition(j, v).toArray().forEach((x, k) => (worst = Math.max(worst, Math.abs(x - joints[t][j][k]))));
      }
    }
    expect(worst).toBeLessThan(1e-3);
    c.dispose();
  });

  it("skins on the CPU (light quality) exactly as the vertex shader would", () => {
    const gpu = make();
    const cpu = new Character(template, skeleton, 0, person.offsets, QUALITY.light, true);
    expect(cpu.pickable[0]).not.toBe(cpu.mesh); // a plain mesh is drawn
    expect((cpu.pickable[0] as THREE.Mesh).isMesh && !(cpu.pickable[0] as THREE.SkinnedMesh).isSkinnedMesh).toBe(true);
    let worst = 0;
    for (const [t, next, w] of [[3, 3, 0], [5, 6, 0.4], [9, 9, 0]]) {
      gpu.setPose(person, t, next, w, new Set());
      cpu.setPose(person, t, next, w, new Set());
      const want = skinned(gpu);
      const got = (cpu.pickable[0] as THREE.Mesh).geometry.getAttribute("position").array;
      want.forEach((x, i) => (worst = Math.max(worst, Math.abs(x - got[i]))));
    }
    expect(worst).toBeLessThan(1e-5);
    // and a ray picks on it as on the skinned one
    cpu.setPose(person, 9, 9, 0, new Set());
    const [x, y, z] = joints[9][J("left_knee")];
    const hit = new THREE.Raycaster(new THREE.Vector3(x, y + 0.08, z + 3), new THREE.Vector3(0, 0, -1)).intersectObjects(cpu.pickable, false)[0];
    expect(["left_knee", "left_ankle"]).toContain(skeleton.joints[(hit!.object.userData.vertexJoint as Uint8Array)[hit!.face!.a]]);
    gpu.dispose();
    cpu.dispose();
  });

  it("is fitted to the person's bones: in the rest pose every vertex keeps its place relative to its joints", () => {
    // the fixture's person is shorter than the template (pelvis 0.87 vs 0.96 m): the mesh's bind
    // pose moves with the joints, so at rest the feet are still at the ankles, the head at the head
    const c = make();
    const rest = new Float32Array(22 * 4);
    for (let j = 0; j < 22; j++) rest[4 * j + 3] = 1;
    const still = { offsets: person.offsets, root: person.offsets.slice(0, 3), rotations: rest };
    c.setPose(still, 0, 0, 0, new Set());
    const verts = skinned(c);
    const bind = c.mesh.geometry.getAttribute("position").array;
    // the rest pose is the fitted bind pose
    expect(verts.reduce((worst, x, i) => Math.max(worst, Math.abs(x - bind[i])), 0)).toBeLessThan(1e-4);
    const ys = verts.filter((_, i) => i % 3 === 1);
    const lowest = Math.min(...ys);
    const ankle = restY(J("left_ankle"));
    const head = restY(J("head"));
    expect(lowest).toBeLessThan(ankle); // the soles below the ankles…
    expect(lowest).toBeGreaterThan(ankle - 0.15); // …not below where the template's are
    expect(Math.max(...ys)).toBeGreaterThan(head); // the crown above the head joint
    expect(Math.max(...ys)).toBeLessThan(head + 0.25);
    c.dispose();
  });

  it("moves with the motion: the skin follows the squat and the rise", () => {
    const c = make();
    const heights: number[] = [];
    for (const t of [3, 7]) {
      c.setPose(person, t, t, 0, new Set());
      const ys = skinned(c).filter((_, i) => i % 3 === 1);
      heights.push(Math.max(...ys));
    }
    // frame 3 squats (pelvis at 0.22 m), frame 7 stands (1.05 m): the top of the head follows
    const pelvis = [joints[3][0][1], joints[7][0][1]];
    expect(heights[1] - heights[0]).toBeGreaterThan(0.6 * (pelvis[1] - pelvis[0]));
    c.dispose();
  });

  it("faces the way the joints do: each foot's skin points from the heel to the toes", () => {
    const c = make();
    const strongest = (v: number) => {
      const w = c.mesh.geometry.getAttribute("skinWeight");
      const idx = c.mesh.geometry.getAttribute("skinIndex");
      let best = 0;
      for (let k = 1; k < 4; k++) if (w.getComponent(v, k) > w.getComponent(v, best)) best = k;
      return idx.getComponent(v, best);
    };
    const n = c.mesh.geometry.getAttribute("position").count;
    const owner = Array.from({ length: n }, (_, v) => strongest(v));
    for (let t = 0; t < rig.frames; t++) {
      c.setPose(person, t, t, 0, new Set());
      const verts = skinned(c);
      for (const side of ["left", "right"]) {
        const [ankle, foot] = [J(`${side}_ankle`), J(`${side}_foot`)];
        const centroid = (j: number) => {
          const m = [0, 0, 0];
          let count = 0;
          owner.forEach((o, v) => o === j && (count++, [0, 1, 2].forEach((k) => (m[k] += verts[3 * v + k]))));
          return new THREE.Vector3(...m).divideScalar(count);
        };
        const skin = centroid(foot).sub(centroid(ankle)).setY(0).normalize();
        const bone = new THREE.Vector3(...joints[t][foot]).sub(new THREE.Vector3(...joints[t][ankle])).setY(0).normalize();
        expect(skin.dot(bone), `frame ${t}, ${side} foot`).toBeGreaterThan(0.8);
      }
    }
    c.dispose();
  });

  it("shows part colours per vertex, the second person tinted, paints contacts, never penetration", () => {
    const a = make(0);
    const b = make(1);
    const colours = [0, 1].map((p) => jointColours(skeleton, p));
    const elbow = J("left_elbow");
    const wrist = J("left_wrist");
    const rknee = J("right_knee");
    expect(a.paintOf(wrist)?.colour).toBe(colours[0][wrist]);
    expect(a.paintOf(rknee)?.colour).toBe(colours[0][rknee]);
    expect(b.paintOf(wrist)?.colour).toBe(colours[1][wrist]);
    expect(colours[0][wrist]).not.toBe(colours[0][rknee]);
    // a contact at the left wrist (the hand glows); every bone keeps its part colour (the
    // stage marks penetration where the bodies overlap, not on the skin)
    a.setPose(person, 0, 0, 0, new Set([wrist]));
    expectPaint(a.paintOf(wrist), CONTACT_COLOUR, 0.7);
    expect([...a.boneColours(elbow).keys()]).toEqual([colours[0][elbow]]);
    expect(a.paintOf(rknee)?.colour).toBe(colours[0][rknee]);
    expect([...a.boneColours(wrist).keys()]).not.toContain(PENETRATION_COLOUR);
    // nothing highlighted: the part colours back
    a.setPose(person, 1, 1, 0, new Set());
    expect([...a.boneColours(wrist).keys()]).toEqual([colours[0][wrist]]);
    expect([...a.boneColours(elbow).keys()]).toEqual([colours[0][elbow]]);
    a.dispose();
    b.dispose();
  });

  // issue 26: the right collar's weights reach across the chest and back, which took the right
  // arm's orange (and its highlight) far over the midline
  it("keeps the arms' colours and highlights off the chest and back", () => {
    const c = make();
    c.setPose(person, 0, 0, 0, new Set());
    const geometry = c.mesh.geometry;
    const rest = geometry.getAttribute("position"); // the bind pose: facing +Z, left at +X
    const colour = geometry.getAttribute("color");
    const bone = c.mesh.userData.vertexJoint as Uint8Array;
    const colours = jointColours(skeleton, 0);
    const right = colours[J("right_shoulder")];
    const hex = (v: number) => "#" + new THREE.Color().fromArray(colour.array, 3 * v).getHexString();
    let orange = 0, chest = 0;
    for (let v = 0; v < rest.count; v++) {
      // the chest and back between the collars (the collars' own skin starts 6.4 cm right of
      // the midline), front and back
      const torso = rest.getY(v) > 1.2 && rest.getY(v) < 1.45 && Math.abs(rest.getX(v)) < 0.06;
      if (!torso) continue;
      chest++;
      if (hex(v) === right) orange++;
    }
    expect(chest).toBeGreaterThan(20);
    expect(orange).toBe(0); // 44 of them were orange before (the right collar's bone)
    // the right arm selected: only its own bones' vertices are painted, none on the trunk's
    c.selected = new Set(["right_collar", "right_shoulder", "right_elbow", "right_wrist"].map(J));
    c.setPose(person, 1, 1, 0, new Set());
    const arm = new Set(["right_collar", "right_shoulder", "right_elbow", "right_wrist"].map(J));
    let painted = 0;
    for (let v = 0; v < rest.count; v++) {
      if (hex(v) !== new THREE.Color(SELECT_COLOUR).getHexString().padStart(7, "#")) continue;
      painted++;
      expect(arm.has(bone[v]), `vertex ${v} on bone ${bone[v]}`).toBe(true);
      expect(rest.getX(v)).toBeLessThan(-0.06);
    }
    expect(painted).toBeGreaterThan(50);
    c.dispose();
  });

  it("picks the bone under a ray, as the mannequin does", () => {
    const c = make();
    c.setPose(person, 9, 9, 0, new Set()); // standing
    const [x, y, z] = joints[9][J("left_knee")];
    // a ray from in front (+z) through a point on the left thigh just above the knee
    const hit = new THREE.Raycaster(new THREE.Vector3(x, y + 0.08, z + 3), new THREE.Vector3(0, 0, -1)).intersectObjects(c.pickable, false)[0];
    expect(hit?.face).toBeTruthy();
    const picked = (hit!.object.userData.vertexJoint as Uint8Array)[hit!.face!.a];
    expect(["left_knee", "left_ankle"]).toContain(skeleton.joints[picked]);
    expect(hit!.object.userData.person).toBe(0);
    c.dispose();
  });
});

function expectPaint(paint: { colour: string; glow: number } | null, colour: string, glow: number): void {
  expect(paint?.colour).toBe(colour);
  expect(paint?.glow).toBeCloseTo(glow, 5);
}

function restY(j: number): number {
  let y = 0;
  for (let k = j; k >= 0; k = skeleton.parents[k]) y += person.offsets[3 * k + 1];
  return y;
}
