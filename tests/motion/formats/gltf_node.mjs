// GLB checks by tools nobody here wrote, driven by tests/motion/formats/test_gltf_readers.py.
//
//   node gltf_node.mjs validate A.glb [B.glb …]
//       the Khronos glTF Validator's report per file: {file: {errors, warnings, infos, hints,
//       messages: [{code, severity, pointer, message}]}}
//   node gltf_node.mjs sample FILE.glb T1 [T2 …]
//       three.js GLTFLoader + AnimationMixer at each time (seconds): per person (skin), the
//       world positions of its 22 joints and of every skinned vertex (CPU skinning by
//       SkinnedMesh.getVertexPosition), {"people": [{"joints": [t][22][3],
//       "vertices": [t][V][3] | null}], "clips": [{name, duration, tracks}]}
// Prints one JSON object on stdout.
import { readFileSync } from "node:fs";
import validator from "gltf-validator";
import * as THREE from "three";
import { GLTFLoader } from "three/examples/jsm/loaders/GLTFLoader.js";

function bytes(path) {
  const b = readFileSync(path);
  return b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength);
}

async function validate(files) {
  const out = {};
  for (const file of files) {
    const report = await validator.validateBytes(new Uint8Array(bytes(file)), { maxIssues: 200 });
    const i = report.issues;
    out[file] = {
      errors: i.numErrors, warnings: i.numWarnings, infos: i.numInfos, hints: i.numHints,
      messages: i.messages.map((m) => ({ code: m.code, severity: m.severity, pointer: m.pointer,
                                         message: m.message })),
    };
  }
  return out;
}

function parse(buffer) {
  return new Promise((resolve, reject) => new GLTFLoader().parse(buffer, "", resolve, reject));
}

async function sample(file, times) {
  const gltf = await parse(bytes(file));
  const json = gltf.parser.json;
  const scene = gltf.scene;
  const mixer = new THREE.AnimationMixer(scene);
  for (const clip of gltf.animations) mixer.clipAction(clip).play();
  const people = [];
  for (let s = 0; s < json.skins.length; s++) {
    const joints = await Promise.all(json.skins[s].joints.map((n) => gltf.parser.getDependency("node", n)));
    let mesh = null;
    scene.traverse((o) => {
      if (o.isSkinnedMesh && o.skeleton.bones[0] === joints[0]) mesh = o;
    });
    people.push({ bones: joints, mesh, joints: [], vertices: mesh ? [] : null });
  }
  const v = new THREE.Vector3();
  for (const t of times) {
    mixer.setTime(t);
    scene.updateMatrixWorld(true);
    for (const p of people) {
      p.joints.push(p.bones.map((b) => b.getWorldPosition(v).toArray()));
      if (p.mesh) {
        p.mesh.skeleton.update();
        const count = p.mesh.geometry.attributes.position.count;
        const verts = [];
        for (let i = 0; i < count; i++) {
          p.mesh.getVertexPosition(i, v);        // skinned, in the mesh's space
          verts.push(v.applyMatrix4(p.mesh.matrixWorld).toArray());
        }
        p.vertices.push(verts);
      }
    }
  }
  return {
    people: people.map((p) => ({ joints: p.joints, vertices: p.vertices,
                                 names: p.bones.map((b) => b.name) })),
    clips: gltf.animations.map((c) => ({ name: c.name, duration: c.duration, tracks: c.tracks.length })),
  };
}

const [command, ...args] = process.argv.slice(2);
const result = command === "validate" ? await validate(args)
  : command === "sample" ? await sample(args[0], args.slice(1).map(Number))
  : null;
if (result === null) {
  console.error("usage: gltf_node.mjs validate FILE… | sample FILE T…");
  process.exit(2);
}
process.stdout.write(JSON.stringify(result));
