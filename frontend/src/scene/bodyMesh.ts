// The mesh of one mannequin: every bone's cylinder and every joint's sphere merged into one
// geometry whose vertices the CPU places each pose (~1,800, well under a millisecond). One draw
// call per person (43 meshes before). In SwiftShader it measured the same as two InstancedMeshes
// per person (its cost there is per vertex, docs/studio.md), and picking reads the joint straight
// off the hit triangle (no per-instance bounds to refresh). Per vertex: position, normal, colour
// (its piece's colour: part, highlight) and glow (bodyMaterial.ts); `vertexJoint` tells picking
// which joint (a bone: its child joint) a hit vertex stands for.
import * as THREE from "three";
import { mergeVertices } from "three/examples/jsm/utils/BufferGeometryUtils.js";
import { standardGlowMaterial, vertexLitMaterial } from "./bodyMaterial";
import type { QualitySettings } from "./quality";

/** One piece of the body: a unit shape (indexed geometry), the joint it stands for, its colour. */
export interface Piece {
  shape: THREE.BufferGeometry;
  joint: number;
  colour: string;
}

const SCRATCH = new THREE.Color();

/** A unit shape with the vertices at its seam and poles shared: three's sphere repeats its seam
 * column and each pole once per segment (an 8×6 sphere: 63 vertices, 42 distinct), its cylinder
 * the seam. Positions and normals there are equal, so the look is the same; the uvs go (unused). */
export function weldedShape(g: THREE.BufferGeometry): THREE.BufferGeometry {
  g.deleteAttribute("uv");
  const welded = mergeVertices(g, 1e-4);
  g.dispose();
  return welded;
}

export class BodyMesh {
  readonly mesh: THREE.Mesh;
  /** The joint each vertex belongs to (for picking: a hit triangle's first vertex). */
  readonly vertexJoint: Uint8Array;
  private readonly pieces: { start: number; count: number; tplPos: ArrayLike<number>; tplNrm: ArrayLike<number> }[];
  private readonly base: THREE.Color[];
  private readonly painted: (string | null)[];
  private readonly position: THREE.BufferAttribute;
  private readonly normal: THREE.BufferAttribute;
  private readonly colour: THREE.BufferAttribute;
  private readonly glow: THREE.BufferAttribute;

  constructor(pieces: Piece[], quality: QualitySettings, userData: object) {
    const vertices = pieces.reduce((n, p) => n + p.shape.getAttribute("position").count, 0);
    const index: number[] = [];
    this.vertexJoint = new Uint8Array(vertices);
    this.pieces = [];
    let start = 0;
    for (const p of pieces) {
      const count = p.shape.getAttribute("position").count;
      for (const i of p.shape.getIndex()!.array) index.push(start + i);
      this.vertexJoint.fill(p.joint, start, start + count);
      this.pieces.push({
        start,
        count,
        tplPos: p.shape.getAttribute("position").array,
        tplNrm: p.shape.getAttribute("normal").array,
      });
      start += count;
    }
    const dynamic = (size: number) => new THREE.BufferAttribute(new Float32Array(vertices * size), size).setUsage(THREE.DynamicDrawUsage);
    this.position = dynamic(3);
    this.normal = dynamic(3);
    this.colour = dynamic(3);
    this.glow = dynamic(1);
    const geometry = new THREE.BufferGeometry();
    geometry.setIndex(index);
    geometry.setAttribute("position", this.position);
    geometry.setAttribute("normal", this.normal);
    geometry.setAttribute("color", this.colour);
    geometry.setAttribute("glow", this.glow);
    this.mesh = new THREE.Mesh(geometry, quality.shadowMap ? standardGlowMaterial() : vertexLitMaterial());
    this.mesh.castShadow = quality.shadowMap;
    // the people walk: bounds change every pose (recomputed when a ray needs them)
    this.mesh.frustumCulled = false;
    this.mesh.userData = { ...userData, vertexJoint: this.vertexJoint };
    this.base = pieces.map((p) => new THREE.Color(p.colour));
    this.painted = pieces.map(() => "");
    pieces.forEach((_, i) => this.paint(i, null, 0));
  }

  /** Place piece i: its unit shape scaled by `s`, rotated by `q`, moved to `at`. */
  place(i: number, at: THREE.Vector3, q: THREE.Quaternion, s: THREE.Vector3): void {
    const { start, count, tplPos, tplNrm } = this.pieces[i];
    // the rotation matrix of q (row-major r00 … r22)
    const { x, y, z, w } = q;
    const r00 = 1 - 2 * (y * y + z * z), r01 = 2 * (x * y - z * w), r02 = 2 * (x * z + y * w);
    const r10 = 2 * (x * y + z * w), r11 = 1 - 2 * (x * x + z * z), r12 = 2 * (y * z - x * w);
    const r20 = 2 * (x * z - y * w), r21 = 2 * (y * z + x * w), r22 = 1 - 2 * (x * x + y * y);
    const pos = this.position.array as Float32Array;
    const nrm = this.normal.array as Float32Array;
    for (let k = 0; k < count; k++) {
      const t = 3 * k;
      const o = 3 * (start + k);
      const px = tplPos[t] * s.x, py = tplPos[t + 1] * s.y, pz = tplPos[t + 2] * s.z;
      pos[o] = at.x + r00 * px + r01 * py + r02 * pz;
      pos[o + 1] = at.y + r10 * px + r11 * py + r12 * pz;
      pos[o + 2] = at.z + r20 * px + r21 * py + r22 * pz;
      // the scales keep x = z (cylinders: radius, length; spheres: uniform), so rotating the
      // template normal is enough
      const nx = tplNrm[t], ny = tplNrm[t + 1], nz = tplNrm[t + 2];
      nrm[o] = r00 * nx + r01 * ny + r02 * nz;
      nrm[o + 1] = r10 * nx + r11 * ny + r12 * nz;
      nrm[o + 2] = r20 * nx + r21 * ny + r22 * nz;
    }
  }

  /** Paint piece i with a highlight colour (glowing) or its base colour (null). */
  paint(i: number, highlight: string | null, glow: number): void {
    if (this.painted[i] === highlight) return;
    this.painted[i] = highlight;
    const c = highlight ? SCRATCH.set(highlight) : this.base[i];
    const { start, count } = this.pieces[i];
    const colours = this.colour.array as Float32Array;
    for (let k = start; k < start + count; k++) c.toArray(colours, 3 * k);
    (this.glow.array as Float32Array).fill(highlight ? glow : 0, start, start + count);
    this.colour.needsUpdate = true;
    this.glow.needsUpdate = true;
  }

  /** After a pose: upload the vertices, drop the stale bounds. */
  posed(): void {
    this.position.needsUpdate = true;
    this.normal.needsUpdate = true;
    this.mesh.geometry.boundingSphere = null;
    this.mesh.geometry.boundingBox = null;
  }

  /** The base colour and glow of piece i now (for tests). */
  colourOf(i: number): { colour: string; glow: number } {
    const k = this.pieces[i].start;
    return { colour: "#" + SCRATCH.fromArray(this.colour.array, 3 * k).getHexString(), glow: this.glow.getX(k) };
  }

  dispose(): void {
    this.mesh.geometry.dispose();
    (this.mesh.material as THREE.Material).dispose();
  }
}
