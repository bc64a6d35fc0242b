import { readFileSync } from "node:fs";
import * as THREE from "three";
import { beforeAll, describe, expect, it } from "vitest";
import rigJson from "../test/rig.json";
import { skeleton } from "../test/fixtures";
import { parseRig } from "../playback/rig";
import { BODY_NODE, Character, lightTemplate, parseHumanoid, type HumanoidTemplate } from "./Character";
import { LIGHT_DETAIL, LIGHT_LOD } from "./lightBody";
import { QUALITY } from "./quality";
import committed from "./humanoid-light.json";

const GLB = new URL("../../public/humanoid.glb", import.meta.url);
const person = parseRig("m", rigJson).people[0];
let full: HumanoidTemplate;
let light: HumanoidTemplate;

beforeAll(async () => {
  const b = readFileSync(GLB);
  full = await parseHumanoid(b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength));
  light = lightTemplate(full);
});

const body = (t: HumanoidTemplate) => t.getObjectByName(BODY_NODE) as THREE.SkinnedMesh;

describe("the light level of detail of the character", () => {
  it("is what scripts/humanoid_light.mjs makes from the committed humanoid.glb", async () => {
    const script = "../../scripts/humanoid_light.mjs";
    const { lightLod } = (await import(/* @vite-ignore */ script)) as { lightLod(b: Buffer): Promise<typeof committed> };
    const made = await lightLod(readFileSync(GLB));
    expect(made.vertices).toEqual(committed.vertices);
    expect(made.triangles).toEqual(committed.triangles);
  });

  it("keeps a fifth of the triangles, on the mesh's own vertices, and stays a closed surface", () => {
    const g = body(full).geometry;
    const tris = LIGHT_LOD.triangles.length / 3;
    expect(tris).toBeLessThanOrEqual(Math.ceil((g.getIndex()!.count / 3) * LIGHT_DETAIL));
    expect(LIGHT_LOD.vertices.length).toBeLessThan(900); // the mannequin's light body: 918
    expect(new Set(LIGHT_LOD.vertices).size).toBe(LIGHT_LOD.vertices.length);
    expect(Math.max(...LIGHT_LOD.triangles)).toBe(LIGHT_LOD.vertices.length - 1);
    // every edge between exactly two triangles: no holes
    const edges = new Map<string, number>();
    for (let t = 0; t < tris; t++) {
      for (let k = 0; k < 3; k++) {
        const [a, b] = [LIGHT_LOD.triangles[3 * t + k], LIGHT_LOD.triangles[3 * t + ((k + 1) % 3)]];
        const key = a < b ? `${a},${b}` : `${b},${a}`;
        edges.set(key, (edges.get(key) ?? 0) + 1);
      }
    }
    expect([...edges.values()].every((n) => n === 2)).toBe(true);
    expect(committed.error).toBeLessThan(0.01);
  });

  it("carries every attribute of the kept vertices over exactly", () => {
    const a = body(full).geometry;
    const b = body(light).geometry;
    for (const name of ["position", "normal", "skinIndex", "skinWeight"]) {
      const src = a.getAttribute(name);
      const dst = b.getAttribute(name);
      expect(dst.count).toBe(LIGHT_LOD.vertices.length);
      LIGHT_LOD.vertices.forEach((from, to) => {
        for (let k = 0; k < src.itemSize; k++) expect(dst.getComponent(to, k)).toBe(src.getComponent(from, k));
      });
    }
  });

  it("poses the same: its skin at each frame is the full mesh's kept vertices", () => {
    const a = new Character(full, skeleton, 0, person.offsets, QUALITY.full);
    const b = new Character(light, skeleton, 0, person.offsets, QUALITY.light);
    const v = new THREE.Vector3();
    const w = new THREE.Vector3();
    let worst = 0;
    for (const t of [0, 3, 7]) {
      for (const c of [a, b]) {
        c.setPose(person, t, t, 0, new Set());
        c.group.updateMatrixWorld(true);
        c.mesh.skeleton.update();
      }
      LIGHT_LOD.vertices.forEach((from, to) => {
        a.mesh.getVertexPosition(from, v);
        b.mesh.getVertexPosition(to, w);
        worst = Math.max(worst, v.distanceTo(w));
      });
    }
    expect(worst).toBeLessThan(1e-5);
    a.dispose();
    b.dispose();
  });
});
