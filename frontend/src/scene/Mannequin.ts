// A person drawn as a cylinder per bone and a sphere per joint (the joint spheres, at least as
// wide as the bones meeting there, close the cylinders' ends: together they are capsules),
// coloured by body part, merged into one mesh per person (bodyMesh.ts): one draw call whatever
// the skeleton. Per frame: contact joints glow green; the selected / hovered part is painted on
// top. Penetration is not painted on the body (it hid where the bodies meet): the stage marks
// the overlaps themselves (PenetrationMarks.ts).
import * as THREE from "three";
import type { Skeleton } from "../api/types";
import { CONTACT_COLOUR, bones, jointColours } from "./colours";
import { blobMap } from "./blobShadow";
import { QUALITY, type QualitySettings } from "./quality";
import { BodyMesh, weldedShape } from "./bodyMesh";

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

export const SELECT_COLOUR = "#ffd166";
export const HOVER_COLOUR = "#fff3c4";

export class Mannequin {
  readonly group = new THREE.Group();
  /** Joints of the selected / hovered body part (click to edit), painted on top of part colours. */
  selected = new Set<number>();
  hovered = new Set<number>();
  /** Whether a pose was set (the mesh has vertices in place). */
  posed = false;
  private readonly bonePairs: [number, number][];
  private readonly boneRadii: number[];
  private readonly jointRadii: number[];
  private readonly body: BodyMesh;
  private readonly blobs: { joint: number; mesh: THREE.Mesh; mat: THREE.MeshBasicMaterial }[] = [];
  private readonly a = new THREE.Vector3();
  private readonly b = new THREE.Vector3();
  private readonly q = new THREE.Quaternion();
  private readonly s = new THREE.Vector3();

  /** `quality`: tessellation, and shadows: cast them for the renderer's shadow map, or draw blob
   * shadows on the floor. Bones take their length from each pose. */
  constructor(
    readonly skeleton: Skeleton,
    readonly person: number,
    quality: QualitySettings = QUALITY.full,
  ) {
    const colours = jointColours(skeleton, person);
    this.bonePairs = bones(skeleton);
    this.boneRadii = this.bonePairs.map(([child]) => boneRadius(skeleton.joints[child]));
    this.jointRadii = skeleton.joints.map((name, j) => {
      const adjacent = this.bonePairs.filter(([c, p]) => c === j || p === j).map(([c]) => boneRadius(skeleton.joints[c]));
      return name === "head" ? HEAD_RADIUS : Math.max(0.03, ...adjacent) * 1.04;
    });
    // unit shapes, scaled per piece: a cylinder of radius 1 and length 1 along y (open: the
    // joint spheres cover its ends), a sphere of radius 1; bones first, then joints. Thin pieces
    // (a few pixels wide on screen) take the coarser shapes of `quality.small`.
    const shape = (g: THREE.BufferGeometry) => (quality.weld ? weldedShape(g) : g);
    const cylinder = shape(new THREE.CylinderGeometry(1, 1, 1, quality.capsule[1], 1, true));
    const sphere = shape(new THREE.SphereGeometry(1, ...quality.sphere));
    const thinCylinder = shape(new THREE.CylinderGeometry(1, 1, 1, quality.small.radial, 1, true));
    const thinSphere = shape(new THREE.SphereGeometry(1, ...quality.small.sphere));
    const thin = (r: number) => r < quality.small.radius;
    const lighter = (c: string) => "#" + new THREE.Color(c).lerp(new THREE.Color("#ffffff"), 0.18).getHexString();
    this.body = new BodyMesh(
      [
        ...this.bonePairs.map(([child], i) => ({
          shape: thin(this.boneRadii[i]) ? thinCylinder : cylinder,
          joint: child,
          colour: colours[child],
        })),
        ...skeleton.joints.map((_, j) => ({
          shape: thin(this.jointRadii[j]) ? thinSphere : sphere,
          joint: j,
          colour: lighter(colours[j]),
        })),
      ],
      quality,
      { person },
    );
    for (const g of [cylinder, sphere, thinCylinder, thinSphere]) g.dispose();
    this.group.add(this.body.mesh);
    if (!quality.shadowMap) {
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

  /** The piece of the body mesh that is joint j's sphere. */
  private sphereOf(j: number): number {
    return this.bonePairs.length + j;
  }

  private point(f: Float32Array, j: number, out: THREE.Vector3): THREE.Vector3 {
    return out.set(f[3 * j], f[3 * j + 1], f[3 * j + 2]);
  }

  /** Whether the body is drawn; hidden (the skinned character stands in), a pose only places
   * the blob shadows. */
  get bodyVisible(): boolean {
    return this.body.mesh.visible;
  }

  set bodyVisible(on: boolean) {
    this.body.mesh.visible = on;
  }

  /** Pose the mannequin: `joints` is one frame (66 floats); sets highlight colours. No allocation. */
  setPose(joints: Float32Array, contacts: Set<number>): void {
    if (this.bodyVisible) this.placeBody(joints, contacts);
    this.placeBlobs(joints);
  }

  private placeBody(joints: Float32Array, contacts: Set<number>): void {
    const { a, b, q, s, body } = this;
    for (let i = 0; i < this.bonePairs.length; i++) {
      const [child, parent] = this.bonePairs[i];
      this.point(joints, parent, a);
      this.point(joints, child, b);
      b.sub(a); // the bone's direction × length
      const len = b.length();
      if (len > 1e-6) q.setFromUnitVectors(UP, b.divideScalar(len));
      a.addScaledVector(b, len / 2); // the bone's middle
      const r = this.boneRadii[i];
      s.set(r, Math.max(len, 1e-4), r);
      body.place(i, a, q, s);
      body.paint(i, this.pickColour(child), 0.45);
    }
    q.identity();
    for (let j = 0; j < this.jointRadii.length; j++) {
      const contact = contacts.has(j);
      s.setScalar(this.jointRadii[j] * (contact ? 1.3 : 1));
      body.place(this.sphereOf(j), this.point(joints, j, a), q, s);
      body.paint(this.sphereOf(j), contact ? CONTACT_COLOUR : this.pickColour(j), 0.7);
    }
    body.posed();
    this.posed = true;
  }

  private placeBlobs(joints: Float32Array): void {
    for (const { joint, mesh, mat } of this.blobs) {
      const y = joints[3 * joint + 1];
      mesh.position.set(joints[3 * joint], 0.003, joints[3 * joint + 2]);
      // fainter and wider as the joint rises off the floor
      const lift = Math.min(1, Math.max(0, (y - (joint === 0 ? 0.9 : 0.08)) / 0.8));
      mat.opacity = 0.55 * (1 - 0.7 * lift);
      mesh.scale.setScalar(1 + 0.5 * lift);
    }
  }

  /** Meshes a pointer ray can hit: the body; userData {person, vertexJoint}, where
   * vertexJoint[face.a] is the joint (a bone: its child joint) a hit triangle belongs to. */
  get pickable(): THREE.Object3D[] {
    return [this.body.mesh];
  }

  /** Colour and glow shown now on joint j's sphere (for tests). */
  jointPaint(j: number): { colour: string; glow: number } {
    return this.body.colourOf(this.sphereOf(j));
  }

  private pickColour(j: number): string | null {
    return this.selected.has(j) ? SELECT_COLOUR : this.hovered.has(j) ? HOVER_COLOUR : null;
  }

  dispose(): void {
    this.body.dispose();
    for (const { mesh, mat } of this.blobs) {
      mesh.geometry.dispose();
      mat.dispose();
    }
    this.group.removeFromParent();
  }
}
