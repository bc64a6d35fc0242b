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

from typing import Callable

from interplay.catalogue import grammar as g
from interplay.catalogue.words import questions, tokens, words

# (the words a question is about, the answer, what it is about), from words.toml's questions.
# {side}: the side the question names (default right), {other}: the opposite side.
KNOWLEDGE = questions()


def is_question(text: str) -> bool:
    return text.strip().endswith("?") or bool(words("question_opening", ignore_case=True).starts(
        text, len(text) - len(text.lstrip())))


def _fill(answer: str, question: str) -> str:
    side = "left" if any(t.text.lower() == "left" for t in tokens(question)) else "right"
    return answer.format(side=side, other="left" if side == "right" else "right")


def answer(question: str, similar: Callable[[str, list[str]], tuple[int, float]] | None = None,
           threshold: float = 0.5) -> tuple[str, str]:
    """(motion text, reason) answering a question prompt."""
    q = question.strip().rstrip("?").strip()
    for keys, text, what in KNOWLEDGE:
        if keys.search(q):
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
