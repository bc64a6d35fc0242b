// The floor for software WebGL (light quality): the same look as Ground.ts (floor colour, minor
// lines every 0.5 m, major every 2 m, a fade into the background) without its per-pixel
// procedural shader, which cost a software rasteriser about a third of each frame. Here the
// floor is a disc whose vertex colours carry the fade, and the grid is line segments whose vertex
// colours fade too; the fragment shader only writes the interpolated colour, and the grid costs
// only the pixels of its lines. Lines are cut into 2 m pieces: long lines that pass behind the
// camera are clipped wrongly by some software rasterisers (SwiftShader), short ones are not.
import * as THREE from "three";

const FLOOR_RADIUS = 22; // m, as Ground's fade
const GRID_RADIUS = 14; // m: the lines fade out by here
const PIECE = 2; // m
const MINOR = 0.5;
const MAJOR = 2;

const vertexShader = /* glsl */ `
  attribute vec3 color;
  varying vec3 vColour;
  void main() {
    vColour = color;
    gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
  }
`;
const fragmentShader = /* glsl */ `
  varying vec3 vColour;
  void main() {
    gl_FragColor = vec4(vColour, 1.0);
  }
`;

/** Colours here are display (sRGB) values, written as they are (no conversion per pixel). */
function display(hex: string): THREE.Color {
  return new THREE.Color().setStyle(hex, THREE.LinearSRGBColorSpace);
}

/** Drawn first, behind everything, without writing depth: nothing to fight over at y = 0. */
function flatMaterial(): THREE.ShaderMaterial {
  return new THREE.ShaderMaterial({ vertexShader, fragmentShader, toneMapped: false, depthWrite: false });
}

const smooth = (a: number, b: number, x: number) => {
  const t = Math.min(1, Math.max(0, (x - a) / (b - a)));
  return t * t * (3 - 2 * t);
};

export class LineGround {
  readonly group = new THREE.Group();
  private readonly floor: THREE.Mesh;
  private readonly grid: THREE.LineSegments;

  constructor(background: string) {
    const floorColour = display("#181b22");
    const far = display(background);
    // the disc: concentric rings, each vertex coloured by its distance from the centre
    const disc = new THREE.RingGeometry(0, FLOOR_RADIUS, 48, 8);
    disc.rotateX(-Math.PI / 2);
    const pos = disc.getAttribute("position");
    const colours = new Float32Array(pos.count * 3);
    const c = new THREE.Color();
    for (let i = 0; i < pos.count; i++) {
      const r = Math.hypot(pos.getX(i), pos.getZ(i));
      c.copy(floorColour).lerp(far, smooth(FLOOR_RADIUS * 0.3, FLOOR_RADIUS, r)).toArray(colours, 3 * i);
    }
    disc.setAttribute("color", new THREE.BufferAttribute(colours, 3));
    this.floor = new THREE.Mesh(disc, flatMaterial());
    this.floor.renderOrder = -2;

    // the grid: lines x = k·0.5 and z = k·0.5 within the radius, in 2 m pieces
    const minor = display("#252a34");
    const major = display("#363e4e");
    const points: number[] = [];
    const cols: number[] = [];
    const ends = (t: number) => Math.sqrt(GRID_RADIUS * GRID_RADIUS - t * t);
    for (let k = -GRID_RADIUS / MINOR; k <= GRID_RADIUS / MINOR; k++) {
      const t = k * MINOR;
      const lineColour = Math.abs(t % MAJOR) < 1e-6 ? major : minor;
      const half = ends(t);
      for (let s = -half; s < half; s += PIECE) {
        const e = Math.min(half, s + PIECE);
        for (const [x, z] of [[t, s], [t, e], [s, t], [e, t]]) {
          points.push(x, 0.002, z);
          const fade = smooth(GRID_RADIUS * 0.3, GRID_RADIUS, Math.hypot(x, z));
          // the floor's colour under the line at that distance, then the line over it
          const under = floorColour.clone().lerp(far, smooth(FLOOR_RADIUS * 0.3, FLOOR_RADIUS, Math.hypot(x, z)));
          c.copy(lineColour).lerp(under, fade).toArray(cols, cols.length);
        }
      }
    }
    const lines = new THREE.BufferGeometry();
    lines.setAttribute("position", new THREE.Float32BufferAttribute(points, 3));
    lines.setAttribute("color", new THREE.Float32BufferAttribute(cols, 3));
    this.grid = new THREE.LineSegments(lines, flatMaterial());
    this.grid.renderOrder = -1;
    this.group.add(this.floor, this.grid);
  }

  /** Centre the floor's fade on a point; the grid moves in whole major cells (it stays on the
   * world's 0.5 m lines). */
  centreOn(x: number, z: number): void {
    this.floor.position.set(x, 0, z);
    this.grid.position.set(Math.round(x / MAJOR) * MAJOR, 0, Math.round(z / MAJOR) * MAJOR);
  }

  dispose(): void {
    for (const o of [this.floor, this.grid]) {
      o.geometry.dispose();
      (o.material as THREE.Material).dispose();
    }
  }
}
