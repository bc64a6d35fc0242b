// A person drawn as the skinned humanoid (the mesh the GLB export skins, served at
// /humanoid.glb): the template loaded once by three's GLTFLoader and cloned per person with
// SkeletonUtils, its bones fitted to the person's rest offsets (bone positions, inverse bind
// matrices and the bind-pose vertices, as `humanoid.on_skeleton` does), and posed from the
// server's rotations (playback/rig.ts). Full quality skins in the vertex shader (three's
// skinning chunks, in the standard and the per-vertex lit material); light quality skins its
// ~850 vertices here at each pose and draws a plain mesh (software WebGL pays more for the
// shader's bone texture reads; docs/studio.md). Part colours and highlights are vertex
// colours, as the mannequin's: a vertex takes the colour of the bone it lies on; contact joints
// glow green, the selected / hovered part is painted on top (penetration is marked where the
// bodies overlap by the stage, PenetrationMarks.ts, not painted on the skin).
import * as THREE from "three";
import { GLTFLoader } from "three/examples/jsm/loaders/GLTFLoader.js";
import * as SkeletonUtils from "three/examples/jsm/utils/SkeletonUtils.js";
import type { Skeleton } from "../api/types";
import { NUM_JOINTS } from "../playback/frameBuffer";
import { fitPositions, restJoints, sampleRig, vertexJoints, type RigPerson } from "../playback/rig";
import { standardGlowMaterial, vertexLitMaterial } from "./bodyMaterial";
import { lodGeometry } from "./lightBody";
import { CONTACT_COLOUR, jointColours } from "./colours";
import { HOVER_COLOUR, SELECT_COLOUR } from "./Mannequin";
import { QUALITY, type QualitySettings } from "./quality";

export const HUMANOID_URL = "/humanoid.glb";
/** The skinned mesh's node in humanoid.glb (frontend/scripts/humanoid_asset.py). */
export const BODY_NODE = "humanoid_body";

/** Highlight states of a vertex, in order of precedence (0: its part colour). */
const CONTACT = 1;
const SELECTED = 2;
const HOVERED = 3;
const GLOW = [0, 0.7, 0.45, 0.45];
const PAINT = [null, CONTACT_COLOUR, SELECT_COLOUR, HOVER_COLOUR].map((c) => (c ? new THREE.Color(c) : null));
const SCRATCH = new THREE.Color();

/** The loaded template: humanoid.glb's scene (bones named as the skeleton, one skinned body). */
export type HumanoidTemplate = THREE.Object3D;

/** Parse humanoid.glb (its bytes) into the template. */
export function parseHumanoid(data: ArrayBuffer): Promise<HumanoidTemplate> {
  return new Promise((resolve, reject) => {
    new GLTFLoader().parse(data, "", (gltf) => {
      const body = gltf.scene.getObjectByName(BODY_NODE) as THREE.SkinnedMesh | undefined;
      if (!body?.isSkinnedMesh) reject(new Error(`humanoid.glb has no skinned '${BODY_NODE}'`));
      else resolve(gltf.scene);
    }, reject);
  });
}

/** The template with the light level of detail as its body (lightBody.ts). */
export function lightTemplate(template: HumanoidTemplate): HumanoidTemplate {
  const light = SkeletonUtils.clone(template); // (a plain clone would keep the template's bones)
  const body = light.getObjectByName(BODY_NODE) as THREE.SkinnedMesh;
  body.geometry = lodGeometry(body.geometry);
  return light;
}

let loading: Promise<HumanoidTemplate> | null = null;

/** The template, fetched and parsed once per page (a failed load is tried again next time);
 * `light`: with the light level of detail. */
export async function loadHumanoid(light = false, url = HUMANOID_URL): Promise<HumanoidTemplate> {
  loading ??= fetch(url)
    .then((res) => {
      if (!res.ok) throw new Error(`${url}: HTTP ${res.status}`);
      return res.arrayBuffer();
    })
    .then(parseHumanoid)
    .catch((err) => {
      loading = null;
      throw err;
    });
  const full = await loading;
  return light ? lightTemplate(full) : full;
}

export class Character {
  /** The clone's root: the bone hierarchy and the body (its skinned mesh, a sibling). */
  readonly group: THREE.Object3D;
  readonly mesh: THREE.SkinnedMesh;
  /** Joints of the selected / hovered body part, painted on top of the part colours. */
  selected = new Set<number>();
  hovered = new Set<number>();
  /** The bones by skeleton joint index. */
  readonly bones: THREE.Bone[];
  /** Per vertex: the strongest joint (contacts) and the bone, by its child joint (the rest). */
  private readonly vertexJoint: Uint8Array;
  private readonly vertexBone: Uint8Array;
  private readonly base: Float32Array;
  private readonly colour: THREE.BufferAttribute;
  private readonly glow: THREE.BufferAttribute;
  /** Per joint: contact (by the strongest joint), and its selected / hovered paint. */
  private readonly jointState = new Uint8Array(NUM_JOINTS);
  private readonly pickState = new Uint8Array(NUM_JOINTS);
  private painted = false;
  /** The skinned bounds (what a ray tests first) are older than the pose. */
  private boundsStale = true;
  private readonly q = new Float32Array(NUM_JOINTS * 4);
  private readonly root = new Float32Array(3);
  /** Skinning on the CPU (light quality): the mesh drawn instead of the skinned one, and what
   * it is skinned from. */
  private readonly cpu: {
    mesh: THREE.Mesh;
    position: THREE.BufferAttribute;
    normal: THREE.BufferAttribute;
    bindPosition: Float32Array;
    bindNormal: ArrayLike<number>;
    skinIndex: ArrayLike<number>;
    skinWeight: ArrayLike<number>;
  } | null = null;

  /** Person `person` on their own rest offsets (22 × xyz, the rig's). `cpuSkinning`: skin the
   * vertices here at each pose and draw a plain mesh (a software rasteriser pays for the bone
   * texture reads of GPU skinning per vertex; docs/studio.md), else skin in the vertex shader. */
  constructor(
    template: HumanoidTemplate,
    skeleton: Skeleton,
    readonly person: number,
    offsets: ArrayLike<number>,
    quality: QualitySettings = QUALITY.full,
    cpuSkinning = false,
  ) {
    this.group = SkeletonUtils.clone(template);
    const body = this.group.getObjectByName(BODY_NODE) as THREE.SkinnedMesh;
    this.mesh = body;
    const byName = new Map(body.skeleton.bones.map((b) => [b.name, b]));
    this.bones = skeleton.joints.map((name) => {
      const b = byName.get(name);
      if (!b) throw new Error(`humanoid.glb has no bone '${name}'`);
      return b;
    });
    // fit the bones: the template's rest skeleton → the person's
    const templateOffsets = new Float32Array(NUM_JOINTS * 3);
    this.bones.forEach((b, j) => b.position.toArray(templateOffsets, 3 * j));
    const templateRest = restJoints(templateOffsets, skeleton.parents);
    const rest = restJoints(offsets, skeleton.parents);
    this.bones.forEach((b, j) => b.position.fromArray(offsets, 3 * j));
    // the template's geometry is shared by clones: this person gets a copy with its own fitted
    // positions, colours and glow
    const geometry = body.geometry.clone();
    const skinIndex = geometry.getAttribute("skinIndex").array;
    const skinWeight = geometry.getAttribute("skinWeight").array;
    const fitted = fitPositions(geometry.getAttribute("position").array, skinIndex, skinWeight, templateRest, rest);
    geometry.setAttribute("position", new THREE.BufferAttribute(fitted, 3));
    // the chest and back take the trunk's bone (not a collar's): no arm colour bleeds onto them
    const { joint, bone } = vertexJoints(skinIndex, skinWeight, skeleton.parents, skeleton.joints);
    this.vertexJoint = joint;
    this.vertexBone = bone;
    const colours = jointColours(skeleton, person).map((c) => new THREE.Color(c));
    const n = joint.length;
    this.base = new Float32Array(3 * n);
    for (let v = 0; v < n; v++) colours[bone[v]].toArray(this.base, 3 * v);
    this.colour = new THREE.BufferAttribute(this.base.slice(), 3);
    this.glow = new THREE.BufferAttribute(new Float32Array(n), 1);
    geometry.setAttribute("color", this.colour);
    geometry.setAttribute("glow", this.glow);
    geometry.computeBoundingSphere();
    body.geometry = geometry;
    body.material = quality.shadowMap ? standardGlowMaterial() : vertexLitMaterial();
    body.castShadow = quality.shadowMap;
    body.frustumCulled = false; // the people walk (bounds computed again when a ray needs them)
    body.userData = { person, vertexJoint: bone };
    // the inverse bind matrices of the person's rest pose (no rotation: minus the joint's rest
    // position); the clone's skeleton shares the template's array, so this one is new
    body.skeleton.boneInverses = body.skeleton.bones.map((b) => {
      const j = this.bones.indexOf(b);
      return new THREE.Matrix4().makeTranslation(-rest[3 * j], -rest[3 * j + 1], -rest[3 * j + 2]);
    });
    body.bind(body.skeleton, new THREE.Matrix4());
    if (cpuSkinning) {
      const dynamic = () => new THREE.BufferAttribute(new Float32Array(3 * n), 3).setUsage(THREE.DynamicDrawUsage);
      const drawn = new THREE.BufferGeometry();
      drawn.setIndex(geometry.getIndex());
      const position = dynamic();
      const normal = dynamic();
      drawn.setAttribute("position", position);
      drawn.setAttribute("normal", normal);
      drawn.setAttribute("color", this.colour);
      drawn.setAttribute("glow", this.glow);
      const mesh = new THREE.Mesh(drawn, body.material);
      mesh.castShadow = body.castShadow;
      mesh.frustumCulled = false;
      mesh.userData = body.userData;
      body.visible = false; // it keeps the bones and the bind pose; the renderer skips it
      this.group.add(mesh);
      this.cpu = { mesh, position, normal, bindPosition: fitted, bindNormal: geometry.getAttribute("normal").array, skinIndex, skinWeight };
    }
  }

  /** Skin the vertices from the posed bones (CPU skinning): each vertex by its weighted bones'
   * matrices (bone world × inverse bind; the bind matrix is the identity). No allocation. */
  private skinOnCpu(): void {
    const cpu = this.cpu!;
    this.group.updateMatrixWorld(true);
    this.mesh.skeleton.update(); // boneMatrices: per bone, world × inverse bind (column-major)
    const m = this.mesh.skeleton.boneMatrices!;
    const { bindPosition: p, bindNormal: nb, skinIndex, skinWeight } = cpu;
    const pos = cpu.position.array as Float32Array;
    const nrm = cpu.normal.array as Float32Array;
    const n = pos.length / 3;
    for (let v = 0; v < n; v++) {
      // the blended matrix's 3 × 4 part (columns 0–2: rotation, 3: translation)
      let a0 = 0, a1 = 0, a2 = 0, a4 = 0, a5 = 0, a6 = 0, a8 = 0, a9 = 0, a10 = 0, a12 = 0, a13 = 0, a14 = 0;
      for (let k = 0; k < 4; k++) {
        const w = skinWeight[4 * v + k];
        if (w === 0) continue;
        const o = 16 * skinIndex[4 * v + k];
        a0 += w * m[o]; a1 += w * m[o + 1]; a2 += w * m[o + 2];
        a4 += w * m[o + 4]; a5 += w * m[o + 5]; a6 += w * m[o + 6];
        a8 += w * m[o + 8]; a9 += w * m[o + 9]; a10 += w * m[o + 10];
        a12 += w * m[o + 12]; a13 += w * m[o + 13]; a14 += w * m[o + 14];
      }
      const i = 3 * v;
      const x = p[i], y = p[i + 1], z = p[i + 2];
      pos[i] = a0 * x + a4 * y + a8 * z + a12;
      pos[i + 1] = a1 * x + a5 * y + a9 * z + a13;
      pos[i + 2] = a2 * x + a6 * y + a10 * z + a14;
      const nx = nb[i], ny = nb[i + 1], nz = nb[i + 2];
      nrm[i] = a0 * nx + a4 * ny + a8 * nz; // the shader normalises
      nrm[i + 1] = a1 * nx + a5 * ny + a9 * nz;
      nrm[i + 2] = a2 * nx + a6 * ny + a10 * nz;
    }
    cpu.position.needsUpdate = true;
    cpu.normal.needsUpdate = true;
    cpu.mesh.geometry.boundingSphere = null; // a ray recomputes it
  }

  /** Pose at frame t of the rig, blended by `weight` towards frame `next`; paints the
   * highlights of frame t. No allocation. */
  setPose(rig: RigPerson, t: number, next: number, weight: number, contacts: Set<number>): void {
    sampleRig(rig, t, next, weight, this.q, this.root);
    const { bones, q, root } = this;
    for (let j = 0; j < NUM_JOINTS; j++) bones[j].quaternion.fromArray(q, 4 * j);
    bones[0].position.fromArray(root);
    this.boundsStale = true;
    if (this.cpu) this.skinOnCpu();
    this.paint(contacts);
  }

  /** Write the vertex colours when a joint's highlight changed. */
  private paint(contacts: Set<number>): void {
    let changed = !this.painted;
    for (let j = 0; j < NUM_JOINTS; j++) {
      const js = contacts.has(j) ? CONTACT : 0;
      const ks = this.selected.has(j) ? SELECTED : this.hovered.has(j) ? HOVERED : 0;
      if (js !== this.jointState[j] || ks !== this.pickState[j]) changed = true;
      this.jointState[j] = js;
      this.pickState[j] = ks;
    }
    if (!changed) return;
    this.painted = true;
    const colours = this.colour.array as Float32Array;
    const glow = this.glow.array as Float32Array;
    for (let v = 0; v < this.vertexJoint.length; v++) {
      const vj = this.vertexJoint[v];
      const vb = this.vertexBone[v];
      const state = this.jointState[vj] || this.pickState[vb];
      const c = PAINT[state];
      if (c) c.toArray(colours, 3 * v);
      else {
        colours[3 * v] = this.base[3 * v];
        colours[3 * v + 1] = this.base[3 * v + 1];
        colours[3 * v + 2] = this.base[3 * v + 2];
      }
      glow[v] = GLOW[state];
    }
    this.colour.needsUpdate = true;
    this.glow.needsUpdate = true;
  }

  /** World position of joint j's bone now (after the group's matrices are updated). */
  jointPosition(j: number, out = new THREE.Vector3()): THREE.Vector3 {
    return this.bones[j].getWorldPosition(out);
  }

  /** Meshes a pointer ray can hit: the body; userData {person, vertexJoint} as the mannequin's. */
  get pickable(): THREE.Object3D[] {
    if (this.cpu) return [this.cpu.mesh];
    if (this.boundsStale) {
      this.group.updateMatrixWorld(true);
      this.mesh.computeBoundingSphere(); // from the posed bones (SkinnedMesh), in place
      this.boundsStale = false;
    }
    return [this.mesh];
  }

  /** The colour and glow now of the first vertex whose strongest joint is j, for tests. */
  paintOf(j: number): { colour: string; glow: number } | null {
    const v = this.vertexJoint.indexOf(j);
    if (v < 0) return null;
    return { colour: "#" + SCRATCH.fromArray(this.colour.array, 3 * v).getHexString(), glow: this.glow.getX(v) };
  }

  /** The colours now on the skin of the bone ending at joint j (as #rrggbb → vertices), for tests. */
  boneColours(j: number): Map<string, number> {
    const out = new Map<string, number>();
    this.vertexBone.forEach((b, v) => {
      if (b !== j || this.vertexJoint[v] === j) return;
      const c = "#" + SCRATCH.fromArray(this.colour.array, 3 * v).getHexString();
      out.set(c, (out.get(c) ?? 0) + 1);
    });
    return out;
  }

  dispose(): void {
    this.cpu?.mesh.geometry.dispose();
    this.mesh.geometry.dispose();
    (this.mesh.material as THREE.Material).dispose();
    this.mesh.skeleton.dispose();
    this.group.removeFromParent();
  }
}
