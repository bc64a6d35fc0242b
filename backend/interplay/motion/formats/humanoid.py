"""A procedural, smooth humanoid mesh bound to the 22 smpl22 joints (numpy only).

The body is an implicit surface, a smooth union of ellipsoids, tapered capsules and rounded
boxes placed on the rest pose (`skeleton.rest_joints()`: Y up, metres, facing +Z, arms out
along ±X), turned into triangles by surface nets on a regular grid, each vertex moved onto the
surface, relaxed along it and given the surface's normal. Each vertex is skinned by its
distance to the bones: every joint owns the segments from it to its children (a leaf one to
its end: the top of the head, the hand's tip, the toes' tip; the ankle also one back to the
heel), a vertex weighs the joints whose segments lie within `BLEND` metres of its nearest one,
among that joint's parent, grandparent and children, at most four, weights normalised.

    mesh = humanoid()                     # cached; the template skeleton's rest pose
    mesh.positions, mesh.normals          # (V, 3) float32
    mesh.triangles                        # (F, 3) uint32, counter-clockwise seen from outside
    mesh.joints, mesh.weights             # (V, 4) uint8 joint indices, float32 weights (sum 1)
    on_skeleton(mesh, offsets)            # the same mesh on a person's own rest offsets

Deterministic: the same numbers every run, so the GLB export (`formats/gltf.py`) and the
front end's copy (`frontend/public/humanoid.glb`, written by
`frontend/scripts/humanoid_asset.py`) are one mesh.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from interplay.motion import skeleton as sk

SPACING = 0.024        # grid step of the surface nets (metres)
BLEND = 0.06           # a joint weighs in while its bone is this much farther than the nearest
INFLUENCES = 4

J = sk.JOINT_INDEX


@dataclass(frozen=True)
class Humanoid:
    positions: np.ndarray       # (V, 3) float32, the bind pose
    normals: np.ndarray         # (V, 3) float32, unit
    triangles: np.ndarray       # (F, 3) uint32
    joints: np.ndarray          # (V, 4) uint8, skeleton joint indices (unused slots: 0)
    weights: np.ndarray         # (V, 4) float32, rows sum to 1 (unused slots: 0)


# --- signed distances (negative inside) of the primitives, over points (N, 3) ---------------

def _cone(p: np.ndarray, a, b, ra: float, rb: float) -> np.ndarray:
    """A capsule from a to b whose radius goes linearly from ra to rb."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    ab = b - a
    t = np.clip((p - a) @ ab / (ab @ ab), 0.0, 1.0)
    return np.linalg.norm(p - (a + t[:, None] * ab), axis=1) - (ra + t * (rb - ra))


def _ellipsoid(p: np.ndarray, centre, radii, frame: np.ndarray | None = None) -> np.ndarray:
    """An ellipsoid (radii along the frame's columns, default the world axes); the usual
    first-order distance estimate."""
    q = p - np.asarray(centre, float)
    if frame is not None:
        q = q @ frame
    r = np.asarray(radii, float)
    k0 = np.linalg.norm(q / r, axis=1)
    k1 = np.linalg.norm(q / (r * r), axis=1)
    return k0 * (k0 - 1.0) / np.maximum(k1, 1e-12)


def _rounded_box(p: np.ndarray, lo, hi, radius: float, frame: np.ndarray, origin) -> np.ndarray:
    """A box from lo to hi in a local frame (columns: axes, at origin), edges rounded."""
    q = (p - np.asarray(origin, float)) @ frame
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    centre, half = (lo + hi) / 2, (hi - lo) / 2 - radius
    d = np.abs(q - centre) - half
    return np.linalg.norm(np.maximum(d, 0.0), axis=1) + np.minimum(d.max(axis=1), 0.0) - radius


def _smin(a: np.ndarray, b: np.ndarray, k: float) -> np.ndarray:
    """Smooth union (polynomial), blending within k."""
    h = np.maximum(k - np.abs(a - b), 0.0) / k
    return np.minimum(a, b) - h * h * k * 0.25


def _unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def _foot_frame(ankle: np.ndarray, toe: np.ndarray) -> np.ndarray:
    """Columns: across (the foot's left), up, forward (ankle → toe on the ground)."""
    fwd = toe - ankle
    fwd = _unit([fwd[0], 0.0, fwd[2]])
    up = np.array([0.0, 1.0, 0.0])
    return np.stack([np.cross(up, fwd), up, fwd], axis=1)


def _hand_frame(elbow: np.ndarray, wrist: np.ndarray) -> np.ndarray:
    """Columns: along the forearm, palm normal (up in the T pose), across the hand."""
    along = _unit(wrist - elbow)
    across = _unit(np.cross(along, [0.0, 1.0, 0.0]))
    return np.stack([along, np.cross(across, along), across], axis=1)


def _ends(rest: np.ndarray) -> dict[int, list[np.ndarray]]:
    """The far ends of each joint's skinning segments (the joint is the near end)."""
    ends: dict[int, list[np.ndarray]] = {j: [rest[c] for c in sk.children(j)]
                                         for j in range(sk.NUM_JOINTS)}
    ends[sk.HEAD].append(rest[sk.HEAD] + [0.0, 0.19, 0.02])
    for elbow, wrist in ((J["left_elbow"], sk.LEFT_HAND), (J["right_elbow"], sk.RIGHT_HAND)):
        ends[wrist].append(rest[wrist] + 0.17 * _unit(rest[wrist] - rest[elbow]))
    for ankle, toe in ((sk.LEFT_ANKLE, sk.LEFT_FOOT), (sk.RIGHT_ANKLE, sk.RIGHT_FOOT)):
        frame = _foot_frame(rest[ankle], rest[toe])
        ends[toe].append(rest[toe] + 0.05 * frame[:, 2])
        ends[ankle].append(rest[ankle] - 0.07 * frame[:, 2] - [0.0, 0.03, 0.0])   # the heel
    return ends


def body_distance(p: np.ndarray, rest: np.ndarray | None = None) -> np.ndarray:
    """Signed distance estimate (N,) of points (N, 3) to the body on the rest joints (22, 3)."""
    r = sk.rest_joints() if rest is None else rest
    sole = min(r[sk.LEFT_FOOT, 1], r[sk.RIGHT_FOOT, 1]) - 0.01
    # Torso: tapered capsules up the spine, elliptic in section (depth = width / DEPTH), and
    # the neck, blended broadly.
    flat = np.array([1.0, 1.0, 1.0 / 0.72])
    q = p * flat
    hips = r[sk.PELVIS] + [0.0, -0.04, -0.012]
    waist = r[J["spine1"]] + [0.0, 0.02, 0.012]
    chest = r[J["spine3"]] + [0.0, 0.02, 0.03]
    top = r[sk.NECK] + [0.0, -0.055, 0.0]
    d = _cone(q, hips * flat, waist * flat, 0.16, 0.135)
    d = _smin(d, _cone(q, waist * flat, chest * flat, 0.135, 0.155), 0.04)
    d = _smin(d, _cone(q, chest * flat, top * flat, 0.155, 0.115), 0.04)
    d = _smin(d, _cone(p, r[sk.LEFT_SHOULDER] + [-0.04, -0.012, 0.0],
                       r[sk.RIGHT_SHOULDER] + [0.04, -0.012, 0.0], 0.055, 0.055), 0.08)
    d = _smin(d, _cone(p, r[sk.NECK] - [0.0, 0.06, 0.0], r[sk.HEAD] + [0.0, 0.02, 0.0],
                       0.055, 0.048), 0.04)
    # Head and a nose, so the facing reads.
    head = r[sk.HEAD] + [0.0, 0.08, 0.02]
    d = _smin(d, _ellipsoid(p, head, (0.078, 0.1, 0.092)), 0.04)
    d = _smin(d, _ellipsoid(p, head + [0.0, -0.01, 0.085], (0.016, 0.026, 0.025)), 0.02)
    for side in ("left", "right"):
        sh, el, wr = r[J[f"{side}_shoulder"]], r[J[f"{side}_elbow"]], r[J[f"{side}_wrist"]]
        hip, knee, ankle, toe = (r[J[f"{side}_hip"]], r[J[f"{side}_knee"]],
                                 r[J[f"{side}_ankle"]], r[J[f"{side}_foot"]])
        # Arm and mitten hand.
        arm = _smin(_cone(p, sh, el, 0.052, 0.04), _cone(p, el, wr, 0.04, 0.03), 0.03)
        hand = _hand_frame(el, wr)
        arm = _smin(arm, _ellipsoid(p, wr + 0.085 * hand[:, 0], (0.09, 0.024, 0.046), hand), 0.03)
        d = _smin(d, arm, 0.05)
        # Leg with a calf.
        leg = _smin(_cone(p, hip + [0.0, 0.03, 0.0], knee, 0.088, 0.056),
                    _cone(p, knee, ankle, 0.054, 0.036), 0.03)
        calf = knee + 0.3 * (ankle - knee) + [0.0, 0.0, -0.018]
        leg = _smin(leg, _ellipsoid(p, calf, (0.05, 0.11, 0.05)), 0.04)
        # Foot: a tall rear part (heel to the ball) and a low front (the toes), sole flat.
        frame = _foot_frame(ankle, toe)
        base = ankle.copy()
        base[1] = sole
        reach = float((toe - ankle) @ frame[:, 2])
        rear = _rounded_box(p, (-0.045, 0.0, -0.075), (0.045, ankle[1] - sole + 0.015, reach - 0.01),
                            0.03, frame, base)
        front = _rounded_box(p, (-0.047, 0.0, reach - 0.06), (0.047, 0.042, reach + 0.05),
                             0.018, frame, base)
        leg = _smin(leg, _smin(rear, front, 0.03), 0.03)
        d = _smin(d, leg, 0.04)
    return np.maximum(d, sole - p[:, 1])          # a flat sole


# --- surface nets ---------------------------------------------------------------------------

def _surface_nets(f: np.ndarray, origin: np.ndarray, h: float) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (V, 3) and quads (Q, 4) of the zero set of samples f (nx, ny, nz) on a grid."""
    inside = f < 0
    n = np.array(f.shape)
    total = np.zeros((*(n - 1), 3))
    count = np.zeros(tuple(n - 1))
    grid = np.stack(np.meshgrid(*[np.arange(k) for k in n], indexing="ij"), axis=-1) * h + origin
    for axis in range(3):
        lo = [slice(None)] * 3
        hi = [slice(None)] * 3
        lo[axis], hi[axis] = slice(0, -1), slice(1, None)
        f0, f1 = f[tuple(lo)], f[tuple(hi)]
        cross = inside[tuple(lo)] != inside[tuple(hi)]
        t = np.where(cross, f0 / np.where(cross, f0 - f1, 1.0), 0.0)
        pts = grid[tuple(lo)].copy()
        pts[..., axis] += t * h
        pts *= cross[..., None]
        # Each edge touches the four cells around it (the two other axes, 0 or 1 lower).
        others = [a for a in range(3) if a != axis]
        for da in (0, 1):
            for db in (0, 1):
                sel = [slice(None)] * 3
                sel[others[0]] = slice(da, da + n[others[0]] - 1)
                sel[others[1]] = slice(db, db + n[others[1]] - 1)
                total += pts[tuple(sel)]
                count += cross[tuple(sel)]
    active = count > 0
    index = np.full(tuple(n - 1), -1, dtype=np.int64)
    index[active] = np.arange(int(active.sum()))
    verts = total[active] / count[active][:, None]
    quads = []
    for axis in range(3):
        lo = [slice(None)] * 3
        hi = [slice(None)] * 3
        lo[axis], hi[axis] = slice(0, -1), slice(1, None)
        cross = inside[tuple(lo)] != inside[tuple(hi)]
        a, b = [x for x in range(3) if x != axis]
        e = np.argwhere(cross)
        e = e[(e[:, a] >= 1) & (e[:, b] >= 1) & (e[:, a] <= n[a] - 2) & (e[:, b] <= n[b] - 2)]
        cells = []
        for da, db in ((1, 1), (0, 1), (0, 0), (1, 0)):
            c = e.copy()
            c[:, a] -= da
            c[:, b] -= db
            cells.append(index[c[:, 0], c[:, 1], c[:, 2]])
        q = np.stack(cells, axis=1)
        # Wind so the quad faces out of the inside end of its edge.
        flip = inside[e[:, 0], e[:, 1], e[:, 2]]
        q[flip] = q[flip][:, ::-1]
        quads.append(q)
    return verts, np.concatenate(quads)


def _gradient(p: np.ndarray, rest: np.ndarray, eps: float = 1e-4) -> np.ndarray:
    g = np.empty_like(p)
    for axis in range(3):
        step = np.zeros(3)
        step[axis] = eps
        g[:, axis] = (body_distance(p + step, rest) - body_distance(p - step, rest)) / (2 * eps)
    return g


def _project(p: np.ndarray, rest: np.ndarray, steps: int = 3) -> np.ndarray:
    """Points moved onto the zero set by Newton steps along the gradient."""
    for _ in range(steps):
        g = _gradient(p, rest)
        p = p - (body_distance(p, rest) / np.maximum((g * g).sum(axis=1), 1e-12))[:, None] * g
    return p


def _triangles(verts: np.ndarray, quads: np.ndarray) -> np.ndarray:
    """Each quad split along its shorter diagonal."""
    a, b, c, d = quads.T
    short = (np.linalg.norm(verts[a] - verts[c], axis=1) <= np.linalg.norm(verts[b] - verts[d], axis=1))
    t1 = np.where(short[:, None], np.stack([a, b, c], 1), np.stack([a, b, d], 1))
    t2 = np.where(short[:, None], np.stack([a, c, d], 1), np.stack([b, c, d], 1))
    return np.concatenate([t1, t2])


def _relax(verts: np.ndarray, tris: np.ndarray, rest: np.ndarray, rounds: int = 3) -> np.ndarray:
    """Each vertex halfway to its neighbours' mean, then back onto the surface (evens out the
    triangles surface nets leave)."""
    edges = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    edges = np.unique(np.sort(edges, axis=1), axis=0)
    deg = np.bincount(edges.ravel(), minlength=len(verts)).astype(float)
    for _ in range(rounds):
        acc = np.zeros_like(verts)
        np.add.at(acc, edges[:, 0], verts[edges[:, 1]])
        np.add.at(acc, edges[:, 1], verts[edges[:, 0]])
        verts = _project(0.5 * verts + 0.5 * acc / np.maximum(deg, 1)[:, None], rest, steps=2)
    return verts


# --- skinning -------------------------------------------------------------------------------

def _segment_distance(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    ab = b - a
    t = np.clip((p - a) @ ab / max(float(ab @ ab), 1e-12), 0.0, 1.0)
    return np.linalg.norm(p - (a + t[:, None] * ab), axis=1)


def _candidates() -> np.ndarray:
    """(22, 22) bool: joints that may weigh on a vertex whose nearest bone is the row's joint
    (itself, its parent and grandparent, its children): keeps the left thigh off the right."""
    ok = np.eye(sk.NUM_JOINTS, dtype=bool)
    for j in range(sk.NUM_JOINTS):
        p = sk.PARENTS[j]
        if p >= 0:
            ok[j, p] = True
            if sk.PARENTS[p] >= 0:
                ok[j, sk.PARENTS[p]] = True
        for c in sk.children(j):
            ok[j, c] = True
    return ok


def skin_weights(positions: np.ndarray, rest: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Joint indices (V, 4) uint8 and weights (V, 4) float32 by distance to the bones."""
    ends = _ends(rest)
    dist = np.stack([np.min([_segment_distance(positions, rest[j], e) for e in ends[j]], axis=0)
                     for j in range(sk.NUM_JOINTS)], axis=1)                 # (V, 22)
    nearest = dist.argmin(axis=1)
    gap = dist - dist[np.arange(len(dist)), nearest][:, None]
    w = np.clip(1.0 - gap / BLEND, 0.0, None) ** 2 * _candidates()[nearest]
    order = np.argsort(-w, axis=1, kind="stable")[:, :INFLUENCES]
    top = np.take_along_axis(w, order, axis=1)
    top = top / top.sum(axis=1, keepdims=True)
    joints = np.where(top > 0, order, 0).astype(np.uint8)
    weights = top.astype(np.float32)
    # Exactly normalised in float32: the largest weight takes up the rounding.
    weights[:, 0] = 1.0 - weights[:, 1:].sum(axis=1, dtype=np.float32)
    return joints, weights


# --- the mesh -------------------------------------------------------------------------------

def build_humanoid(spacing: float = SPACING) -> Humanoid:
    """The mesh on the template skeleton (`skeleton.REST_OFFSETS`), made from scratch."""
    rest = sk.rest_joints()
    lo = np.array([rest[:, 0].min() - 0.25, rest[:, 1].min() - 0.06, rest[:, 2].min() - 0.2])
    hi = np.array([rest[:, 0].max() + 0.25, rest[:, 1].max() + 0.25, rest[:, 2].max() + 0.2])
    n = np.ceil((hi - lo) / spacing).astype(int) + 1
    axes = [lo[i] + spacing * np.arange(n[i]) for i in range(3)]
    pts = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    f = body_distance(pts, rest).reshape(tuple(n))
    verts, quads = _surface_nets(f, lo, spacing)
    verts = _project(verts, rest)
    tris = _triangles(verts, quads)
    verts = _relax(verts, tris, rest)
    normals = _gradient(verts, rest)
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    # Any triangle facing inwards after the moves is turned round.
    a, b, c = verts[tris[:, 0]], verts[tris[:, 1]], verts[tris[:, 2]]
    inward = (np.cross(b - a, c - a) * (normals[tris[:, 0]] + normals[tris[:, 1]]
                                        + normals[tris[:, 2]])).sum(axis=1) < 0
    tris[inward] = tris[inward][:, ::-1]
    joints, weights = skin_weights(verts, rest)
    normals32 = normals.astype(np.float32)
    normals32 /= np.linalg.norm(normals32, axis=1, keepdims=True)
    return Humanoid(positions=verts.astype(np.float32), normals=normals32,
                    triangles=tris.astype(np.uint32), joints=joints, weights=weights)


@lru_cache(maxsize=1)
def humanoid() -> Humanoid:
    """The mesh on the template skeleton, built once per process."""
    return build_humanoid()


def on_skeleton(mesh: Humanoid, offsets: np.ndarray) -> np.ndarray:
    """Bind-pose positions (V, 3) float32 of the mesh on a skeleton with other rest offsets:
    each vertex follows its joints' moves from the template's rest pose to this one."""
    shift = sk.rest_joints(np.asarray(offsets, float)) - sk.rest_joints()
    moved = mesh.positions + np.einsum("vk,vkc->vc", mesh.weights, shift[mesh.joints])
    return moved.astype(np.float32)
