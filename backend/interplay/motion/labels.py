"""Cleaning capture labels into short prompts, and the data card's mapping table.

CMU's descriptions are short and sometimes lists ("jump, balance"); each known description is
mapped by hand to one prompt in the studio's vocabulary. HDM05, cmu-8action, Bandai Namco and
DeepMimic labels are mapped by their retargeting modules (`hdm05_prompt`, `cmu_8action_prompt`,
`bandai_prompt`, `deepmimic_prompt`).
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
    # cmu-asfamc and cmu-iclone trials (CMU's descriptions for subjects 01, 02, 05, 06, 11,
    # 131, 135); trials already in cmu-bvh keep their cmu-bvh prompt.
    "playground - forward jumps, turn around": "a person jumps forward several times and turns around",
    "playground - climb, sit, dangle legs, rock back, lower self to ground":
        "a person climbs, sits, dangles the legs and lowers themselves to the ground",
    "playground - climb, jump down, dangle, legs push off against":
        "a person climbs, jumps down and dangles from a bar",
    "punch/strike": "a person punches and strikes",
    "bend over, scoop up, rise, lift arm": "a person bends over, scoops something up, stands up and lifts an arm",
    "swordplay": "a person fights with a sword",
    "wash self": "a person washes themselves",
    "dance - expressive arms, pirouette": "a person dances with expressive arms and turns a pirouette",
    "dance - sideways arabesque, turn step, folding arms":
        "a person dances a sideways arabesque, a turning step and folds the arms",
    "dance - sideways arabesque, folding arms, bending back":
        "a person dances a sideways arabesque, folds the arms and bends back",
    "dance - quasi-cou-de-pied, raised leg above hip-height, jete en tourant":
        "a person dances, raises a leg above hip height and leaps turning",
    "dance - cartwheel-like start, pirouettes, jete": "a person dances, turns pirouettes and leaps",
    "dance - small jetes, attitude/arabesque, shifted-axis pirouette, turn":
        "a person dances small leaps, an arabesque and a pirouette",
    "dance - rond de jambe in the air, jete, turn": "a person dances, circles a raised leg, leaps and turns",
    "dance - glissade devant, glissade derriere, attitude/arabesque":
        "a person dances gliding steps forward and back and an arabesque",
    "dance - sideways steps, pirouette": "a person dances sideways steps and a pirouette",
    "dance - arms held high, pointe tendue a terre, upper body rotation":
        "a person dances with the arms held high, a pointed foot and the upper body turning",
    "dance - small jetes, pirouette": "a person dances small leaps and a pirouette",
    "dance - retire derriere, attitude/arabesque": "a person dances, lifts a bent leg behind and holds an arabesque",
    "dance - coupe dessous, jete en tourant": "a person dances a quick step under and a turning leap",
    "dance - coupe dessous, grand jete en tourant": "a person dances a quick step under and a big turning leap",
    "dance - attitude/arabesque, jete en tourant, bending back":
        "a person dances an arabesque and a turning leap and bends back",
    "basketball - forward dribble": "a person dribbles a basketball forward",
    "basketball - backward dribble": "a person dribbles a basketball backwards",
    "basketball - sideways dribble": "a person dribbles a basketball sideways",
    "basketball - forward dribble, 90-degree left turns":
        "a person dribbles a basketball forward and turns 90 degrees to the left",
    "basketball - forward dribble, 90-degree right turns":
        "a person dribbles a basketball forward and turns 90 degrees to the right",
    "basketball - forward dribble, 90-degree right turns, crossover dribble":
        "a person dribbles a basketball forward, turns 90 degrees to the right and crosses over",
    "basketball - crossover dribble, shoot": "a person dribbles a basketball from hand to hand and shoots",
    "basketball - dribble, shoot": "a person dribbles a basketball and shoots",
    "soccer - kick ball": "a person kicks a soccer ball",
    "start hop stop": "a person hops forward and stops",
    "heiansyodan": "a person performs a karate kata with stances, punches and blocks",
}


def cmu_prompt(description: str) -> str:
    """A CMU index description → prompt; unknown descriptions become "a person <description>"."""
    key = " ".join(description.lower().split())
    if key in CMU_PROMPTS:
        return CMU_PROMPTS[key]
    return f"a person {key}"


# Words after the first families → the family they belong to (the newer sources' prompts:
# bandai-namco, cmu-iclone, cmu-asfamc, deepmimic). Checked after FAMILIES, so every prompt
# of the first sources keeps its family (and its split).
FAMILIES = ("salsa", "jog", "run", "jump", "hop", "walk", "sneak", "squat", "kick",
            "throw", "lie", "grab", "deposit", "elbow", "rotate", "basketball",
            "traffic", "soccer", "wash")
MORE_FAMILIES: tuple[tuple[str, str], ...] = (
    ("dance", "dance"), ("flip", "flip"), ("cartwheel", "flip"), ("crawl", "crawl"),
    ("roll", "roll"), ("gets up", "get up"), ("climb", "climb"), ("sprint", "run"),
    ("bow", "bow"), ("wave", "wave"), ("goodbye", "wave"), ("beckon", "gesture"),
    ("gesture", "gesture"), ("points", "gesture"), ("calls", "gesture"), ("raise", "raise"),
    ("punch", "punch"), ("strike", "punch"), ("karate", "punch"), ("sword", "sword"),
    ("slash", "sword"), ("spin", "spin"), ("bend", "bend"),
)


def label_family(prompt: str) -> str:
    """A coarse action family of a prompt, for stratified splits, caption checks and the data
    card's hours per family."""
    text = prompt.lower()
    for family in FAMILIES:
        if family in text:
            return family
    for word, family in MORE_FAMILIES:
        if word in text:
            return family
    return "other"
