"""Write frontend/src/test/rig.json: a generated motion's joints beside its rig as the JSON
export writes it (`Motion.to_json(rig=True)`: schema interplay.motion/2, per person the rest
offsets, root and local wxyz rotations of `rig.solve_rig`), every 5th frame, for the front
end's unit tests of the character (playback/rig.test.ts, scene/Character.test.ts): sampling
the rig and posing the skinned humanoid must give the joints back.

The motion is the issue's squat ("a person squats down deeply then stands", seed 2), made by
`interplay generate` (the studio's pipeline), or a Motion JSON file given as the argument.

Run: .venv/bin/python frontend/scripts/rig_fixture.py [motion.json]
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
from pathlib import Path

from interplay.motion.motion import Motion

OUT = Path(__file__).resolve().parents[1] / "src" / "test" / "rig.json"
PROMPT, SEED, SECONDS, STEP = "a person squats down deeply then stands", 2, 3, 5


def generated() -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "motion.json"
        subprocess.run([str(Path(sys.executable).parent / "interplay"), "generate", "--prompt", PROMPT,
                        "--seed", str(SEED), "--seconds", str(SECONDS), "--out", str(out)], check=True)
        return json.loads(out.read_text())


def fixture(source: dict) -> dict:
    motion = Motion.from_json(source)
    full = motion.to_json(rig=True)
    keep = list(range(0, motion.frames, STEP))
    people = []
    for person in full["people"]:
        rig = person["rig"]
        people.append({
            "joints": [person["joints"][t] for t in keep],
            "rig": {"offsets": rig["offsets"], "root": [rig["root"][t] for t in keep],
                    "rotations": [rig["rotations"][t] for t in keep]},
        })
    return {"schema": full["schema"], "prompt": source.get("prompt", PROMPT), "frames": keep,
            "people": people}


if __name__ == "__main__":
    src = json.loads(Path(sys.argv[1]).read_text()) if len(sys.argv) > 1 else generated()
    OUT.write_text(json.dumps(fixture(src), separators=(",", ":")) + "\n")
    print(f"wrote {OUT} ({OUT.stat().st_size} bytes)")
