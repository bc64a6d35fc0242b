"""Write frontend/src/test/skeleton.json: the GET /api/skeleton payload built from
interplay.motion.skeleton, for the front end's unit tests.

Run: .venv/bin/python frontend/scripts/skeleton_fixture.py
"""

from __future__ import annotations

import json
from pathlib import Path

from interplay.motion import skeleton as sk

OUT = Path(__file__).resolve().parents[1] / "src" / "test" / "skeleton.json"


def payload() -> dict:
    return {
        "joints": list(sk.JOINT_NAMES),
        "parents": list(sk.PARENTS),
        "parts": {p: [int(j) for j in js] for p, js in sk.PART_JOINTS.items()},
        "joint_part": list(sk.JOINT_PART),
        "colours": dict(sk.PART_COLOURS),
        # rest pose (22, 3), used to build test frames
        "rest": [[round(float(x), 5) for x in row] for row in sk.rest_joints()],
    }


if __name__ == "__main__":
    OUT.write_text(json.dumps(payload(), indent=1) + "\n")
    print(f"wrote {OUT}")
