"""Blender renders of exported motions: the docs' contact strips of a wave and a nod
(docs/images/blender-wave.png, docs/images/blender-nod.png, shown in docs/api.md § Exports).

Each motion is exported as a GLB (`formats.gltf.write_glb`, the skinned mesh, with the
head/wrist rotations every export gives: an edit's, the captures' own), imported by Blender's own glTF importer, headless,
and rendered with the Workbench engine at a few frames, side by side in one PNG (each frame
stamped with its number, 20 fps from 0). Made with Debian's Blender 3.4.1:

    .venv/bin/interplay generate --prompt "a person waves with the right hand" --seconds 3 \
        --seed 2 --out /tmp/wave.json
    .venv/bin/interplay generate --prompt "a person stands still" --seconds 3 --seed 2 \
        --out /tmp/stand.json
    .venv/bin/interplay edit /tmp/stand.json --part head --prompt "nod twice" --out /tmp/nod.json
    .venv/bin/python scripts/blender_renders.py /tmp/wave.json --name wave --view front \
        --watch right_wrist --size 0.9 --frames 4,6,8,10,12,14
    .venv/bin/python scripts/blender_renders.py /tmp/nod.json --name nod \
        --frames 0,10,19,27,33,41 --size 0.8 --view left-side

Run with the project's Python it writes the GLB and calls `blender -b --python` on this same
file, which (inside Blender) imports it and renders. The camera is orthographic, aimed at the
person's upper body, between the neck and the joint watched (`--watch`), `--size` metres high
(the view is taken from the person's facing at the first frame: "front", "side" from their
right, "left-side", "three-quarter" from front right). `--no-leaves` renders the derived
head and wrists instead of the edit's and the captures' own.
"""

from __future__ import annotations

import json
import sys

VIEWS = {"front": 0.0, "three-quarter": 40.0, "side": 90.0, "left-side": -90.0}  # degrees to their right


def _inside_blender(args: dict) -> None:
    import bpy
    import numpy
    numpy.bool = bool          # Debian's glTF importer uses np.bool, gone from numpy 1.24
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    bpy.ops.import_scene.gltf(filepath=args["glb"])
    scene.render.engine = "BLENDER_WORKBENCH"
    shading = scene.display.shading
    shading.light, shading.color_type = "STUDIO", "OBJECT"
    shading.show_cavity, shading.show_shadows = True, True
    for obj in scene.objects:
        if obj.type == "MESH":
            obj.color = (0.85, 0.55, 0.35, 1.0)
    world = bpy.data.worlds.new("bg")
    scene.world = world
    world.color = (0.93, 0.93, 0.95)
    scene.render.resolution_x, scene.render.resolution_y = args["width"], args["height"]
    scene.render.film_transparent = False
    cam_data = bpy.data.cameras.new("cam")
    cam_data.type, cam_data.ortho_scale = "ORTHO", args["ortho"]
    cam = bpy.data.objects.new("cam", cam_data)
    scene.collection.objects.link(cam)
    target = bpy.data.objects.new("target", None)
    scene.collection.objects.link(target)
    target.location = args["target"]
    cam.location = args["camera"]
    track = cam.constraints.new("TRACK_TO")
    track.target, track.track_axis, track.up_axis = target, "TRACK_NEGATIVE_Z", "UP_Y"
    scene.camera = cam
    scene.render.use_stamp, scene.render.use_stamp_frame = True, True
    for flag in ("date", "time", "render_time", "camera", "lens", "scene", "filename",
                 "memory", "frame_range", "hostname", "marker", "sequencer_strip"):
        setattr(scene.render, f"use_stamp_{flag}", False)
    scene.render.stamp_font_size = 20
    strips = []
    for f in args["frames"]:
        scene.frame_set(f)
        scene.render.filepath = f"{args['tmp']}/frame{f:04d}.png"
        bpy.ops.render.render(write_still=True)
        img = bpy.data.images.load(scene.render.filepath)
        px = numpy.empty(img.size[0] * img.size[1] * 4, numpy.float32)
        img.pixels.foreach_get(px)
        strips.append(px.reshape(img.size[1], img.size[0], 4))
    gap = numpy.ones((args["height"], 6, 4), numpy.float32)
    row = numpy.concatenate([x for s in strips for x in (s, gap)][:-1], axis=1)
    out = bpy.data.images.new("strip", row.shape[1], row.shape[0], alpha=True)
    out.pixels.foreach_set(row.ravel())
    settings = scene.render.image_settings
    settings.file_format, settings.color_mode, settings.compression = "PNG", "RGB", 100
    out.save_render(args["out"], scene=scene)


def main(argv: list[str]) -> int:
    import argparse
    import subprocess
    import tempfile
    from pathlib import Path

    import numpy as np

    from interplay.generators.primitives.body import trunk_axes
    from interplay.motion import skeleton as sk
    from interplay.motion.formats.gltf import write_glb
    from interplay.motion.motion import Motion
    from interplay.pipeline.leaves import captured_since

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("motion", help="Motion JSON file")
    ap.add_argument("--name", required=True, help="docs/images/blender-NAME.png")
    ap.add_argument("--view", choices=sorted(VIEWS), default="three-quarter")
    ap.add_argument("--frames", default="0,10,20,30,40,50", help="motion frames (from 0)")
    ap.add_argument("--watch", default="head", help="the joint the camera frames with the neck")
    ap.add_argument("--size", type=float, default=1.0, help="the view's height (m)")
    ap.add_argument("--close", action="store_true", help="aim at the joint watched alone (a foot's toes)")
    ap.add_argument("--no-leaves", action="store_true",
                    help="leave out the edit's and the captures' head/wrist rotations (the derived ones)")
    ap.add_argument("--out-dir", default=str(Path(__file__).resolve().parents[1] / "docs" / "images"))
    ap.add_argument("--blender", default="blender")
    a = ap.parse_args(argv)
    motion = Motion.from_json(json.loads(Path(a.motion).read_text()))
    joints = motion.people[0].astype(np.float64)
    frames = [int(f) for f in a.frames.split(",")]
    # Blender is Z up: the motion's (x, y, z) is Blender's (x, -z, y).
    to_z = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
    _, _, chest = trunk_axes(joints[:1])
    forward = chest[0] * [1.0, 0.0, 1.0]
    forward /= np.linalg.norm(forward)
    turn = np.radians(VIEWS[a.view])
    right = np.cross(forward, [0.0, 1.0, 0.0])       # the person's right, seen from the front
    look = np.cos(turn) * forward + np.sin(turn) * right
    # Aimed between the neck and the joint watched (the waving wrist, the head), over the frames.
    aim = [sk.JOINT_INDEX[a.watch]] if a.close else [sk.NECK, sk.JOINT_INDEX[a.watch]]
    watched = joints[frames][:, aim].mean((0, 1))
    camera = watched + 4.0 * look
    with tempfile.TemporaryDirectory() as tmp:
        glb = Path(tmp) / f"{a.name}.glb"
        # The leaves the exports give (`pipeline.leaves`): an edit's over the captures' own.
        leaves = {} if a.no_leaves else {**captured_since(motion.plan, 1, motion.frames)[0], **motion.leaves_of(0)}
        glb.write_bytes(write_glb([joints], fps=motion.fps, leaves=[leaves]))
        args = {"glb": str(glb), "tmp": tmp, "frames": [f + 1 for f in frames],
                "out": str(Path(a.out_dir) / f"blender-{a.name}.png"), "width": 320, "height": 320,
                "ortho": a.size, "target": (to_z @ watched).tolist(), "camera": (to_z @ camera).tolist()}
        run = subprocess.run([a.blender, "-b", "--factory-startup", "--python", __file__, "--",
                              json.dumps(args)], capture_output=True, text=True, timeout=600)
        if run.returncode != 0 or not Path(args["out"]).is_file():
            print(run.stdout[-3000:], run.stderr[-3000:], file=sys.stderr)
            return 1
    print(f"wrote {args['out']}")
    return 0


if __name__ == "__main__":
    try:
        import bpy  # noqa: F401
    except ImportError:
        sys.exit(main(sys.argv[1:]))
    _inside_blender(json.loads(sys.argv[-1]))
