// Penetration drawn where it happens: at each pose of two people, the overlaps of their sphere
// bodies (sphereBody.ts, the server's penetration model; overlaps.ts) as red marks — a solid
// core and a translucent halo sized by the overlap — drawn over the bodies (no depth test: an
// overlap lies inside both bodies, where the mannequins' own surfaces would hide it). The
// bodies keep their part colours. Computed from the pose drawn (blended while playing), so the
// marks stay on the bodies; no allocation per pose.
import * as THREE from "three";
import type { Skeleton } from "../api/types";
import type { FrameBuffer } from "../playback/frameBuffer";
import { PENETRATION_COLOUR } from "./colours";
import { emptyMarks, findOverlaps, MARK_STRIDE, MAX_MARKS, type OverlapMarks } from "./overlaps";
import { bodyScale, NUM_SPHERES, placeSpheres, sphereLayout, type SphereLayout } from "./sphereBody";

/** The solid core's share of a mark's radius. */
const CORE = 0.5;

export class PenetrationMarks {
  readonly group = new THREE.Group();
  readonly marks: OverlapMarks = emptyMarks();
  private layout: SphereLayout | null = null;
  private skeleton: Skeleton | null = null;
  private readonly spheres = [new Float32Array(NUM_SPHERES * 4), new Float32Array(NUM_SPHERES * 4)];
  /** Each person's body scale for a buffer's contents (its version: frames still streaming). */
  private scales = { buffer: null as FrameBuffer | null, version: -1, values: [1, 1] };
  private readonly halo: THREE.InstancedMesh;
  private readonly core: THREE.InstancedMesh;
  private readonly m = new THREE.Matrix4();
  private readonly p = new THREE.Vector3();
  private readonly q = new THREE.Quaternion();
  private readonly s = new THREE.Vector3();

  constructor() {
    const material = (opacity: number) => new THREE.MeshBasicMaterial({
      color: PENETRATION_COLOUR, transparent: true, opacity, depthTest: false, depthWrite: false, toneMapped: false,
    });
    this.halo = new THREE.InstancedMesh(new THREE.SphereGeometry(1, 14, 10), material(0.35), MAX_MARKS);
    this.core = new THREE.InstancedMesh(new THREE.SphereGeometry(CORE, 10, 8), material(0.95), MAX_MARKS);
    for (const [mesh, order] of [[this.halo, 20], [this.core, 21]] as const) {
      mesh.count = 0;
      mesh.renderOrder = order; // after the bodies and the floor
      mesh.frustumCulled = false; // the instances move every pose; their bounds would go stale
      this.group.add(mesh);
    }
  }

  /** Scales from all the frames received (as the server's `body_scale` over the motion). */
  private scaleOf(buffer: FrameBuffer, p: number): number {
    const c = this.scales;
    if (c.buffer !== buffer || c.version !== buffer.version) {
      this.scales = {
        buffer,
        version: buffer.version,
        values: [0, 1].map((k) => (k < buffer.persons ? bodyScale(this.layout!, buffer.positions[k], buffer.received) : 1)),
      };
    }
    return this.scales.values[p];
  }

  /** Mark the overlaps of two poses (22 × xyz each) of `buffer`'s people; none for one person. */
  update(skeleton: Skeleton, buffer: FrameBuffer, poses: Float32Array[]): void {
    if (skeleton !== this.skeleton) {
      this.skeleton = skeleton;
      this.layout = sphereLayout(skeleton);
    }
    if (poses.length !== 2 || !this.layout) this.marks.count = 0;
    else {
      poses.forEach((pose, p) => placeSpheres(this.layout!, pose, this.scaleOf(buffer, p), this.spheres[p]));
      findOverlaps(this.spheres[0], this.spheres[1], this.marks);
    }
    const d = this.marks.data;
    for (let k = 0; k < this.marks.count; k++) {
      const o = k * MARK_STRIDE;
      this.m.compose(this.p.set(d[o], d[o + 1], d[o + 2]), this.q, this.s.setScalar(d[o + 3]));
      this.halo.setMatrixAt(k, this.m);
      this.core.setMatrixAt(k, this.m);
    }
    for (const mesh of [this.halo, this.core]) {
      mesh.count = this.marks.count;
      mesh.instanceMatrix.needsUpdate = true;
    }
  }

  clear(): void {
    this.marks.count = this.halo.count = this.core.count = 0;
  }

  dispose(): void {
    for (const mesh of [this.halo, this.core]) {
      mesh.geometry.dispose();
      (mesh.material as THREE.Material).dispose();
      mesh.dispose();
    }
    this.group.removeFromParent();
  }
}
