// One instanced mesh of a mannequin: a unit shape drawn once per bone or joint, with a matrix, a
// colour and a glow per instance (bodyMaterial.ts reads the last two).
import * as THREE from "three";
import { standardGlowMaterial, vertexLitMaterial } from "./bodyMaterial";
import type { QualitySettings } from "./quality";

const SCRATCH = new THREE.Color();

/** One instanced mesh: unit geometry, per-instance base colour and glow. */
export class Instances {
  readonly mesh: THREE.InstancedMesh;
  readonly base: THREE.Color[];
  private readonly glow: THREE.InstancedBufferAttribute;
  private readonly painted: (string | null)[];

  constructor(geometry: THREE.BufferGeometry, colours: string[], quality: QualitySettings, userData: object) {
    const n = colours.length;
    this.glow = new THREE.InstancedBufferAttribute(new Float32Array(n), 1);
    this.glow.setUsage(THREE.DynamicDrawUsage);
    geometry.setAttribute("glow", this.glow);
    const material = quality.shadowMap ? standardGlowMaterial() : vertexLitMaterial();
    this.mesh = new THREE.InstancedMesh(geometry, material, n);
    this.mesh.instanceMatrix.setUsage(THREE.DynamicDrawUsage);
    this.mesh.castShadow = quality.shadowMap;
    // the people walk: bounds change every frame (recomputed when a ray needs them)
    this.mesh.frustumCulled = false;
    this.mesh.userData = userData;
    this.base = colours.map((c) => new THREE.Color(c));
    this.base.forEach((c, i) => this.mesh.setColorAt(i, c));
    this.painted = colours.map(() => null);
  }

  /** Paint instance i with a highlight colour (glowing) or its base colour (null). */
  paint(i: number, highlight: string | null, glow: number): void {
    if (this.painted[i] === highlight) return;
    this.painted[i] = highlight;
    this.mesh.setColorAt(i, highlight ? SCRATCH.set(highlight) : this.base[i]);
    this.glow.setX(i, highlight ? glow : 0);
    this.mesh.instanceColor!.needsUpdate = true;
    this.glow.needsUpdate = true;
  }

  /** After the matrices of a pose: upload them, and drop the stale bounds. */
  posed(): void {
    this.mesh.instanceMatrix.needsUpdate = true;
    this.mesh.boundingSphere = null;
    this.mesh.boundingBox = null;
  }

  dispose(): void {
    this.mesh.geometry.dispose();
    (this.mesh.material as THREE.Material).dispose();
    this.mesh.dispose();
  }
}
