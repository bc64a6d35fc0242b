"""Motion matching by text: find captured windows whose descriptions match a segment prompt
and cut pieces of the requested length from them.

The index holds one window per clip prompt (the whole clip) and one per automatic caption
(its frame range), each with its MiniLM embedding. A query embeds the segment prompt, scores
windows by cosine similarity, keeps the best window per clip, and picks among the top-k
clips near the best score with the request's random generator (so a seed fixes the choice),
preferring train-split clips. Requests longer than the chosen clip chain further pieces
(the same clip again or another of the candidates).

A "track" is the JSON-able result (it goes into the plan): a list of pieces
{"clip", "people", "start", "end", "score"} that together last the requested frames.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..motion.clip import Clip
from .stitch import FADE, Piece


@dataclass(frozen=True)
class RetrievalConfig:
    top_k: int = 5           # clips the seed chooses among
    margin: float = 0.08     # …that score within this of the best
    pair_margin: float = 0.05  # two-person captures win when within this of the best single
    pair_min: float = 0.45     # …and at least this similar to the prompt
    min_piece: int = 20      # a chained piece lasts at least 1 s when the clip allows


@dataclass(frozen=True)
class Candidate:
    clip: int        # index into the index's clips
    window: int      # best window of that clip
    score: float


class RetrievalIndex:
    def __init__(self, clips: list[Clip] | tuple[Clip, ...], encoder,
                 config: RetrievalConfig = RetrievalConfig()):
        if not clips:
            raise ValueError("the retrieval index needs at least one clip")
        self.clips = list(clips)
        self.by_id = {c.id: i for i, c in enumerate(self.clips)}
        self.encoder = encoder
        self.config = config
        rows = []   # (clip index, start, end, text)
        for i, c in enumerate(self.clips):
            rows.append((i, 0, c.frames, c.prompt))
            for cap in c.captions:
                if cap.end - cap.start >= 2:
                    rows.append((i, int(cap.start), min(int(cap.end), c.frames), cap.text))
        self.win_clip = np.array([r[0] for r in rows])
        self.win_start = np.array([r[1] for r in rows])
        self.win_end = np.array([r[2] for r in rows])
        self.win_text = [r[3] for r in rows]
        self.embeddings = encoder.encode(self.win_text)          # (W, 384), unit rows
        self.clip_pair = np.array([len(c.people) == 2 for c in self.clips])
        self.clip_train = np.array([c.split == "train" for c in self.clips])

    # -- scoring ---------------------------------------------------------------------------
    def candidates(self, text: str, pair: bool) -> list[Candidate]:
        """Best window per clip, best first, among two-person clips (pair) or all clips
        (single-person use takes a two-person clip's lead)."""
        q = self.encoder.encode([text])[0]
        score = self.embeddings @ q                                # (W,)
        ok = self.clip_pair[self.win_clip] if pair else np.ones(len(score), bool)
        best: dict[int, int] = {}
        for w in np.flatnonzero(ok)[np.argsort(-score[ok], kind="stable")]:
            best.setdefault(int(self.win_clip[w]), int(w))
        return [Candidate(c, w, float(score[w])) for c, w in best.items()]

    def shortlist(self, text: str, pair: bool) -> list[Candidate]:
        """The top-k clips within `margin` of the best; train-split clips only, if any."""
        cands = self.candidates(text, pair)
        if not cands:
            return []
        top = [c for c in cands[:self.config.top_k] if c.score >= cands[0].score - self.config.margin]
        train = [c for c in top if self.clip_train[c.clip]]
        return train or top

    def use_pair(self, text: str) -> bool:
        """Whether a two-person prompt matches a two-person capture (e.g. salsa) well enough."""
        pair = self.candidates(text, pair=True)
        if not pair:
            return False
        single = self.candidates(text, pair=False)
        best_single = max((c.score for c in single if not self.clip_pair[c.clip]), default=-1.0)
        return pair[0].score >= max(self.config.pair_min, best_single - self.config.pair_margin)

    # -- cutting ---------------------------------------------------------------------------
    def _cut(self, cand: Candidate, need: int, rng: np.random.Generator, first: bool) -> tuple[int, int]:
        """(start, end) in the clip: the window if long enough (random offset inside), else
        the window grown within the clip, else from the window start (or the clip start for a
        chained piece) to the clip end."""
        s, e = int(self.win_start[cand.window]), int(self.win_end[cand.window])
        total = self.clips[cand.clip].frames
        if e - s >= need:
            lo, hi = s, e - need
        elif total >= need:
            lo, hi = max(0, e - need), min(s, total - need)
        else:
            start = s if first else 0
            start = min(start, max(0, total - self.config.min_piece))
            return start, total
        start = int(rng.integers(lo, hi + 1))
        return start, start + need

    def track(self, text: str, frames: int, rng: np.random.Generator, pair: bool = False,
              exclude: set[str] = frozenset()) -> list[dict]:
        """Pieces that last `frames` for a prompt: [{"clip", "people", "start", "end", "score"}]."""
        cands = self.shortlist(text, pair)
        if exclude:
            cands = [c for c in cands if self.clips[c.clip].id not in exclude] or cands
        if not cands:
            raise ValueError("no captured motion matches this request")
        people = [0, 1] if pair else [0]
        pieces, left, first = [], frames, True
        while left > 0:
            cand = cands[int(rng.integers(len(cands)))]
            start, end = self._cut(cand, left, rng, first)
            end = min(end, start + left)
            pieces.append({"clip": self.clips[cand.clip].id, "people": people, "start": start,
                           "end": end, "score": round(cand.score, 4)})
            left -= end - start
            first = False
        return pieces

    def pieces(self, track: list[dict]) -> list[list[Piece]]:
        """Materialise a track: per piece, one `Piece` per person (core + ≤ FADE tail frames)."""
        out = []
        for p in track:
            if p["clip"] not in self.by_id:
                raise ValueError(f"unknown clip {p['clip']!r} in the plan")
            clip = self.clips[self.by_id[p["clip"]]]
            s, e = int(p["start"]), int(p["end"])
            if not 0 <= s < e <= clip.frames:
                raise ValueError(f"frames {s}–{e} are outside clip {clip.id} ({clip.frames} frames)")
            out.append([Piece(clip.people[k][s:e], clip.people[k][e:e + FADE], clip.offsets[k])
                        for k in p["people"]])
        return out

    def clip(self, clip_id: str) -> Clip:
        return self.clips[self.by_id[clip_id]]
