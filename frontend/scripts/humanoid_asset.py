"""Write frontend/public/humanoid.glb: the procedural humanoid of
`interplay.motion.formats.humanoid` (the same mesh the GLB export skins), alone, skinned to the
22 smpl22 joints in the rest pose, for the studio's skinned character. Vite copies public/ into
dist/, and the server answers it at /humanoid.glb.

Layout (`interplay.motion.formats.gltf.humanoid_glb`): scene roots "humanoid" (over the joint
nodes, named as `skeleton.JOINT_NAMES`, each translated by its rest offset) and
"humanoid_body" (the skinned mesh: POSITION, NORMAL, JOINTS_0 = skeleton joint indices,
WEIGHTS_0, up to 4 per vertex); Y up, metres, facing +Z. To fit a person's own rest offsets,
move each vertex by its weighted joints' rest-position change (`humanoid.on_skeleton`).
tests/motion/formats/test_humanoid.py fails when the committed file is not what this writes.

Run: .venv/bin/python frontend/scripts/humanoid_asset.py
"""

from __future__ import annotations

from pathlib import Path

from interplay.motion.formats.gltf import humanoid_glb

OUT = Path(__file__).resolve().parents[1] / "public" / "humanoid.glb"


if __name__ == "__main__":
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_bytes(humanoid_glb())
    print(f"wrote {OUT} ({OUT.stat().st_size} bytes)")
