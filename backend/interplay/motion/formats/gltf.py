"""GLB (binary glTF 2.0) export of a motion for one or two people, written with pygltflib (the
one module of `motion/` that imports anything but numpy).

    data = write_glb(people, fps=20)              # bytes: skinned humanoids + one animation
    data = write_glb(people, mesh=False)          # skeletons + the animation, no mesh
    data = humanoid_glb()                         # the bare mesh on the template, rest pose

Layout, per person k (scene roots "person1", "person2": people are numbered from 1, as the
studio and the BVH file names number them): a node tree of the 22 smpl22 joints
named as the skeleton (`skeleton.JOINT_NAMES`; each person's under its own root), each joint's
rest translation its offset from its parent (the pelvis's: its rest height), rotations identity
in the bind pose; a skin over those joints (in skeleton order, so JOINTS_0 holds skeleton joint
indices) with inverse bind matrices of the rest pose; with the mesh, a node "person{k+1}_body"
holding the humanoid (`formats/humanoid.py`) fitted to the person's rest offsets, skinned with
up to four joints per vertex. One animation for the whole motion: for every person the
pelvis's translation (the root, metres) and every joint's local rotation (unit quaternions
x, y, z, w, from `rig.solve_rig`), keyed at frame i / fps seconds, LINEAR. Y up, metres, the
rest pose facing +Z; the person's left is +X.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import pygltflib as gl

from interplay.motion import skeleton as sk
from interplay.motion.formats.humanoid import Humanoid, humanoid, on_skeleton
from interplay.motion.formats.presets import (
    END_NAMES,
    UNITS,
    bone_axes,
    check_fps_units_names,
    export_rigs,
    joint_names,
)
from interplay.motion.rig import Rig, end_sites
from interplay.motion.rotations import matrix_to_quat

MEDIA_TYPE = "model/gltf-binary"
GENERATOR = "Interplay (pygltflib)"
# Base colours (linear RGBA) of person 0 and person 1.
PERSON_COLOURS = ((0.32, 0.52, 0.78, 1.0), (0.85, 0.45, 0.25, 1.0))

_COMPONENT = {np.dtype(np.float32): gl.FLOAT, np.dtype(np.uint8): gl.UNSIGNED_BYTE,
              np.dtype(np.uint16): gl.UNSIGNED_SHORT, np.dtype(np.uint32): gl.UNSIGNED_INT}
_TYPE = {1: gl.SCALAR, 2: gl.VEC2, 3: gl.VEC3, 4: gl.VEC4, 16: gl.MAT4}


class _Buffer:
    """The GLB's one binary buffer: arrays appended as buffer views and accessors."""

    def __init__(self, doc: gl.GLTF2):
        self.doc = doc
        self.chunks: list[bytes] = []
        self.size = 0

    def add(self, array: np.ndarray, target: int | None = None, bounds: bool = False) -> int:
        """Accessor index of array (N,) or (N, k): one element a row, little-endian."""
        a = np.ascontiguousarray(array)
        width = 1 if a.ndim == 1 else int(np.prod(a.shape[1:]))
        data = a.astype(a.dtype.newbyteorder("<"), copy=False).tobytes()
        self.doc.bufferViews.append(gl.BufferView(buffer=0, byteOffset=self.size,
                                                  byteLength=len(data), target=target))
        pad = -len(data) % 4
        self.chunks.append(data + b"\0" * pad)
        self.size += len(data) + pad
        flat = a.reshape(len(a), width)
        self.doc.accessors.append(gl.Accessor(
            bufferView=len(self.doc.bufferViews) - 1, componentType=_COMPONENT[a.dtype],
            count=len(a), type=_TYPE[width],
            min=flat.min(axis=0).tolist() if bounds else None,
            max=flat.max(axis=0).tolist() if bounds else None))
        return len(self.doc.accessors) - 1

    def blob(self) -> bytes:
        return b"".join(self.chunks)


def _shared_mesh_data(buf: _Buffer, mesh: Humanoid) -> dict[str, int]:
    """Accessors every person's mesh shares (only positions differ between people)."""
    index_type = np.uint16 if len(mesh.positions) < 65535 else np.uint32
    return {
        "indices": buf.add(mesh.triangles.reshape(-1).astype(index_type), gl.ELEMENT_ARRAY_BUFFER),
        "NORMAL": buf.add(mesh.normals.astype(np.float32), gl.ARRAY_BUFFER),
        "JOINTS_0": buf.add(mesh.joints.astype(np.uint8), gl.ARRAY_BUFFER),
        "WEIGHTS_0": buf.add(mesh.weights.astype(np.float32), gl.ARRAY_BUFFER),
    }


def _inverse_bind(bind: np.ndarray, rest: np.ndarray) -> np.ndarray:
    """(N, 16) float32 column-major inverse bind matrices of joints whose bind pose is the
    rotation bind (N, 3, 3) at rest (N, 3): [bind^T | -bind^T rest]."""
    m = np.tile(np.eye(4), (len(rest), 1, 1))
    m[:, :3, :3] = np.swapaxes(bind, -1, -2)
    m[:, :3, 3] = -np.einsum("nji,nj->ni", bind, rest)
    return np.swapaxes(m, 1, 2).reshape(len(rest), 16).astype(np.float32)


def _quat(m: np.ndarray) -> list[float]:
    q = matrix_to_quat(m)
    return [float(x) for x in q[[1, 2, 3, 0]]]


def _add_person(doc: gl.GLTF2, buf: _Buffer, label: str, colour: Sequence[float],
                offsets: np.ndarray, mesh: Humanoid | None, shared: dict[str, int] | None,
                layout: _Layout) -> int:
    """Adds a person's root node `label` over its joint nodes (then, with Mixamo names, its
    end bones), its skin and (with mesh) its body `<label>_body`; returns the first joint's
    node index (joint j is node first + j). offsets in metres; the file's units by layout."""
    first = len(doc.nodes) + 1                       # after the person's root node
    doc.scenes[0].nodes.append(len(doc.nodes))
    doc.nodes.append(gl.Node(name=label, children=[first]))
    bind = layout.bind(offsets)
    ends = end_sites(offsets) if layout.ends else {}
    end_node = {j: first + sk.NUM_JOINTS + k for k, j in enumerate(ends)}
    rest = sk.rest_joints(offsets)
    for j, name in enumerate(layout.names):
        p = sk.PARENTS[j]
        parent = np.eye(3) if p < 0 else bind[p]
        node = gl.Node(name=layout.prefix(label) + name,
                       translation=[float(x) for x in parent.T @ offsets[j] * layout.scale],
                       children=[first + c for c in sk.children(j)] + ([end_node[j]] if j in ends else []))
        if layout.axes:
            node.rotation = _quat(parent.T @ bind[j])
        doc.nodes.append(node)
    for j, tip in ends.items():
        doc.nodes.append(gl.Node(name=layout.prefix(label) + END_NAMES[layout.naming][j],
                                 translation=[float(x) for x in bind[j].T @ tip * layout.scale]))
    tips = np.array([rest[j] + ends[j] for j in ends]).reshape(-1, 3)
    ibm = _inverse_bind(np.concatenate([bind, bind[list(ends)]]),
                        np.concatenate([rest, tips]) * layout.scale)
    doc.skins.append(gl.Skin(name=label, skeleton=first,
                             joints=list(range(first, first + sk.NUM_JOINTS + len(ends))),
                             inverseBindMatrices=buf.add(ibm)))
    if mesh is not None and shared is not None:
        doc.materials.append(gl.Material(
            name=label, pbrMetallicRoughness=gl.PbrMetallicRoughness(
                baseColorFactor=[float(c) for c in colour],
                metallicFactor=0.0, roughnessFactor=0.8)))
        positions = on_skeleton(mesh, offsets) * np.float32(layout.scale)
        attributes = gl.Attributes(POSITION=buf.add(positions, gl.ARRAY_BUFFER, bounds=True),
                                   NORMAL=shared["NORMAL"], JOINTS_0=shared["JOINTS_0"],
                                   WEIGHTS_0=shared["WEIGHTS_0"])
        doc.meshes.append(gl.Mesh(name=f"{label}_body", primitives=[gl.Primitive(
            attributes=attributes, indices=shared["indices"], material=len(doc.materials) - 1)]))
        # A scene root: a skinned mesh's own parents would not move it.
        doc.nodes.append(gl.Node(name=f"{label}_body", mesh=len(doc.meshes) - 1,
                                 skin=len(doc.skins) - 1))
        doc.scenes[0].nodes.append(len(doc.nodes) - 1)
    return first


@dataclass(frozen=True)
class _Layout:
    """How the joints are written: names (SMPL's or Mixamo's; each prefixed "person<k>_"
    when there are several people), units (scale: file units per metre), and with Mixamo
    names its rest axes (`presets.bone_axes`) and end bones."""
    naming: str = "smpl"
    scale: float = 1.0
    several: bool = False

    @property
    def names(self) -> tuple[str, ...]:
        return joint_names(self.naming)

    @property
    def axes(self) -> bool:
        return self.naming == "mixamo"

    @property
    def ends(self) -> bool:
        return self.naming == "mixamo"

    def prefix(self, label: str) -> str:
        return f"{label}_" if self.several else ""

    def bind(self, offsets: np.ndarray) -> np.ndarray:
        if not self.axes:
            return np.tile(np.eye(3), (sk.NUM_JOINTS, 1, 1))
        return bone_axes(offsets, end_sites(offsets))

    def rotations(self, rig: Rig, bind: np.ndarray) -> np.ndarray:
        """The rig's local rotations (T, 22, 4) w x y z for nodes whose rest rotations are
        bind's: parent_bind^T · local · bind, one sign through time."""
        if not self.axes:
            q = np.asarray(rig.rotations, np.float64)
            return q / np.linalg.norm(q, axis=-1, keepdims=True)
        parent = np.stack([np.eye(3) if p < 0 else bind[p] for p in sk.PARENTS])
        m = np.swapaxes(parent, -1, -2)[None] @ rig.matrices() @ bind[None]
        q = matrix_to_quat(m)
        for i in range(1, len(q)):
            q[i, np.sum(q[i] * q[i - 1], axis=-1) < 0] *= -1.0
        return q


def _document(extras: dict) -> gl.GLTF2:
    return gl.GLTF2(asset=gl.Asset(version="2.0", generator=GENERATOR), scene=0,
                    scenes=[gl.Scene(name="interplay", nodes=[])], extras=extras)


def _finish(doc: gl.GLTF2, buf: _Buffer) -> bytes:
    blob = buf.blob()
    doc.buffers = [gl.Buffer(byteLength=len(blob))]
    doc.set_binary_blob(blob)
    return b"".join(doc.save_to_bytes())


def rigs_glb(rigs: Sequence[Rig], fps: float = sk.FPS, *, mesh: bool = True,
             name: str = "motion", units: str = "m", names: str = "smpl") -> bytes:
    """The GLB of one or more people's rigs (one frame rate, one length, metres), written
    in units ("m" or "cm") with joint names ("smpl" or "mixamo")."""
    if not rigs:
        raise ValueError("a GLB needs at least one person")
    check_fps_units_names(fps, units, names)
    frames = {r.frames for r in rigs}
    if len(frames) != 1:
        raise ValueError(f"people have different lengths {sorted(frames)}")
    t = frames.pop()
    layout = _Layout(naming=names, scale=UNITS[units], several=len(rigs) > 1)
    doc = _document({"fps": float(fps), "frames": t, "skeleton": sk.SKELETON_NAME,
                     "units": units, "names": names})
    buf = _Buffer(doc)
    body = humanoid() if mesh else None
    shared = _shared_mesh_data(buf, body) if body is not None else None
    times = buf.add((np.arange(t) / float(fps)).astype(np.float32), bounds=True)
    animation = gl.Animation(name=name)
    for k, rig in enumerate(rigs):
        offsets = np.asarray(rig.offsets, np.float64)
        first = _add_person(doc, buf, f"person{k + 1}", PERSON_COLOURS[k % len(PERSON_COLOURS)],
                            offsets, body, shared, layout)
        outputs = [(first + sk.PELVIS, "translation", np.asarray(rig.root * layout.scale, np.float32))]
        q = layout.rotations(rig, layout.bind(offsets))
        xyzw = q[..., [1, 2, 3, 0]].astype(np.float32)
        outputs += [(first + j, "rotation", xyzw[:, j]) for j in range(sk.NUM_JOINTS)]
        for node, path, values in outputs:
            animation.samplers.append(gl.AnimationSampler(
                input=times, output=buf.add(values), interpolation=gl.ANIM_LINEAR))
            animation.channels.append(gl.AnimationChannel(
                sampler=len(animation.samplers) - 1,
                target=gl.AnimationChannelTarget(node=node, path=path)))
    doc.animations.append(animation)
    return _finish(doc, buf)


def write_glb(people: Sequence[np.ndarray], fps: float = sk.FPS, *, mesh: bool = True,
              name: str = "motion", out_fps: float | None = None, units: str = "m",
              names: str = "smpl", leaves: Sequence[Mapping[str, np.ndarray] | None] | None = None
              ) -> bytes:
    """The GLB of a motion: people (T, 22, 3) each at fps, as `presets.export_rigs` writes
    them (each on the rest offsets of their own motion, all over one floor, no hand, knee or
    foot under it, resampled to out_fps keeping the last pose, with each person's explicit
    head / wrist rotations `leaves` where given), in units with names."""
    check_fps_units_names(out_fps, units, names)
    people = [np.asarray(p, np.float64) for p in people]
    rate = fps if out_fps is None else float(out_fps)
    return rigs_glb(export_rigs(people, fps, rate, leaves=leaves), rate, mesh=mesh, name=name, units=units, names=names)


def humanoid_glb(offsets: np.ndarray = sk.REST_OFFSETS) -> bytes:
    """The humanoid alone, skinned, in the rest pose (no animation): the front end's asset."""
    doc = _document({"skeleton": sk.SKELETON_NAME})
    buf = _Buffer(doc)
    body = humanoid()
    _add_person(doc, buf, "humanoid", (0.8, 0.8, 0.8, 1.0), np.asarray(offsets, np.float64), body,
                _shared_mesh_data(buf, body), _Layout())
    return _finish(doc, buf)
