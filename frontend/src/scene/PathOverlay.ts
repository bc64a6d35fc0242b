// The drawn path on the ground: a smooth curve (Catmull-Rom through the points) as a flat tube,
// a start marker, arrows along it showing the direction, and draggable handles on its points.
import * as THREE from "three";
import type { Point } from "../directing/path";

export const PATH_COLOURS = ["#5b8cff", "#ff9a5b"]; // Person 1, Person 2
const LIFT = 0.02; // above the floor, below the feet
const ARROW_EVERY = 0.6; // metres between direction arrows

export class PathOverlay {
  readonly group = new THREE.Group();
  /** Handles (one per control point), userData.index; raycast to drag one. */
  handles: THREE.Mesh[] = [];
  private disposables: { dispose(): void }[] = [];

  constructor() {
    this.group.renderOrder = 2;
  }

  private clear(): void {
    this.disposables.forEach((d) => d.dispose());
    this.disposables = [];
    this.handles = [];
    this.group.clear();
  }

  private keep<T extends { dispose(): void }>(x: T): T {
    this.disposables.push(x);
    return x;
  }

  /** Redraw for `points` (ground x, z), coloured for `person`; handles only when `editable`. */
  update(points: Point[], person: number, editable: boolean): void {
    this.clear();
    if (points.length < 2) {
      if (points.length === 1) this.marker(points[0], PATH_COLOURS[person] ?? PATH_COLOURS[0]);
      return;
    }
    const colour = PATH_COLOURS[person] ?? PATH_COLOURS[0];
    const curve = new THREE.CatmullRomCurve3(
      points.map(([x, z]) => new THREE.Vector3(x, LIFT, z)),
      false,
      "centripetal",
    );
    const length = curve.getLength();
    const mat = this.keep(new THREE.MeshBasicMaterial({ color: colour, transparent: true, opacity: 0.9 }));
    const tube = this.keep(new THREE.TubeGeometry(curve, Math.max(16, Math.round(length * 24)), 0.025, 6, false));
    this.group.add(new THREE.Mesh(tube, mat));
    this.marker(points[0], "#39d98a");

    const cone = this.keep(new THREE.ConeGeometry(0.07, 0.18, 12));
    const up = new THREE.Vector3(0, 1, 0);
    for (let d = ARROW_EVERY * 0.5; d < length; d += ARROW_EVERY) {
      const u = d / length;
      const arrow = new THREE.Mesh(cone, mat);
      arrow.position.copy(curve.getPointAt(u));
      arrow.quaternion.setFromUnitVectors(up, curve.getTangentAt(u));
      this.group.add(arrow);
    }
    if (editable) {
      const ball = this.keep(new THREE.SphereGeometry(0.045, 12, 8));
      const hmat = this.keep(new THREE.MeshBasicMaterial({ color: "#ffffff" }));
      points.forEach(([x, z], index) => {
        const h = new THREE.Mesh(ball, hmat);
        h.position.set(x, LIFT + 0.02, z);
        h.userData = { index };
        this.handles.push(h);
        this.group.add(h);
      });
    }
  }

  /** The start marker: a flat ring where the path begins. */
  private marker([x, z]: Point, colour: string): void {
    const ring = this.keep(new THREE.RingGeometry(0.1, 0.16, 24));
    const mat = this.keep(new THREE.MeshBasicMaterial({ color: colour, side: THREE.DoubleSide }));
    const m = new THREE.Mesh(ring, mat);
    m.rotation.x = -Math.PI / 2;
    m.position.set(x, LIFT + 0.005, z);
    this.group.add(m);
  }

  dispose(): void {
    this.clear();
    this.group.removeFromParent();
  }
}
