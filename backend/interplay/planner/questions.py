"""Questions as prompts ("what does a person do before a penalty kick?") → the motion that
answers them, from a small knowledge table (Table 8's conversation prompts, #2 and #6).

    answer("What is a person's reaction after stubbing their left feet toe?")
      → ("a person hops on the right foot while holding the left foot with both hands",
         "question: stubbed toe → …")

A question matches an entry by its keywords; when none matches and a similarity function is
given, by the nearest entry description (MiniLM), when similar enough; otherwise the question's
own words become the motion ("how does a person jump" → "a person jumps").
"""

from __future__ import annotations

import re
from typing import Callable

from interplay.catalogue import grammar as g
from interplay.catalogue.words import words

# (keywords, answer, description). {side}: the side the question names (default right),
# {other}: the opposite side.
KNOWLEDGE: tuple[tuple[str, str, str], ...] = (
    (r"penalty|spot[\s-]kick", "a person runs forward and kicks with the right foot",
     "what a person does before a penalty kick"),
    (r"stub\w*|hurt\w*\s+(?:the|his|her|their)?\s*(?:left|right)?\s*(?:foot|feet|toe)|"
     r"step\w*\s+on\s+(?:a\s+)?(?:lego|nail|something\s+sharp)",
     "a person hops on the {other} foot while holding the {side} foot with both hands",
     "a person's reaction to a stubbed toe or a hurt foot"),
    (r"scor\w*\s+a\s+goal|goal\s+celebration|celebrat\w*\s+(?:a\s+)?goal",
     "a person runs forward with both arms raised, then jumps", "how a player celebrates a goal"),
    (r"goalkeeper|goalie|save\s+a\s+(?:shot|penalty)",
     "a person dives to the left with both arms stretched out", "what a goalkeeper does"),
    (r"goodbye|farewell|saying\s+bye|leav\w+\s+a\s+party",
     "a person waves the right hand, then turns around and walks away", "how to say goodbye"),
    (r"greet|hello|meet\w*\s+(?:a\s+)?friend|say\w*\s+hi\b", "a person waves the right hand",
     "how a person greets someone"),
    (r"free\s+throw|shoot\w*\s+(?:a\s+)?(?:basketball|hoop)|basketball",
     "a person bends the knees, then jumps while shooting with both hands up",
     "how to shoot a basketball"),
    (r"\bcold\b|freezing|shiver\w*", "a person rubs both arms with the hands",
     "what a person does when they are cold"),
    (r"\brain\w*", "a person walks quickly with both hands held over the head",
     "what a person does when it starts raining"),
    (r"tired|yawn\w*|wak\w+\s+up|sleepy", "a person stretches both arms above the head",
     "what a person does when they are tired or wake up"),
    (r"don'?t\s+know|confus\w*|not\s+sure|clueless|no\s+idea",
     "a person raises both shoulders with the palms turned up", "how a person shows they don't know"),
    (r"\bwin(?:s|ning)?\b|victory|\bwon\b|champion", "a person jumps with both arms raised above the head",
     "how a person celebrates winning"),
    (r"loud\s+(?:noise|sound|music|bang)|explosion|siren", "a person covers the ears with both hands",
     "a person's reaction to a loud noise"),
    (r"slip\w*\s+on\s+(?:ice|a\s+banana|a\s+wet)|\bicy\b",
     "a person stumbles, swinging both arms, then falls on the floor", "what happens when a person slips"),
    (r"taxi|\bcab\b|bus\s+stop", "a person raises the right arm high and waves it",
     "how a person hails a taxi"),
    (r"warm(?:\s+|-)?up|before\s+(?:a\s+)?(?:run|race|exercise|workout|match)",
     "a person stretches both arms, then jumps in place", "how a person warms up"),
    (r"start\w*\s+(?:of\s+)?a\s+(?:race|sprint)|starting\s+block|on\s+your\s+marks",
     "a person crouches down, then sprints forward", "how a sprinter starts a race"),
    (r"tennis", "a person swings the right arm across the body", "how to hit a tennis ball"),
    (r"golf|putt\w*", "a person swings both arms across the body", "how to swing a golf club"),
    (r"bowling", "a person steps forward and swings the right arm forward low",
     "how a person bowls"),
    (r"pitch\w*|throw\w*\s+(?:a\s+)?(?:ball|baseball|frisbee)",
     "a person steps forward and throws with the right arm", "how to throw a ball"),
    (r"jump\w*\s+rope|skipping\s+rope", "a person hops in place while circling both hands at the sides",
     "how to jump rope"),
    (r"police|arrest\w*|surrender\w*|hands\s+up", "a person raises both hands above the head",
     "what a person does when the police say hands up"),
    (r"applau\w*|concert|end\s+of\s+(?:a\s+)?(?:show|performance|play)", "a person claps the hands",
     "what the audience does at the end of a show"),
    (r"scared|fright\w*|spider|mouse|snake|\bghost",
     "a person jumps back with both arms raised in front of the chest", "a person's reaction to a fright"),
    (r"swimming\s+pool|dive\s+into|\bpool\b",
     "a person raises both arms above the head, then dives forward", "how a person dives into a pool"),
)


def is_question(text: str) -> bool:
    return text.strip().endswith("?") or bool(words("question_opening", ignore_case=True).starts(
        text, len(text) - len(text.lstrip())))


def _fill(answer: str, question: str) -> str:
    side = "left" if re.search(r"\bleft\b", question, re.IGNORECASE) else "right"
    return answer.format(side=side, other="left" if side == "right" else "right")


def answer(question: str, similar: Callable[[str, list[str]], tuple[int, float]] | None = None,
           threshold: float = 0.5) -> tuple[str, str]:
    """(motion text, reason) answering a question prompt."""
    q = question.strip().rstrip("?").strip()
    for keys, text, what in KNOWLEDGE:
        if re.search(keys, q, re.IGNORECASE):
            out = _fill(text, q)
            return out, f"question: matched '{what}' → '{out}'"
    if similar is not None:
        i, score = similar(q, [what for _, _, what in KNOWLEDGE])
        if score >= threshold:
            out = _fill(KNOWLEDGE[i][1], q)
            return out, (f"question: nearest known question '{KNOWLEDGE[i][2]}' (similarity "
                         f"{score:.2f}) → '{out}'")
    rest = g.QUESTION_STEM.sub("", q).strip()
    out = f"a person {rest}" if rest else q
    return out, f"question: not in the knowledge table; planned from its own words '{out}'"
