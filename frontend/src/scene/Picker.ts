// Pointer rays into the stage: the ground point under the pointer (y = 0 plane), the mannequin
// joint (bone or joint sphere) under it, or a path handle under it.
import * as THREE from "three";

export interface JointHit {
  person: number;
  joint: number;
}

const GROUND = new THREE.Plane(new THREE.Vector3(0, 1, 0), 0);
/** Metres from the camera beyond which a floor hit is not taken: near the horizon a pixel
 * spans metres of floor, so a short stroke there became a path tens of metres long. */
export const MAX_GROUND_DISTANCE = 25;

/** Whether a floor hit is near enough to the camera to draw on. */
export function usableGroundHit(hit: { x: number; y: number; z: number } | null, camera: { x: number; y: number; z: number }, max = MAX_GROUND_DISTANCE): boolean {
  return hit !== null && Math.hypot(hit.x - camera.x, hit.y - camera.y, hit.z - camera.z) <= max;
}

export class Picker {
  private readonly ray = new THREE.Raycaster();
  private readonly ndc = new THREE.Vector2();

  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly camera: THREE.Camera,
  ) {}

  /** Aim the ray through a client (CSS pixel) position. */
  private aim(clientX: number, clientY: number): THREE.Raycaster {
    const r = this.canvas.getBoundingClientRect();
    this.ndc.set(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1);
    this.ray.setFromCamera(this.ndc, this.camera);
    return this.ray;
  }

  /** Ground point [x, z] under the pointer, or null (above the horizon, or so close to it
   * that the hit is over MAX_GROUND_DISTANCE away). */
  ground(clientX: number, clientY: number): [number, number] | null {
    const ray = this.aim(clientX, clientY).ray;
    const hit = ray.intersectPlane(GROUND, new THREE.Vector3());
    return hit && usableGroundHit(hit, ray.origin) ? [hit.x, hit.z] : null;
  }

  /** The nearest mannequin joint (or bone, by its child joint) under the pointer. */
  joint(clientX: number, clientY: number, meshes: THREE.Object3D[]): JointHit | null {
    // merged body meshes (Mannequin.pickable): userData.vertexJoint[face.a] is the joint
    const hit = this.aim(clientX, clientY).intersectObjects(meshes, false)[0];
    const data = hit?.object.userData as { person?: number; vertexJoint?: Uint8Array } | undefined;
    const joint = hit?.face ? data?.vertexJoint?.[hit.face.a] : undefined;
    return typeof data?.person === "number" && typeof joint === "number" ? { person: data.person, joint } : null;
  }

  /** Index of the path handle under the pointer, or null. */
  handle(clientX: number, clientY: number, handles: THREE.Object3D[]): number | null {
    const hit = this.aim(clientX, clientY).intersectObjects(handles, false)[0];
    return hit ? (hit.object.userData.index as number) : null;
  }
}
