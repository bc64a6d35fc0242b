// The floor for software WebGL (light quality): Ground.ts's grid (minor lines every 0.5 m, major
// every 2 m, fading out with distance) without its per-pixel procedural shader, which cost a
// software rasteriser about a third of each frame. The grid is line segments whose vertex colours
// carry the fade; the fragment shader only writes the interpolated colour, so the grid costs only
// the pixels of its lines. No floor plane: the stage clears to the floor colour (FLOOR_COLOUR)
// instead, since even a flat-coloured plane over half the screen cost about 6 ms a frame there;
// the horizon is where the lines fade out. Lines are cut into 2 m pieces: long lines that pass
// behind the camera are clipped wrongly by some software rasterisers (SwiftShader), short ones
// are not.
import * as THREE from "three";
import type { StagePalette } from "./palette";

/** The floor colour of Ground.ts: the light stage's background. */
export const FLOOR_COLOUR = "#181b22";
// m: where the lines have faded out. Minor lines sooner: far away, at a grazing angle, lines
// 0.5 m apart crowd into a band of aliased pixels (there is no MSAA in light quality).
const MAJOR_RADIUS = 14;
const MINOR_RADIUS = 6.5;
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

/** Drawn first, behind everything, without writing depth. */
function flatMaterial(): THREE.ShaderMaterial {
  return new THREE.ShaderMaterial({ vertexShader, fragmentShader, toneMapped: false, depthWrite: false });
}

const smooth = (a: number, b: number, x: number) => {
  const t = Math.min(1, Math.max(0, (x - a) / (b - a)));
  return t * t * (3 - 2 * t);
};

export class LineGround {
  readonly group = new THREE.Group();
  private readonly grid: THREE.LineSegments;
  /** Per vertex: major line or not, and its fade (0 near, 1 faded out), to recolour it. */
  private readonly kinds: { major: boolean; fade: number }[] = [];

  constructor() {
    const floorColour = display(FLOOR_COLOUR);
    const c = new THREE.Color();
    // the grid: lines x = k·0.5 and z = k·0.5 within their radius, in 2 m pieces
    const minor = display("#252a34");
    const major = display("#363e4e");
    const points: number[] = [];
    const cols: number[] = [];
    for (let k = -MAJOR_RADIUS / MINOR; k <= MAJOR_RADIUS / MINOR; k++) {
      const t = k * MINOR;
      const isMajor = Math.abs(t % MAJOR) < 1e-6;
      const lineColour = isMajor ? major : minor;
      const radius = isMajor ? MAJOR_RADIUS : MINOR_RADIUS;
      if (Math.abs(t) >= radius) continue;
      const half = Math.sqrt(radius * radius - t * t);
      for (let s = -half; s < half; s += PIECE) {
        const e = Math.min(half, s + PIECE);
        for (const [x, z] of [[t, s], [t, e], [s, t], [e, t]]) {
          points.push(x, 0.002, z);
          const fade = smooth(radius * 0.3, radius, Math.hypot(x, z));
          c.copy(lineColour).lerp(floorColour, fade).toArray(cols, cols.length);
          this.kinds.push({ major: isMajor, fade });
        }
      }
    }
    const lines = new THREE.BufferGeometry();
    lines.setAttribute("position", new THREE.Float32BufferAttribute(points, 3));
    lines.setAttribute("color", new THREE.Float32BufferAttribute(cols, 3));
    this.grid = new THREE.LineSegments(lines, flatMaterial());
    this.grid.renderOrder = -1;
    this.group.add(this.grid);
  }

  /** Recolour the grid for a floor colour (the UI theme; the stage clears to `p.floor`). */
  setPalette(p: StagePalette): void {
    const floorColour = display(p.floor);
    const [minor, major] = [display(p.minor), display(p.major)];
    const colours = this.grid.geometry.getAttribute("color") as THREE.BufferAttribute;
    const c = new THREE.Color();
    this.kinds.forEach((k, i) => {
      c.copy(k.major ? major : minor).lerp(floorColour, k.fade);
      colours.setXYZ(i, c.r, c.g, c.b);
    });
    colours.needsUpdate = true;
  }

  /** Centre the fade on a point: the grid moves in whole major cells (it stays on the world's
   * 0.5 m lines). */
  centreOn(x: number, z: number): void {
    this.grid.position.set(Math.round(x / MAJOR) * MAJOR, 0, Math.round(z / MAJOR) * MAJOR);
  }

  dispose(): void {
    this.grid.geometry.dispose();
    (this.grid.material as THREE.Material).dispose();
  }
}
