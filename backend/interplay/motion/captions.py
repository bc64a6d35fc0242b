"""Pose codes → short English captions per body part, a one-sentence summary, and scoring of
captions against capture labels. Pure functions over the dict `posecodes.frame_codes` returns.

A clip is cut into windows of `window` frames (a last window shorter than half joins the one
before). In each window every part gets exactly one caption, the first rule of its priority
list that holds ("the left hand waves" before "the left arm is raised above the head" before
"the left elbow is bent" …, a resting default last); equal neighbours are then merged, so a
caption spans [start, end) frames of one unchanged description.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.motion.clip import Caption

PARTS = ("body", "left_upper", "right_upper", "left_lower", "right_lower")

# Share of a window's frames a state must hold to be said (a sustained state vs a glimpse).
LOCOMOTION_SHARE = 0.4   # travelling for 40% of the window: starting/stopping still counts
STATE_SHARE = 0.4        # postures held (hand near the face, arm raised forward …)
BRIEF_SHARE = 0.2        # postures that are passed through quickly (a squat, hand to the floor)
TURN_MIN_DEG = 45.0      # net heading change within a window that is a turn

GAITS = {"walking": "walks", "jogging": "jogs", "running": "runs"}
DIRECTIONS = {"moving_forward": "forward", "moving_backwards": "backwards",
              "moving_left": "sideways to the left", "moving_right": "sideways to the right"}
# Part captions a summary mentions only when nothing more telling happened.
MINOR = ("swings back and forth", "elbow is bent", "knee is bent", "takes a step",
         "raised to shoulder height")
DEFAULT_ARM = "the {side} arm rests at the side"
DEFAULT_LEG = "the {side} leg stands still"


@dataclass(frozen=True)
class _Window:
    codes: dict
    start: int
    end: int

    def share(self, name: str) -> float:
        return float(np.mean(self.codes[name][self.start:self.end]))

    def count(self, name: str) -> int:
        return int(np.count_nonzero(self.codes[name][self.start:self.end]))

    def heading_change(self) -> float:
        """Net heading change over the window in degrees (+ = turned to the left)."""
        h = self.codes["heading"]
        return float(np.degrees(h[self.end - 1] - h[self.start]))


def _locomotion(w: _Window) -> tuple[str, str] | None:
    """(verb, direction phrase) when the person travels by steps for much of the window."""
    shares = {g: w.share(g) for g in GAITS}
    if sum(shares.values()) < LOCOMOTION_SHARE:
        return None
    gait = max(shares, key=shares.__getitem__)
    verb = "sneaks" if gait == "walking" and w.share("sneaking") >= 0.5 * shares[gait] else GAITS[gait]
    left, right = w.share("circling_left"), w.share("circling_right")
    if max(left, right) >= 0.5 and left != right:
        return verb, f"in a circle to the {'left' if left > right else 'right'}"
    direction = max(DIRECTIONS, key=w.share)
    return verb, DIRECTIONS[direction]


def _turn(w: _Window) -> str | None:
    dh = w.heading_change()
    return None if abs(dh) < TURN_MIN_DEG else ("left" if dh > 0 else "right")


def _lying_text(w: _Window) -> str:
    n = w.end - w.start
    first = _Window(w.codes, w.start, w.start + max(n // 4, 1)).share("lying")
    last = _Window(w.codes, w.end - max(n // 4, 1), w.end).share("lying")
    if first < 0.5 <= last:
        return "the person lies down on the floor"
    if last < 0.5 <= first:
        return "the person gets up from the floor"
    return "the person lies on the floor"


def _body_text(w: _Window, loco: tuple[str, str] | None) -> str:
    if w.share("lying") >= 0.3:
        return _lying_text(w)
    if w.count("jumping"):
        jump = w.codes["jumping"][w.start:w.end]
        ahead = np.mean(w.codes["moving_forward"][w.start:w.end][jump]) >= 0.5
        return "the person jumps forward" if ahead else "the person jumps"
    left, right = w.count("left_foot_kicking"), w.count("right_foot_kicking")
    if left or right:
        return ("the person kicks" if left == right
                else f"the person kicks with the {'left' if left > right else 'right'} leg")
    turn = _turn(w)
    if loco:
        verb, direction = loco
        text = f"the person {verb} {direction}"
        return text + f" and turns {turn}" if turn and "circle" not in direction else text
    if w.share("sitting") >= 0.5:
        return "the person sits on the floor"
    if w.share("squatting") >= BRIEF_SHARE:
        return "the person squats"
    if w.share("crouching") + w.share("squatting") >= 0.5:
        return "the person crouches"
    if w.share("bending_forward") >= 0.3:
        return "the person bends forward"
    if turn:
        return f"the person turns {turn}"
    if w.share("standing_still") >= 0.6:
        return "the person stands still"
    return "the person stays in place"


def _arm_text(w: _Window, side: str) -> str:
    s = side
    p = f"{side}_"
    if w.share(p + "hand_waving") >= 0.25:
        return f"the {s} hand waves"
    if w.count(p + "hand_punching"):
        return f"the {s} arm punches forward"
    if w.share(p + "arm_circling_backward") >= 0.3:
        return f"the {s} arm circles backwards"
    if w.share(p + "arm_circling_forward") >= 0.3:
        return f"the {s} arm circles forwards"
    if w.share(p + "hand_above_head") >= BRIEF_SHARE:
        return f"the {s} arm is raised above the head"
    if w.share(p + "hand_at_head") >= BRIEF_SHARE:
        return f"the {s} arm is raised to head height"
    if w.share(p + "hand_floor") >= BRIEF_SHARE:
        return f"the {s} hand reaches down to the floor"
    if w.share(p + "hand_near_face") >= STATE_SHARE:
        return f"the {s} hand is near the face"
    if w.share("hands_together") >= STATE_SHARE:
        return f"the {s} hand holds the other hand"
    if w.share(p + "hand_near_hip") >= 0.5:
        return f"the {s} hand rests on the hip"
    if w.share(p + "arm_sideways") >= STATE_SHARE:
        return f"the {s} arm is stretched out to the side"
    if w.share(p + "arm_forward") >= STATE_SHARE:
        return f"the {s} arm is raised forward"
    if w.share(p + "hand_at_shoulder") >= STATE_SHARE:
        return f"the {s} hand is raised to shoulder height"
    if w.share(p + "arm_swinging") >= 0.5:
        return f"the {s} arm swings back and forth"
    if w.share(p + "elbow_bent") >= 0.6:
        return f"the {s} elbow is bent"
    return DEFAULT_ARM.format(side=s)


def _leg_text(w: _Window, side: str, loco: tuple[str, str] | None) -> str:
    s = side
    p = f"{side}_"
    if w.count(p + "foot_kicking"):
        return f"the {s} leg kicks forward"
    if w.share("lying") >= 0.5 or w.share("sitting") >= 0.5:
        return f"the {s} leg rests on the floor"
    if w.count("jumping"):
        return f"the {s} leg jumps"
    if loco:
        return f"the {s} leg {loco[0]} {loco[1]}"
    if w.share(p + "knee_raised") >= BRIEF_SHARE:
        return f"the {s} knee is raised"
    if w.share("squatting") >= BRIEF_SHARE:
        return f"the {s} leg bends deeply"
    if w.share(p + "foot_lifted") >= STATE_SHARE:
        return f"the {s} foot is lifted off the ground"
    contact = w.codes[p + "foot_contact"][w.start:w.end]
    if np.count_nonzero(contact[1:] & ~contact[:-1]) and w.count(p + "foot_stepping") >= 2:
        return f"the {s} leg takes a step"
    if w.share(p + "knee_bent") >= 0.5:
        return f"the {s} knee is bent"
    return DEFAULT_LEG.format(side=s)


def _windows(t: int, window: int) -> list[tuple[int, int]]:
    bounds = list(range(0, t, window)) + [t]
    if len(bounds) > 2 and bounds[-1] - bounds[-2] < window // 2:
        del bounds[-2]                                           # a short tail joins the window before
    return list(zip(bounds[:-1], bounds[1:]))


def captions_from_codes(codes: dict[str, np.ndarray], window: int) -> list[Caption]:
    """Captions (sorted by part, then start) from frame codes; see the module docstring."""
    t = len(codes["speed"])
    rows: dict[str, list[Caption]] = {p: [] for p in PARTS}
    for a, b in _windows(t, window):
        w = _Window(codes, a, b)
        loco = _locomotion(w)
        texts = {"body": _body_text(w, loco),
                 "left_upper": _arm_text(w, "left"), "right_upper": _arm_text(w, "right"),
                 "left_lower": _leg_text(w, "left", loco), "right_lower": _leg_text(w, "right", loco)}
        for part, text in texts.items():
            row = rows[part]
            if row and row[-1].text == text:
                row[-1].end = b                                  # merge equal neighbours
            else:
                row.append(Caption(a, b, part, text))
    return [c for p in PARTS for c in rows[p]]


def _notable(cap: Caption) -> bool:
    """Part captions worth a summary: not a resting default, not the legs echoing the body."""
    if cap.part == "body":
        return True
    side = cap.part.split("_")[0]
    if cap.text in (DEFAULT_ARM.format(side=side), DEFAULT_LEG.format(side=side)):
        return False
    if cap.part.endswith("lower"):
        words = cap.text.split()
        return not (len(words) > 3 and words[3] in (*GAITS.values(), "sneaks", "jumps", "rests"))
    return True


def summarise(captions: list[Caption], max_body: int = 3, max_parts: int = 2) -> str:
    """One sentence: what the body does in order ("walks forward, then jumps"), then the most
    telling part captions (events before postures, longer first, one per part)."""
    body = [c.text for c in sorted((c for c in captions if c.part == "body"), key=lambda c: c.start)]
    quiet = ("the person stands still", "the person stays in place")
    busy = [x for x in body if x not in quiet] or body[:1]
    steps = [x for i, x in enumerate(busy) if i == 0 or x != busy[i - 1]]
    steps = [s if i == 0 else s.removeprefix("the person ") for i, s in enumerate(steps[:max_body])]
    frames: dict[tuple[str, str], int] = {}
    for c in captions:
        if c.part != "body" and _notable(c):
            frames[c.part, c.text] = frames.get((c.part, c.text), 0) + c.end - c.start
    parts: list[str] = []
    used: set[str] = set()
    for part, text in sorted(frames, key=lambda k: (any(m in k[1] for m in MINOR), -frames[k])):
        if part not in used and len(parts) < max_parts:      # one caption per part
            parts.append(text)
            used.add(part)
    sentence = ", then ".join(steps) if steps else "the person does not move"
    if parts:
        sentence += "; " + " and ".join(parts)
    return sentence[0].upper() + sentence[1:] + "."


# Label family (interplay.motion.labels.label_family) → parts whose captions should show it and
# the words that do. Families without a caption (throw, soccer, salsa …) are not scored.
FAMILY_CHECKS: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "walk": (("body",), ("walks",)),
    "jog": (("body",), ("jogs", "runs")),
    "run": (("body",), ("runs", "jogs")),
    "jump": (("body",), ("jumps",)),
    "hop": (("body",), ("jumps",)),
    "sneak": (("body",), ("sneaks", "crouches")),
    "squat": (("body",), ("squats",)),
    "lie": (("body",), ("lies",)),
    "kick": (("left_lower", "right_lower"), ("kicks",)),
    "grab": (("left_upper", "right_upper"), ("above the head", "to head height")),
    "rotate": (("left_upper", "right_upper"), ("circles",)),
    "elbow": (("left_lower", "right_lower"), ("knee is raised",)),
    "deposit": (PARTS, ("bends", "reaches down", "squats", "crouches")),
    "circle": (("body",), ("circle", "turns")),
}


def label_families(label: str, prompt: str) -> list[str]:
    """Scored families of a clip: its coarse family, plus "circle" for travelling in circles."""
    from interplay.motion.labels import label_family  # the data set's own family rule, one definition

    text = f"{prompt} {label}".lower()
    fams = [label_family(prompt)]
    if fams[0] == "other":
        fams = [label_family(label)]
    if "circle" in text and fams[0] in ("walk", "jog", "run", "sneak"):
        fams.append("circle")                                    # walking/jogging in a circle
    return [f for f in fams if f in FAMILY_CHECKS]


def score_clips(items: list[tuple[str, str, list[Caption]]]) -> dict:
    """Agreement of captions with label families over (label, prompt, captions) items:
    `any` = share of (item, family) pairs where some caption of the family's parts says it,
    `dominant` = where, in one of those parts, the captions saying it cover at least as many
    frames as any other single caption text."""
    per: dict[str, list[tuple[bool, bool]]] = {}
    unscored = 0
    for label, prompt, caps in items:
        fams = label_families(label, prompt)
        unscored += not fams
        for fam in fams:
            parts, words = FAMILY_CHECKS[fam]
            hit_any = hit_dominant = False
            for part in parts:
                frames: dict[str, int] = {}
                for c in caps:
                    if c.part == part:
                        frames[c.text] = frames.get(c.text, 0) + c.end - c.start
                saying = sum(n for text, n in frames.items() if any(wd in text for wd in words))
                others = [n for text, n in frames.items() if not any(wd in text for wd in words)]
                hit_any |= saying > 0
                hit_dominant |= saying > 0 and saying >= max(others, default=0)
            per.setdefault(fam, []).append((hit_any, hit_dominant))
    pairs = [r for rows in per.values() for r in rows]

    def rate(rows: list[tuple[bool, bool]], k: int) -> float:
        return round(float(np.mean([r[k] for r in rows])), 4) if rows else 0.0

    return {"pairs": len(pairs), "unscored_items": unscored,
            "any": rate(pairs, 0), "dominant": rate(pairs, 1),
            "families": {f: {"n": len(r), "any": rate(r, 0), "dominant": rate(r, 1)}
                         for f, r in sorted(per.items())}}
