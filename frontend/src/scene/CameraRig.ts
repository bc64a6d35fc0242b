// The stage's camera: orbit controls, the preset views (framing.ts: where to look from and how
// far back for everyone to fit), following the people as they move, and the path tool's top
// view. A view is applied once (a preset, or the opening view of a motion); afterwards the orbit
// controls are the user's, and following keeps whatever they did (the target and camera move
// by the people's displacement only, never back to a computed place).
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import type { Skeleton } from "../api/types";
import type { FrameBuffer } from "../playback/frameBuffer";
import { fitView, groupFrame, viewDirection, type Vec3, type ViewPreset } from "./framing";
import { NUM_SPHERES, bodyScale, placeSpheres, sphereLayout, type SphereLayout } from "./sphereBody";

/** Metres above the people the path tool's top view looks down from (about 9 m of floor across at 40°). */
export const TOP_VIEW_HEIGHT = 12;
/** Frames of the motion whose bodies a view fits, at most (spread over the frames received). */
const FIT_FRAMES = 48;

export class CameraRig {
  readonly camera = new THREE.PerspectiveCamera(40, 1, 0.05, 200);
  readonly controls: OrbitControls;
  /** While true the camera does not follow the people (drawing a path: the floor must not
   * slide under the pointer as they walk, or loop back). */
  followPaused = false;
  /** The view last applied, and whether the user has moved the camera since. */
  view: ViewPreset | null = null;
  moved = false;
  /** The camera's offset from its target before the path tool's top view, to go back to. */
  private orbitOffset: THREE.Vector3 | null = null;
  /** The people's centre the camera last followed (it moves by the change of the centre). */
  private readonly anchor = new THREE.Vector3();
  private readonly centre = new THREE.Vector3();
  private readonly centreNext = new THREE.Vector3();
  private layout: { skeleton: Skeleton; spheres: SphereLayout } | null = null;

  constructor(canvas: HTMLCanvasElement, onChange: () => void) {
    this.camera.position.set(2.4, 1.8, 5.2);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.target.set(0, 0.9, 0);
    this.controls.enableDamping = false;
    this.controls.maxPolarAngle = Math.PI * 0.495;
    this.controls.minDistance = 0.8;
    this.controls.maxDistance = 30;
    this.controls.addEventListener("change", onChange);
    this.controls.addEventListener("start", () => (this.moved = true)); // the user's gesture only
    this.controls.update();
  }

  /** Look straight down on the people (for drawing a path), or back to the orbit view as it was. */
  setTopView(on: boolean): void {
    if (on === (this.orbitOffset !== null)) return;
    const target = this.controls.target;
    if (on) {
      this.orbitOffset = this.camera.position.clone().sub(target);
      // a hair off vertical, from +Z: the floor is seen as from the front view, +Z down the screen
      this.camera.position.set(target.x, target.y + TOP_VIEW_HEIGHT, target.z + 0.001);
      this.controls.enableRotate = false;
    } else {
      this.camera.position.copy(target).add(this.orbitOffset!);
      this.orbitOffset = null;
      this.controls.enableRotate = true;
    }
    this.controls.update();
  }

  get topView(): boolean {
    return this.orbitOffset !== null;
  }

  /** Where the people are at frame t: the mean pelvis position on the floor. */
  centreAt(buffer: FrameBuffer, t: number, out: THREE.Vector3): THREE.Vector3 {
    out.set(0, 0, 0);
    for (let p = 0; p < buffer.persons; p++) {
      const f = buffer.frame(p, t);
      out.x += f[0] / buffer.persons;
      out.z += f[2] / buffer.persons;
    }
    return out;
  }

  /** Everyone's sphere bodies ([x, y, z, r] × n) over up to FIT_FRAMES frames of the motion,
   * each frame moved so that its centre is frame t's: what the camera, following the people,
   * will have to show. */
  private bodiesAround(skeleton: Skeleton, buffer: FrameBuffer, t: number): Float32Array {
    if (this.layout?.skeleton !== skeleton) this.layout = { skeleton, spheres: sphereLayout(skeleton) };
    const layout = this.layout.spheres;
    const step = Math.max(1, Math.ceil(buffer.received / FIT_FRAMES));
    const frames = Math.ceil(buffer.received / step);
    const out = new Float32Array(frames * buffer.persons * NUM_SPHERES * 4);
    const one = new Float32Array(NUM_SPHERES * 4);
    const here = this.centreAt(buffer, t, new THREE.Vector3());
    const there = new THREE.Vector3();
    const scales = Array.from({ length: buffer.persons }, (_, p) => bodyScale(layout, buffer.positions[p], buffer.received));
    let o = 0;
    for (let k = 0; k < buffer.received; k += step) {
      this.centreAt(buffer, k, there).sub(here);
      for (let p = 0; p < buffer.persons; p++) {
        placeSpheres(layout, buffer.frame(p, k), scales[p], one);
        for (let s = 0; s < NUM_SPHERES; s++, o += 4) {
          out[o] = one[4 * s] - there.x;
          out[o + 1] = one[4 * s + 1];
          out[o + 2] = one[4 * s + 2] - there.z;
          out[o + 3] = one[4 * s + 3];
        }
      }
    }
    return out;
  }

  /** Apply a preset view to the people of `buffer` at frame t (the frame shown): turn to the
   * preset's direction ("fit": keep the camera's; "default": the first frame's group, so a
   * reset is the opening view again) and stand back until everyone's bodies over the motion
   * fit. */
  applyView(preset: ViewPreset, skeleton: Skeleton, buffer: FrameBuffer, t: number): void {
    if (buffer.received === 0) return;
    t = Math.min(t, buffer.received - 1);
    const joints = skeleton.joints;
    // the people as they are now; the opening view (reset) always from the first frame's
    const at = preset === "default" ? 0 : t;
    const poses = Array.from({ length: buffer.persons }, (_, p) => buffer.frame(p, at));
    const group = groupFrame(poses, joints.indexOf("left_hip"), joints.indexOf("right_hip"));
    const current = (this.orbitOffset ?? this.camera.position.clone().sub(this.controls.target)).clone().normalize();
    const dir: Vec3 = preset === "fit" ? [current.x, current.y, current.z] : viewDirection(preset, group);
    const fit = fitView(dir, this.bodiesAround(skeleton, buffer, t), this.camera.fov, this.camera.aspect, this.controls.minDistance);
    const distance = Math.min(fit.distance, this.controls.maxDistance);
    this.controls.target.set(...fit.target);
    this.camera.position.set(...fit.target).addScaledVector(new THREE.Vector3(...dir), distance);
    if (this.orbitOffset) {
      // in the path tool's top view: keep looking down, and go back to this view when it ends
      this.orbitOffset.copy(this.camera.position).sub(this.controls.target);
      this.camera.position.set(fit.target[0], fit.target[1] + TOP_VIEW_HEIGHT, fit.target[2] + 0.001);
    }
    this.centreAt(buffer, t, this.anchor);
    this.controls.update();
    this.view = preset;
    this.moved = false;
  }

  /** Keep the people in view: move the target and camera by the change of their centre
   * (blended between frames t and next), keeping the user's orbit. The new centre, or null
   * when it did not move. */
  follow(buffer: FrameBuffer, t: number, next: number, weight: number): THREE.Vector3 | null {
    if (this.followPaused) return null;
    const centre = this.centreAt(buffer, t, this.centre);
    if (weight > 0) centre.lerp(this.centreAt(buffer, next, this.centreNext), weight);
    const dx = centre.x - this.anchor.x, dz = centre.z - this.anchor.z;
    if (dx * dx + dz * dz < 1e-10) return null;
    this.controls.target.x += dx;
    this.controls.target.z += dz;
    this.camera.position.x += dx;
    this.camera.position.z += dz;
    this.anchor.copy(centre);
    this.controls.update();
    return centre;
  }

  dispose(): void {
    this.controls.dispose();
  }
}
