"""Motion matching by text: find captured windows whose descriptions match a segment prompt
and cut pieces of the requested length from them.

The index holds one window per clip prompt (the whole clip) and one per automatic caption
(its frame range), each with its MiniLM embedding. A query embeds the segment prompt, scores
windows by cosine similarity (a caption's averaged with its clip label's), keeps the best
window per clip, and picks among the top-k clips near the best score with the request's
random generator (so a seed fixes the choice), preferring train-split clips. Requests longer than the chosen clip chain further pieces
(the same clip again or another of the candidates); a piece that continues another starts at
the frame whose pose best matches where the previous one ends (`matching`).

A "track" is the JSON-able result (it goes into the plan): a list of pieces
{"clip", "people", "start", "end", "score"} that together last the requested frames.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.generators.retrieval.matching import best_start, pose_features
from interplay.generators.retrieval.stitch import FADE, Piece
from interplay.motion.clip import Clip


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
        # Windows: (clip index, start, end, text, kind). A clip prompt covers the whole clip;
        # a caption its frames. Two-person clips: their prompt serves both pair requests and
        # single ones (taking the lead), their "person k: …" captions only pair requests.
        rows = []
        for i, c in enumerate(self.clips):
            rows.append((i, 0, c.frames, c.prompt, "prompt"))
            for cap in c.captions:
                if cap.end - cap.start >= 2:
                    rows.append((i, int(cap.start), min(int(cap.end), c.frames), cap.text, "caption"))
        self.win_clip = np.array([r[0] for r in rows])
        self.win_start = np.array([r[1] for r in rows])
        self.win_end = np.array([r[2] for r in rows])
        self.win_text = [r[3] for r in rows]
        self.win_prompt = np.array([r[4] == "prompt" for r in rows])
        self.embeddings = encoder.encode(self.win_text)          # (W, 384), unit rows
        self.clip_pair = np.array([len(c.people) == 2 for c in self.clips])
        self.clip_train = np.array([c.split == "train" for c in self.clips])
        self.clip_prompt_win = np.flatnonzero(self.win_prompt)      # (C,) clips are in order
        pair_win = self.clip_pair[self.win_clip]
        self.usable = {True: pair_win, False: ~pair_win | self.win_prompt}
        self._features: dict[tuple[int, tuple[int, ...]], np.ndarray] = {}

    # -- scoring ---------------------------------------------------------------------------
    def candidates(self, text: str, pair: bool, prompts_only: bool = False) -> list[Candidate]:
        """Best window per clip, best first, among two-person clips (pair) or single-person
        clips plus the prompts of two-person clips (whose lead then plays alone)."""
        q = self.encoder.encode([text])[0]
        score = self.embeddings @ q                                # (W,)
        # Captions are automatic and sometimes wrong; a caption window counts half its own
        # match and half its clip's (hand-written) label's, so it wins inside fitting clips.
        label = score[self.clip_prompt_win][self.win_clip]
        score = np.where(self.win_prompt, score, (score + label) / 2)
        ok = self.usable[pair] & (self.win_prompt if prompts_only else True)
        best: dict[int, int] = {}
        for w in np.flatnonzero(ok)[np.argsort(-score[ok], kind="stable")]:
            best.setdefault(int(self.win_clip[w]), int(w))
        return [Candidate(c, w, float(score[w])) for c, w in best.items()]

    def shortlist(self, text: str, pair: bool, rng: np.random.Generator) -> list[Candidate]:
        """Up to top-k clips within `margin` of the best (equal scores in seeded order),
        train-split clips only if there are any."""
        cands = self.candidates(text, pair)       # even a poor best match plays (its score shows)
        if not cands:
            return []
        near = [c for c in cands if c.score >= cands[0].score - self.config.margin]
        near = [c for c in near if self.clip_train[c.clip]] or near
        tie = rng.permutation(len(near))
        order = sorted(range(len(near)), key=lambda i: (-round(near[i].score, 3), tie[i]))
        return [near[i] for i in order[:self.config.top_k]]

    def use_pair(self, text: str) -> bool:
        """Whether a two-person prompt matches a two-person capture's label (e.g. salsa) at
        least about as well as any single-person label."""
        pair = self.candidates(text, pair=True, prompts_only=True)
        if not pair:
            return False
        single = self.candidates(text, pair=False, prompts_only=True)
        best_single = max((c.score for c in single if not self.clip_pair[c.clip]), default=-1.0)
        return pair[0].score >= max(self.config.pair_min, best_single - self.config.pair_margin)

    # -- cutting ---------------------------------------------------------------------------
    def features(self, clip: int, people: tuple[int, ...]) -> np.ndarray:
        """Pose-matching features (T, D·len(people)) of a clip's people, cached."""
        key = (clip, tuple(people))
        if key not in self._features:
            c = self.clips[clip]
            self._features[key] = np.concatenate([pose_features(c.people[k]) for k in people],
                                                 axis=1).astype(np.float32)
        return self._features[key]

    def _target(self, after: dict | None, people: list[int]) -> np.ndarray | None:
        """Features of the frame right after a previous piece (its last one at a clip's end),
        when that piece had as many people as the next."""
        if not after or after["clip"] not in self.by_id or len(after["people"]) != len(people):
            return None
        clip = self.by_id[after["clip"]]
        f = self.features(clip, tuple(after["people"]))
        return f[min(int(after["end"]), len(f) - 1)]

    def _cut(self, cand: Candidate, need: int, rng: np.random.Generator, first: bool,
             target: np.ndarray | None, people: list[int]) -> tuple[int, int]:
        """(start, end) in the clip: inside the window if it is long enough, else the window
        grown within the clip, else up to the clip end. The start is the frame that best
        continues the previous pose (target), or random when there is none."""
        s, e = int(self.win_start[cand.window]), int(self.win_end[cand.window])
        total = self.clips[cand.clip].frames
        if e - s >= need:
            lo, hi = s, e - need
        elif total >= need:
            lo, hi = max(0, e - need), min(s, total - need)
        else:
            # Too short: play to the clip end, from the window start (first piece) or from
            # wherever in its first part the pose matches.
            if target is None:
                lo = hi = min(s if first else 0, max(0, total - self.config.min_piece))
            else:
                lo, hi = 0, max(0, total - 2 * self.config.min_piece)
        if target is not None:
            start = best_start(self.features(cand.clip, tuple(people)), target, lo, hi)
        else:
            start = int(rng.integers(lo, hi + 1))
        return start, min(total, start + need)

    def track(self, text: str, frames: int, rng: np.random.Generator, pair: bool = False,
              exclude: frozenset[str] | set[str] = frozenset(), after: dict | None = None
              ) -> list[dict]:
        """Pieces that last `frames` for a prompt: [{"clip", "people", "start", "end", "score"}];
        `after` is the piece this track continues (its start pose is matched)."""
        cands = self.shortlist(text, pair, rng)
        if exclude:
            cands = [c for c in cands if self.clips[c.clip].id not in exclude] or cands
        if not cands:
            raise ValueError("no captured motion matches this request")
        people = [0, 1] if pair else [0]
        pieces: list[dict] = []
        left = frames
        while left > 0:
            cand = cands[int(rng.integers(len(cands)))]
            start, end = self._cut(cand, left, rng, not pieces, self._target(after, people), people)
            end = min(end, start + left)
            rest = left - (end - start)
            if 0 < rest < self.config.min_piece and end - start > 2 * self.config.min_piece:
                end -= self.config.min_piece - rest     # leave the next piece ≥ 1 s, not a sliver
            after = {"clip": self.clips[cand.clip].id, "people": people, "start": start,
                     "end": end, "score": round(cand.score, 4)}
            pieces.append(after)
            left -= end - start
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
