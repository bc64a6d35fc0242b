// Materials of the mannequin meshes (bodyMesh.ts). Both read the vertex colour (`color`) and a
// glow per vertex (attribute `glow`: 0, or how strongly a highlight emits its colour).
// - light (software WebGL): lighting per vertex. The vertex shader does the stage's lights
//   (hemisphere + sun + fill, Lambert), the glow, ACES tone mapping and the sRGB encoding; the
//   fragment shader only writes the interpolated colour. A software rasteriser pays per pixel, and
//   this is the cheapest pixel there is; the bodies are smooth, so Gouraud shading looks the same.
// - full: MeshStandardMaterial (PBR, shadows) with the glow added to its emissive light.
import * as THREE from "three";

/** The stage's lights (Stage.ts), as the light material bakes them in: colour × intensity. */
const HEMI_SKY = new THREE.Color("#dbe6ff").multiplyScalar(1.4);
const HEMI_GROUND = new THREE.Color("#2b2f38").multiplyScalar(1.4);
const SUN = new THREE.Color("#ffffff").multiplyScalar(2.2);
const FILL = new THREE.Color("#9fb4ff").multiplyScalar(0.5);
// towards the lights (their positions relative to their targets)
const SUN_DIR = new THREE.Vector3(3, 7, 5).normalize();
const FILL_DIR = new THREE.Vector3(-4, 3, -3).normalize();

const vertexShader = /* glsl */ `
  attribute float glow;
  uniform vec3 uSky;
  uniform vec3 uGround;
  uniform vec3 uSun;
  uniform vec3 uSunDir;
  uniform vec3 uFill;
  uniform vec3 uFillDir;
  varying vec3 vColour;
  #include <skinning_pars_vertex>

  // three's ACES filmic fit (tonemapping_pars_fragment), exposure 1
  vec3 rrtOdt(vec3 v) {
    vec3 a = v * (v + 0.0245786) - 0.000090537;
    vec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    return a / b;
  }
  vec3 aces(vec3 c) {
    const mat3 inMat = mat3(vec3(0.59719, 0.07600, 0.02840), vec3(0.35458, 0.90834, 0.13383),
                            vec3(0.04823, 0.01566, 0.83777));
    const mat3 outMat = mat3(vec3(1.60475, -0.10208, -0.00327), vec3(-0.53108, 1.10813, -0.07276),
                             vec3(-0.07367, -0.00605, 1.07602));
    return clamp(outMat * rrtOdt(inMat * (c / 0.6)), 0.0, 1.0);
  }
  vec3 srgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(0.41666)) - 0.055, step(vec3(0.0031308), c));
  }

  void main() {
    // a skinned mesh (the character skinned on the GPU, Character.ts) is skinned here as three's
    // own materials do; the chunks are empty for the mannequin (no USE_SKINNING)
    vec3 objectNormal = normal;
    vec3 transformed = position;
    #include <skinbase_vertex>
    #include <skinnormal_vertex>
    #include <skinning_vertex>
    // the mesh is never scaled: world normals are the model matrix's rotation of the normals
    vec3 n = normalize(mat3(modelMatrix) * objectNormal);
    vec3 irradiance = mix(uGround, uSky, 0.5 * n.y + 0.5)
      + max(dot(n, uSunDir), 0.0) * uSun + max(dot(n, uFillDir), 0.0) * uFill;
    vec3 albedo = color;
    vec3 radiance = albedo * 0.95 * irradiance * 0.3183099 + albedo * glow;
    vColour = srgb(aces(radiance));
    gl_Position = projectionMatrix * modelViewMatrix * vec4(transformed, 1.0);
  }
`;

const fragmentShader = /* glsl */ `
  varying vec3 vColour;
  void main() {
    gl_FragColor = vec4(vColour, 1.0);
  }
`;

/** The sky and floor-bounce colours of the per-vertex light (the UI theme; every body's
 * material shares these uniform values, so this relights them all). */
export function setBodyAmbient(sky: string, bounce: string): void {
  HEMI_SKY.set(sky).multiplyScalar(1.4);
  HEMI_GROUND.set(bounce).multiplyScalar(1.4);
}

/** Per-vertex lit material for software rendering (tone mapping and sRGB done in the shader). */
export function vertexLitMaterial(): THREE.ShaderMaterial {
  return new THREE.ShaderMaterial({
    uniforms: {
      uSky: { value: HEMI_SKY },
      uGround: { value: HEMI_GROUND },
      uSun: { value: SUN },
      uSunDir: { value: SUN_DIR },
      uFill: { value: FILL },
      uFillDir: { value: FILL_DIR },
    },
    vertexShader,
    fragmentShader,
    vertexColors: true,
    toneMapped: false,
  });
}

/** PBR material whose emissive light adds each vertex's `glow` × its colour. */
export function standardGlowMaterial(): THREE.MeshStandardMaterial {
  const mat = new THREE.MeshStandardMaterial({ roughness: 0.55, metalness: 0.05, vertexColors: true });
  mat.onBeforeCompile = (shader) => {
    shader.vertexShader = shader.vertexShader
      .replace("#include <common>", "#include <common>\nattribute float glow;\nvarying float vGlow;")
      .replace("#include <begin_vertex>", "#include <begin_vertex>\nvGlow = glow;");
    shader.fragmentShader = shader.fragmentShader
      .replace("#include <common>", "#include <common>\nvarying float vGlow;")
      .replace("#include <emissivemap_fragment>", "#include <emissivemap_fragment>\ntotalEmissiveRadiance += diffuseColor.rgb * vGlow;");
  };
  mat.customProgramCacheKey = () => "standard-glow";
  return mat;
}
