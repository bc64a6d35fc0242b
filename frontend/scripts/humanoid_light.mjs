// Write frontend/src/scene/humanoid-light.json: the light-quality level of detail of the studio's
// skinned character — which of humanoid.glb's vertices to keep and the triangles between them —
// made by meshoptimizer (a dev dependency; it runs here, in Node, not in the page, whose CSP
// allows no WebAssembly): quadric edge collapse onto the mesh's own vertices to LIGHT_DETAIL of
// its triangles (normals weighed in), then vertex-cache order (`reorderMesh`). The page builds the
// light body from the full mesh with it (scene/lightBody.ts), so every kept vertex keeps its
// position, normal and skin weights exactly. scene/lightBody.test.ts fails when the committed
// file is not what this writes from the committed humanoid.glb.
//
// Run (after frontend/scripts/humanoid_asset.py changes the mesh): node frontend/scripts/humanoid_light.mjs
import { readFileSync, writeFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { MeshoptEncoder } from "meshoptimizer/encoder";
import { MeshoptSimplifier } from "meshoptimizer/simplifier";
import { GLTFLoader } from "three/examples/jsm/loaders/GLTFLoader.js";

export const LIGHT_DETAIL = 0.2; // share of the triangles kept
const MAX_ERROR = 0.02; // relative to the mesh's size (1.8 m); the result is well under it
const GLB = new URL("../public/humanoid.glb", import.meta.url);
const OUT = new URL("../src/scene/humanoid-light.json", import.meta.url);

/** {vertices: the full mesh's index of each kept vertex, in their new order; triangles: indices
 * into `vertices`; error: the simplifier's measure, metres} from humanoid.glb's bytes. */
export async function lightLod(bytes, detail = LIGHT_DETAIL) {
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  const gltf = await new Promise((ok, fail) => new GLTFLoader().parse(buffer, "", ok, fail));
  const g = gltf.scene.getObjectByName("humanoid_body").geometry;
  const indices = Uint32Array.from(g.index.array);
  const positions = Float32Array.from(g.attributes.position.array);
  const normals = Float32Array.from(g.attributes.normal.array);
  await Promise.all([MeshoptSimplifier.ready, MeshoptEncoder.ready]);
  const target = Math.floor((indices.length * detail) / 3) * 3;
  const [kept, error] = MeshoptSimplifier.simplifyWithAttributes(indices, positions, 3, normals, 3, [0.5, 0.5, 0.5], null, target, MAX_ERROR);
  const [remap, unique] = MeshoptEncoder.reorderMesh(kept, true, false); // reorders `kept` in place
  const vertices = new Array(unique);
  remap.forEach((to, from) => to !== 0xffffffff && (vertices[to] = from));
  return { vertices, triangles: Array.from(kept), error: +(error * MeshoptSimplifier.getScale(positions, 3)).toFixed(5) };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const lod = await lightLod(readFileSync(GLB));
  writeFileSync(OUT, JSON.stringify({ detail: LIGHT_DETAIL, ...lod }) + "\n");
  console.log(`wrote ${fileURLToPath(OUT)}: ${lod.vertices.length} vertices, ${lod.triangles.length / 3} triangles, error ${(lod.error * 100).toFixed(2)} cm`);
}
