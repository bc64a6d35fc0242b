// The floor in full quality (light quality has LineGround.ts): one opaque plane whose fragment
// shader draws the floor colour, a grid (minor lines every 0.5 m, major every 2 m) and a fade
// into the background with distance, antialiased per pixel. A shader grid rather than
// GridHelper lines: long lines that pass behind the camera are clipped wrongly by some software
// rasterisers (SwiftShader drops them), triangles are not. With a shadow map, a
// ShadowMaterial plane on top darkens where the people's shadows fall.
import * as THREE from "three";
import type { StagePalette } from "./palette";

const vertexShader = /* glsl */ `
  varying vec3 vWorld;
  void main() {
    vec4 world = modelMatrix * vec4(position, 1.0);
    vWorld = world.xyz;
    gl_Position = projectionMatrix * viewMatrix * world;
  }
`;

const fragmentShader = /* glsl */ `
  uniform vec3 uFloor;
  uniform vec3 uMinor;
  uniform vec3 uMajor;
  uniform vec3 uFar;
  uniform vec2 uCentre;
  uniform float uRadius;
  varying vec3 vWorld;

  // 1 on a line of the grid with this spacing, 0 off it; antialiased over one pixel (w: the
  // world size of a pixel).
  float lines(vec2 p, vec2 w, float spacing) {
    vec2 g = abs(fract(p / spacing - 0.5) - 0.5) * spacing / w;
    return 1.0 - min(min(g.x, g.y), 1.0);
  }

  void main() {
    vec2 w = fwidth(vWorld.xz);
    vec3 colour = mix(uFloor, uMinor, lines(vWorld.xz, w, 0.5) * 0.8);
    colour = mix(colour, uMajor, lines(vWorld.xz, w, 2.0) * 0.9);
    float fade = smoothstep(uRadius * 0.3, uRadius, length(vWorld.xz - uCentre));
    // colours are display (sRGB) values already: no colour-space conversion per pixel
    gl_FragColor = vec4(mix(colour, uFar, fade), 1.0);
  }
`;

/** A #rrggbb colour as raw display values (no conversion to the linear working space). */
function display(hex: string): THREE.Vector3 {
  const c = new THREE.Color().setStyle(hex, THREE.LinearSRGBColorSpace);
  return new THREE.Vector3(c.r, c.g, c.b);
}

export class Ground {
  readonly group = new THREE.Group();
  private readonly uniforms = {
    uFloor: { value: display("#181b22") },
    uMinor: { value: display("#252a34") },
    uMajor: { value: display("#363e4e") },
    uFar: { value: display("#14161b") },
    uCentre: { value: new THREE.Vector2(0, 0) },
    uRadius: { value: 22 },
  };

  constructor(background: string, shadows: boolean) {
    this.uniforms.uFar.value.copy(display(background));
    const floor = new THREE.Mesh(
      new THREE.PlaneGeometry(200, 200),
      new THREE.ShaderMaterial({ uniforms: this.uniforms, vertexShader, fragmentShader, toneMapped: false }),
    );
    floor.rotation.x = -Math.PI / 2;
    this.group.add(floor);
    if (shadows) {
      const catcher = new THREE.Mesh(
        new THREE.PlaneGeometry(60, 60),
        new THREE.ShadowMaterial({ opacity: 0.5, depthWrite: false }),
      );
      catcher.rotation.x = -Math.PI / 2;
      catcher.position.y = 0.001;
      catcher.receiveShadow = true;
      this.group.add(catcher);
    }
  }

  /** Recolour the floor (the UI theme): floor, grid lines and the colour it fades into. */
  setPalette(p: StagePalette): void {
    this.uniforms.uFloor.value.copy(display(p.floor));
    this.uniforms.uMinor.value.copy(display(p.minor));
    this.uniforms.uMajor.value.copy(display(p.major));
    this.uniforms.uFar.value.copy(display(p.background));
  }

  /** Centre the fade (and the shadow catcher) on a point of the floor. */
  centreOn(x: number, z: number): void {
    this.uniforms.uCentre.value.set(x, z);
    const catcher = this.group.children[1];
    catcher?.position.set(x, 0.001, z);
  }

  dispose(): void {
    this.group.traverse((o) => {
      if (o instanceof THREE.Mesh) {
        o.geometry.dispose();
        (o.material as THREE.Material).dispose();
      }
    });
  }
}
