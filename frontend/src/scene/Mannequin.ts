// A person drawn as capsules (one per bone) and spheres (one per joint), coloured by body
// part. Per frame: contact joints glow green, bones of penetrating parts turn red.
import * as THREE from "three";
import type { Skeleton } from "../api/types";
import { CONTACT_COLOUR, PENETRATION_COLOUR, bones, jointColours } from "./colours";
import { blobMap } from "./blobShadow";
import { QUALITY, type QualitySettings } from "./quality";

// Capsule radius (m) of the bone ending at a joint, by joint name.
const BONE_RADIUS: [RegExp, number][] = [
  [/^spine/, 0.075],
  [/hip$/, 0.065],
  [/knee$/, 0.06],
  [/ankle$/, 0.045],
  [/foot$/, 0.035],
  [/^neck$/, 0.05],
  [/^head$/, 0.045],
  [/collar$/, 0.045],
  [/shoulder$/, 0.048],
  [/elbow$/, 0.042],
  [/wrist$/, 0.034],
];
const HEAD_RADIUS = 0.1;
const UP = new THREE.Vector3(0, 1, 0);
// Blob shadows (when there is no shadow map): under the pelvis and each ankle, diameter in m.
const BLOBS: [string, number][] = [
  ["pelvis", 0.8],
  ["left_ankle", 0.32],
  ["right_ankle", 0.32],
];

function boneRadius(name: string): number {
  return BONE_RADIUS.find(([re]) => re.test(name))?.[1] ?? 0.04;
}

function material(colour: string): THREE.MeshStandardMaterial {
  return new THREE.MeshStandardMaterial({ color: colour, roughness: 0.55, metalness: 0.05 });
}

interface Part {
  mesh: THREE.Mesh;
  mat: THREE.MeshStandardMaterial;
  colour: THREE.Color;
}

export const SELECT_COLOUR = "#ffd166";
export const HOVER_COLOUR = "#fff3c4";

export class Mannequin {
  readonly group = new THREE.Group();
  /** Joints of the selected / hovered body part (click to edit), painted on top of part colours. */
  selected = new Set<number>();
  hovered = new Set<number>();
  private readonly bonePairs: [number, number][];
  private readonly boneParts: Part[] = [];
  private readonly lengths: number[] = [];
  private readonly jointParts: Part[] = [];
  private readonly blobs: { joint: number; mesh: THREE.Mesh; mat: THREE.MeshBasicMaterial }[] = [];
  private readonly a = new THREE.Vector3();
  private readonly b = new THREE.Vector3();

  /** `rest`: the first frame (66 floats), whose bone lengths size the capsules. `quality`: tessellation,
   * and shadows: cast them for the renderer's shadow map, or draw blob shadows on the floor. */
  constructor(
    skeleton: Skeleton,
    readonly person: number,
    rest: Float32Array,
    private readonly quality: QualitySettings = QUALITY.full,
  ) {
    const shadowMap = quality.shadowMap;
    const colours = jointColours(skeleton, person);
    this.bonePairs = bones(skeleton);
    for (const [child, parent] of this.bonePairs) {
      const length = Math.max(1e-3, this.point(rest, child, this.a).distanceTo(this.point(rest, parent, this.b)));
      const radius = boneRadius(skeleton.joints[child]);
      const geometry = new THREE.CapsuleGeometry(radius, length, ...quality.capsule);
      const part = this.add(geometry, colours[child]);
      part.mesh.userData = { person, joint: child };
      this.boneParts.push(part);
      this.lengths.push(length);
    }
    skeleton.joints.forEach((name, j) => {
      const adjacent = this.bonePairs
        .filter(([c, p]) => c === j || p === j)
        .map(([c]) => boneRadius(skeleton.joints[c]));
      const r = name === "head" ? HEAD_RADIUS : Math.max(0.03, ...adjacent) * 1.04;
      const light = new THREE.Color(colours[j]).lerp(new THREE.Color("#ffffff"), 0.18);
      const part = this.add(new THREE.SphereGeometry(r, ...quality.sphere), "#" + light.getHexString());
      part.mesh.userData = { person, joint: j };
      this.jointParts.push(part);
    });
    if (!shadowMap) {
      for (const [name, size] of BLOBS) {
        const mat = new THREE.MeshBasicMaterial({ map: blobMap(), transparent: true, depthWrite: false, opacity: 0.5 });
        const mesh = new THREE.Mesh(new THREE.PlaneGeometry(size, size), mat);
        mesh.rotation.x = -Math.PI / 2;
        mesh.renderOrder = 1;
        this.group.add(mesh);
        this.blobs.push({ joint: skeleton.joints.indexOf(name), mesh, mat });
      }
    }
  }

  private add(geometry: THREE.BufferGeometry, colour: string): Part {
    const mat = material(colour);
    const mesh = new THREE.Mesh(geometry, mat);
    mesh.castShadow = this.quality.shadowMap;
    this.group.add(mesh);
    return { mesh, mat, colour: new THREE.Color(colour) };
  }

  private point(f: Float32Array, j: number, out: THREE.Vector3): THREE.Vector3 {
    return out.set(f[3 * j], f[3 * j + 1], f[3 * j + 2]);
  }

  /** Pose the mannequin: `joints` is one frame (66 floats); sets highlight colours. */
  setPose(joints: Float32Array, contacts: Set<number>, penetrating: Set<number>): void {
    this.bonePairs.forEach(([child, parent], i) => {
      const { mesh } = this.boneParts[i];
      this.point(joints, parent, this.a);
      this.point(joints, child, this.b);
      mesh.position.addVectors(this.a, this.b).multiplyScalar(0.5);
      const dir = this.b.sub(this.a);
      const len = dir.length();
      if (len > 1e-6) mesh.quaternion.setFromUnitVectors(UP, dir.divideScalar(len));
      mesh.scale.set(1, len / this.lengths[i], 1);
      this.paint(this.boneParts[i], penetrating.has(child) ? PENETRATION_COLOUR : this.pickColour(child), 0.45);
    });
    this.jointParts.forEach((part, j) => {
      this.point(joints, j, part.mesh.position);
      const contact = contacts.has(j);
      part.mesh.scale.setScalar(contact ? 1.3 : 1);
      this.paint(part, contact ? CONTACT_COLOUR : this.pickColour(j), 0.7);
    });
    for (const { joint, mesh, mat } of this.blobs) {
      const y = joints[3 * joint + 1];
      mesh.position.set(joints[3 * joint], 0.003, joints[3 * joint + 2]);
      // fainter and wider as the joint rises off the floor
      const lift = Math.min(1, Math.max(0, (y - (joint === 0 ? 0.9 : 0.08)) / 0.8));
      mat.opacity = 0.55 * (1 - 0.7 * lift);
      mesh.scale.setScalar(1 + 0.5 * lift);
    }
  }

  /** Meshes a pointer ray can hit (bones and joints; userData {person, joint}). */
  get pickable(): THREE.Object3D[] {
    return [...this.boneParts, ...this.jointParts].map((p) => p.mesh);
  }

  private pickColour(j: number): string | null {
    return this.selected.has(j) ? SELECT_COLOUR : this.hovered.has(j) ? HOVER_COLOUR : null;
  }

  private paint(part: Part, highlight: string | null, glow: number): void {
    if (highlight) {
      part.mat.color.set(highlight);
      part.mat.emissive.set(highlight);
      part.mat.emissiveIntensity = glow;
    } else {
      part.mat.color.copy(part.colour);
      part.mat.emissive.set(0x000000);
      part.mat.emissiveIntensity = 0;
    }
  }

  dispose(): void {
    for (const p of [...this.boneParts, ...this.jointParts, ...this.blobs]) {
      p.mesh.geometry.dispose();
      p.mat.dispose();
    }
    this.group.removeFromParent();
  }
}
