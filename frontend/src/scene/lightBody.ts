// The character's body for light quality (software WebGL): the same humanoid mesh at a fifth of
// its triangles — a subset of its own vertices (each keeps its position, normal and skin
// weights exactly) with the triangles between them (the simplifier's error estimate: 6.7 mm),
// in vertex-cache order. The subset is made offline by meshoptimizer (scripts/humanoid_light.mjs,
// committed as humanoid-light.json). A software rasteriser pays per vertex and per triangle: the
// full mesh (4,208 vertices, 8,412 triangles a person) cost several times the mannequin's bodies
// there, this one (843 / 1,682) about what they (918 / 1,468) cost (docs/studio.md). The GLB
// export and full quality keep the full mesh.
import * as THREE from "three";
import lod from "./humanoid-light.json";

/** Share of the triangles light quality keeps. */
export const LIGHT_DETAIL = lod.detail;

export interface Lod {
  /** The full mesh's index of each kept vertex, in the new order. */
  vertices: number[];
  /** Triangles, indices into `vertices`. */
  triangles: number[];
}

export const LIGHT_LOD: Lod = lod;

/** The geometry of a level of detail: every attribute of the kept vertices, carried over. */
export function lodGeometry(geometry: THREE.BufferGeometry, { vertices, triangles }: Lod = LIGHT_LOD): THREE.BufferGeometry {
  const n = geometry.getAttribute("position").count;
  if (vertices.some((v) => v >= n)) throw new Error(`the level of detail is for a mesh of more than ${n} vertices`);
  const out = new THREE.BufferGeometry();
  for (const [name, attr] of Object.entries(geometry.attributes)) {
    const a = attr as THREE.BufferAttribute;
    const size = a.itemSize;
    const src = a.array as ArrayLike<number>;
    const dst = new (a.array.constructor as new (n: number) => THREE.TypedArray)(vertices.length * size);
    vertices.forEach((from, to) => {
      for (let k = 0; k < size; k++) dst[to * size + k] = src[from * size + k];
    });
    out.setAttribute(name, new THREE.BufferAttribute(dst, size, a.normalized));
  }
  out.setIndex(new THREE.BufferAttribute(Uint16Array.from(triangles), 1));
  out.computeBoundingSphere();
  return out;
}
