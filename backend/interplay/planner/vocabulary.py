"""The motion vocabulary the data knows, and the nearest phrase to a text by MiniLM cosine
similarity (CoMA restricts its recaption to words of the training data; this is the offline
version of that restriction).

    vocab = load_vocabulary()                      # clip prompts + whole-body captions + lexicon
    vocab.nearest("a person does a slide tackle")  → Match(phrase, target, score, source)

Phrases: every clip prompt and every whole-body caption of the processed data set
("the person jogs in a circle to the left" → "a person jogs in a circle to the left"), and each
lexicon entry's name whose target is its motion text. Embeddings are computed once per process.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Callable

import numpy as np

from interplay.planner import lexicon


@dataclass(frozen=True)
class Match:
    phrase: str       # the vocabulary phrase that matched
    target: str       # what to use instead (a clip prompt itself, or a lexicon entry's text)
    score: float      # cosine similarity
    source: str       # "data" | "lexicon"


class Vocabulary:
    def __init__(self, phrases: list[str], targets: list[str], sources: list[str],
                 encode: Callable[[list[str]], np.ndarray]):
        if not (len(phrases) == len(targets) == len(sources)) or not phrases:
            raise ValueError("a vocabulary needs the same number (> 0) of phrases, targets, sources")
        self.phrases, self.targets, self.sources = phrases, targets, sources
        self.encode = encode
        self.vectors = encode(phrases)                      # (N, 384) unit rows

    def scores(self, text: str) -> np.ndarray:
        return self.vectors @ self.encode([text])[0]

    def nearest(self, text: str, source: str | None = None) -> Match:
        s = self.scores(text)
        if source is not None:
            s = np.where(np.asarray(self.sources) == source, s, -np.inf)
        i = int(np.argmax(s))
        return Match(self.phrases[i], self.targets[i], float(s[i]), self.sources[i])

    def similar(self, text: str, options: list[str]) -> tuple[int, float]:
        """Index and cosine of the option nearest to `text` (for the question table)."""
        s = self.encode(options) @ self.encode([text])[0]
        i = int(np.argmax(s))
        return i, float(s[i])


def _without_speaker(caption: str) -> str:
    """A caption without its leading "person 2: "."""
    if not caption.startswith("person "):
        return caption
    rest = caption[len("person "):]
    number = rest[:next((i for i, c in enumerate(rest) if not c.isdecimal()), len(rest))]
    return rest[len(number) + 1:].lstrip() if number and rest[len(number):len(number) + 1] == ":" else caption


def data_phrases(clips) -> list[str]:
    """Clip prompts and whole-body captions, as "a person …" sentences, deduplicated."""
    out: dict[str, None] = {}
    for c in clips:
        out.setdefault(c.prompt.strip(), None)
        for cap in c.captions:
            text = _without_speaker(cap.text.strip())
            if cap.part == "body" or text.startswith("the person"):
                person = text.startswith("the person") and not text[10:11].isalnum() and text[10:11] != "_"
                out.setdefault("a person" + text[10:] if person else text, None)
    return [p for p in out if p]


@lru_cache(maxsize=2)
def load_vocabulary(data_dir: str | None = None) -> Vocabulary:
    """The vocabulary of the processed data set (models/data unless given) and the lexicon,
    encoded with the shared MiniLM encoder."""
    from interplay.motion.clip import DATA_DIR, default_clips
    from interplay.text.encoder import get_encoder

    clips = default_clips(str(data_dir or DATA_DIR))
    data = data_phrases(clips)
    lex = lexicon.phrases()
    phrases = data + [f"a person does the {name}" for name, _ in lex]
    targets = data + [text for _, text in lex]
    sources = ["data"] * len(data) + ["lexicon"] * len(lex)
    return Vocabulary(phrases, targets, sources, get_encoder().encode)
