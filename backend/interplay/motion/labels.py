"""Cleaning capture labels into short prompts, and the data card's mapping table.

CMU's descriptions are short and sometimes lists ("jump, balance"); each known description is
mapped by hand to one prompt in the studio's vocabulary. HDM05 and cmu-8action classes are
mapped by their retargeting modules (`hdm05_prompt`, `cmu_8action_prompt`).
"""

from __future__ import annotations

# CMU index description (lower case, stripped) → prompt.
CMU_PROMPTS: dict[str, str] = {
    "walk": "a person walks forward",
    "walk/stride": "a person walks forward with long strides",
    "walk, exaggerated stride": "a person walks forward with exaggerated strides",
    "slow walk": "a person walks slowly",
    "slow walk/stride": "a person walks slowly with long strides",
    "brisk walk": "a person walks briskly",
    "walk on uneven terrain": "a person walks carefully over uneven ground",
    "run": "a person runs forward",
    "run/jog": "a person jogs forward",
    "jump": "a person jumps",
    "jump, balance": "a person jumps and keeps their balance",
    "forward jump": "a person jumps forward",
    "jump up to grab, reach for, tiptoe": "a person jumps up to grab something overhead",
    "salsa dance": "two people dance salsa",
}


def cmu_prompt(description: str) -> str:
    """A CMU index description → prompt; unknown descriptions become "a person <description>"."""
    key = " ".join(description.lower().split())
    if key in CMU_PROMPTS:
        return CMU_PROMPTS[key]
    return f"a person {key}"


def label_family(prompt: str) -> str:
    """A coarse action family of a prompt, for stratified splits and caption checks."""
    text = prompt.lower()
    for family in ("salsa", "jog", "run", "jump", "hop", "walk", "sneak", "squat", "kick",
                   "throw", "lie", "grab", "deposit", "elbow", "rotate", "basketball",
                   "traffic", "soccer", "wash"):
        if family in text:
            return family
    return "other"
