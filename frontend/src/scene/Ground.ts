// The floor: a matte plane that takes the shadows, and a grid drawn in a fragment shader on a
// second plane (minor lines every 0.5 m, major every 2 m, fading with distance). A shader grid
// rather than GridHelper lines: long lines that pass behind the camera are clipped wrongly by
// some software rasterisers (SwiftShader drops them), triangles are not.
import * as THREE from "three";

const vertexShader = /* glsl */ `
  varying vec3 vWorld;
  void main() {
    vec4 world = modelMatrix * vec4(position, 1.0);
    vWorld = world.xyz;
    gl_Position = projectionMatrix * viewMatrix * world;
  }
`;

const fragmentShader = /* glsl */ `
  uniform vec3 uMinor;
  uniform vec3 uMajor;
  uniform vec2 uCentre;
  uniform float uRadius;
  varying vec3 vWorld;

  float lines(vec2 p, float spacing) {
    vec2 c = p / spacing;
    vec2 g = abs(fract(c - 0.5) - 0.5) / fwidth(c);
    return 1.0 - min(min(g.x, g.y), 1.0);
  }

  void main() {
    float minor = lines(vWorld.xz, 0.5);
    float major = lines(vWorld.xz, 2.0);
    float fade = 1.0 - smoothstep(uRadius * 0.35, uRadius, length(vWorld.xz - uCentre));
    vec3 colour = mix(uMinor, uMajor, major);
    float alpha = max(minor * 0.55, major * 0.85) * fade;
    if (alpha < 0.004) discard;
    gl_FragColor = vec4(colour, alpha);
  }
`;

export class Ground {
  readonly group = new THREE.Group();
  private readonly uniforms = {
    uMinor: { value: new THREE.Color("#2c323e") },
    uMajor: { value: new THREE.Color("#465066") },
    uCentre: { value: new THREE.Vector2(0, 0) },
    uRadius: { value: 18 },
  };

  constructor(floorColour = "#15181e") {
    const floor = new THREE.Mesh(
      new THREE.PlaneGeometry(120, 120),
      new THREE.MeshStandardMaterial({ color: floorColour, roughness: 0.95, metalness: 0 }),
    );
    floor.rotation.x = -Math.PI / 2;
    floor.receiveShadow = true;

    const grid = new THREE.Mesh(
      new THREE.PlaneGeometry(120, 120),
      new THREE.ShaderMaterial({
        uniforms: this.uniforms,
        vertexShader,
        fragmentShader,
        transparent: true,
        depthWrite: false,
        polygonOffset: true,
        polygonOffsetFactor: -1,
        polygonOffsetUnits: -1,
      }),
    );
    grid.rotation.x = -Math.PI / 2;
    grid.position.y = 0.001;
    grid.renderOrder = -1;
    this.group.add(floor, grid);
  }

  /** Centre the grid's fade on a point of the floor (the camera's target). */
  centreOn(x: number, z: number): void {
    this.uniforms.uCentre.value.set(x, z);
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
