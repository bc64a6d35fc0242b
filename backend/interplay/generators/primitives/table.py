"""How each primitive is built, one row each: name (the catalogue's `made_by.primitive`), the
base posture, the plan's parts it moves, whether it counts, seconds per cycle (or for the
whole move), and the builder (a name in `registry.BUILDERS`) with its fixed parameters. The
phrasings it is found by are the catalogue's descriptions (`registry._descriptions`)."""

from __future__ import annotations

ARMS = ("left_arm", "right_arm")
LEGS = ("left_leg", "right_leg")
ALL = ARMS + LEGS + ("head",)

PRIMITIVE_TABLE: list[dict] = [
    {"name": "clap", "builder": "hand_contacts", "params": {"target": "hands"}, "posture": "standing",
     "parts": ARMS, "counts": True, "seconds": 0.7},
    {"name": "high_five_self", "builder": "hand_contacts", "params": {"target": "high_five"},
     "posture": "standing", "parts": ARMS, "counts": True, "seconds": 0.9},
    {"name": "tap_chest", "builder": "hand_contacts", "params": {"target": "chest"},
     "posture": "standing", "parts": ("right_arm",), "counts": True, "seconds": 0.7},
    {"name": "tap_head", "builder": "hand_contacts", "params": {"target": "head"},
     "posture": "standing", "parts": ("right_arm",), "counts": True, "seconds": 0.8},
    {"name": "tap_knee", "builder": "hand_contacts", "params": {"target": "knee"},
     "posture": "seated", "parts": ("right_arm",), "counts": True, "seconds": 0.8},
    {"name": "knee_lifts", "builder": "knee_lifts", "params": {"side": "alternate"},
     "posture": "standing", "parts": LEGS, "counts": True, "seconds": 0.8},
    {"name": "reach_grasp", "builder": "reach_grasp_carry", "params": {"carry": False},
     "posture": "standing", "parts": ARMS, "counts": False, "seconds": 3.0},
    {"name": "carry", "builder": "reach_grasp_carry", "params": {"carry": True},
     "posture": "walk", "parts": ARMS, "counts": False, "seconds": 5.0},
    {"name": "push_up", "builder": "push_ups", "params": {}, "posture": "prone",
     "parts": ARMS + LEGS, "counts": True, "seconds": 1.6},
    {"name": "sit_up", "builder": "sit_ups", "params": {}, "posture": "supine",
     "parts": ARMS + LEGS, "counts": True, "seconds": 1.8},
    {"name": "squat", "builder": "squats", "params": {}, "posture": "standing",
     "parts": LEGS, "counts": True, "seconds": 1.6},
    {"name": "lunge", "builder": "lunges", "params": {"side": "alternate"}, "posture": "standing",
     "parts": LEGS, "counts": True, "seconds": 2.0},
    {"name": "jumping_jack", "builder": "jumping_jacks", "params": {}, "posture": "standing",
     "parts": ARMS + LEGS, "counts": True, "seconds": 1.0},
    {"name": "arm_circles", "builder": "arm_circles", "params": {}, "posture": "standing",
     "parts": ARMS, "counts": True, "seconds": 1.0},
    {"name": "limp", "builder": "gait_asymmetric", "params": {"side": "right"}, "posture": "walk",
     "parts": LEGS, "counts": False, "seconds": 6.0},
    {"name": "stumble", "builder": "gait_perturbed", "params": {"kind": "stumble"},
     "posture": "walk", "parts": ALL, "counts": False, "seconds": 5.0},
    {"name": "sway", "builder": "gait_perturbed", "params": {"kind": "sway"}, "posture": "walk",
     "parts": ARMS + ("head",), "counts": True, "seconds": 1.5},
    {"name": "look_up", "builder": "head", "params": {"action": "look_up"}, "posture": "standing",
     "parts": ("head",), "counts": False, "seconds": 2.0},
    {"name": "look_down", "builder": "head", "params": {"action": "look_down"}, "posture": "standing",
     "parts": ("head",), "counts": False, "seconds": 2.0},
    {"name": "look_left", "builder": "head", "params": {"action": "look_left"}, "posture": "standing",
     "parts": ("head",), "counts": False, "seconds": 2.0},
    {"name": "look_right", "builder": "head", "params": {"action": "look_right"}, "posture": "standing",
     "parts": ("head",), "counts": False, "seconds": 2.0},
    {"name": "look_at_partner", "builder": "head", "params": {"action": "look_at"}, "posture": "standing",
     "parts": ("head",), "counts": False, "seconds": 2.0},
    {"name": "nod", "builder": "head", "params": {"action": "nod"}, "posture": "standing",
     "parts": ("head",), "counts": True, "seconds": 0.8},
    {"name": "shake_head", "builder": "head", "params": {"action": "shake"}, "posture": "standing",
     "parts": ("head",), "counts": True, "seconds": 0.9},
]
