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
{"clip", "people", "start", "end", "score"} that together last the requested frames. A
piece's clip may name a view of a capture (`views.py`: "…#mirrored", "…#reversed"), whose
frames, rest offsets and texts `clip()` gives as a clip of its own; what each capture does is
measured once (`measured.py`) for the constrained draws of `tracks.py`, which may also leave a
track shorter than its segment (the generator holds the last pose).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interplay.generators.retrieval import views
from interplay.generators.retrieval.matching import best_start, pose_features
from interplay.generators.retrieval.measured import Measurer, Measures
from interplay.generators.retrieval.stitch import FADE, Piece
from interplay.generators.retrieval.views import View
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
    view: View | None = None              # None: the capture as it is (views.py)
    span: tuple[int, int] | None = None   # frames of the view to cut in (default: the window's)


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
        self._features: dict[tuple[str, tuple[int, ...]], np.ndarray] = {}
        self._views: dict[str, Clip] = {}
        self.measures = Measurer(lambda clip_id: self.clip(clip_id).people)

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
        return self.narrow(self.candidates(text, pair), rng)  # even a poor best match plays

    def narrow(self, cands: list[Candidate], rng: np.random.Generator,
               margin: float | None = None) -> list[Candidate]:
        """Of candidates best first: up to top-k within `margin` (the config's by default) of
        the best (equal scores in seeded order), train-split clips only if there are any."""
        if not cands:
            return []
        margin = self.config.margin if margin is None else margin
        near = [c for c in cands if c.score >= cands[0].score - margin]
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

    # -- views ---------------------------------------------------------------------------
    def ref(self, cand: Candidate) -> str:
        """The name a plan records for a candidate's frames: its clip id, or its view's."""
        return cand.view.ref if cand.view is not None else self.clips[cand.clip].id

    def view(self, ref: str) -> View:
        """The view a plan's clip name stands for; ValueError for an unknown clip."""
        view = View.parse(ref)
        if view.clip not in self.by_id:
            raise ValueError(f"unknown clip {view.clip!r} in the plan")
        return view

    def people(self, ref: str) -> list[np.ndarray]:
        """Every person's joints (T, 22, 3) of a clip or a view of it."""
        return self.clip(ref).people

    def measured(self, ref: str) -> Measures:
        """What a clip's (or view's) person 0 does, measured (`measured.py`)."""
        return self.measures(self.view(ref))

    def window_span(self, cand: Candidate) -> tuple[int, int]:
        """The frames of the candidate's view it is cut in: its span, or its window's."""
        if cand.span is not None:
            return cand.span
        s, e = int(self.win_start[cand.window]), int(self.win_end[cand.window])
        view = cand.view
        return view.span(s, e, self.clips[cand.clip].frames) if view is not None else (s, e)

    # -- cutting ---------------------------------------------------------------------------
    def features(self, ref: str, people: tuple[int, ...]) -> np.ndarray:
        """Pose-matching features (T, D·len(people)) of a clip's (or view's) people, cached."""
        key = (ref, tuple(people))
        if key not in self._features:
            joints = self.people(ref)
            self._features[key] = np.concatenate([pose_features(joints[k]) for k in people],
                                                 axis=1).astype(np.float32)
        return self._features[key]

    def _target(self, after: dict | None, people: list[int]) -> np.ndarray | None:
        """Features of the frame right after a previous piece (its last one at a clip's end,
        or when the piece's last pose was held), when that piece had as many people as the
        next."""
        if not after or len(after["people"]) != len(people):
            return None
        try:
            f = self.features(after["clip"], tuple(after["people"]))
        except ValueError:
            return None
        end = int(after["end"]) - (1 if after.get("held") else 0)
        return f[max(0, min(end, len(f) - 1))]

    def _cut(self, cand: Candidate, need: int, rng: np.random.Generator, first: bool,
             target: np.ndarray | None, people: list[int]) -> tuple[int, int]:
        """(start, end) in the clip: inside the window if it is long enough, else the window
        grown within the clip, else up to the clip end (a candidate with a `span` is never
        grown past it). The start is the frame that best continues the previous pose
        (target), or random when there is none."""
        s, e = self.window_span(cand)
        floor, total = (s, e) if cand.span is not None else (0, self.clips[cand.clip].frames)
        if e - s >= need:
            lo, hi = s, e - need
        elif total - floor >= need:
            lo, hi = max(floor, e - need), min(s, total - need)
        else:
            # Too short: play to the clip end, from the window start (first piece) or from
            # wherever in its first part the pose matches.
            if target is None:
                lo = hi = min(s if first else floor, max(floor, total - self.config.min_piece))
            else:
                lo, hi = floor, max(floor, total - 2 * self.config.min_piece)
        if target is not None:
            start = best_start(self.features(self.ref(cand), tuple(people)), target, lo, hi)
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
        return self.chain(cands, frames, rng, [0, 1] if pair else [0], after)

    def chain(self, cands: list[Candidate], frames: int, rng: np.random.Generator,
              people: list[int], after: dict | None = None) -> list[dict]:
        """Pieces cut from seeded picks among `cands`, each continuing the pose the one before
        ends in, until they last `frames`."""
        pieces: list[dict] = []
        left = frames
        while left > 0:
            cand = cands[int(rng.integers(len(cands)))]
            start, end = self._cut(cand, left, rng, not pieces, self._target(after, people), people)
            end = min(end, start + left)
            rest = left - (end - start)
            if 0 < rest < self.config.min_piece and end - start > 2 * self.config.min_piece:
                end -= self.config.min_piece - rest     # leave the next piece ≥ 1 s, not a sliver
            after = {"clip": self.ref(cand), "people": people, "start": start,
                     "end": end, "score": round(cand.score, 4)}
            pieces.append(after)
            left -= end - start
        return pieces

    def pieces(self, track: list[dict]) -> list[list[Piece]]:
        """Materialise a track: per piece, one `Piece` per person (core + ≤ FADE tail frames),
        from the clip or the view of it the piece names."""
        out = []
        for p in track:
            clip = self.clip(self.view(p["clip"]).ref)
            s, e = int(p["start"]), int(p["end"])
            if not 0 <= s < e <= clip.frames:
                raise ValueError(f"frames {s}–{e} are outside clip {clip.id} ({clip.frames} frames)")
            out.append([Piece(clip.people[k][s:e], clip.people[k][e:e + FADE], clip.offsets[k])
                        for k in p["people"]])
        return out

    def clip(self, clip_id: str) -> Clip:
        """The capture a clip id names, or a view of it as a clip of its own (its frames turned
        as the view shows them, left and right swapped in its texts when mirrored)."""
        view = View.parse(clip_id)
        clip = self.clips[self.by_id[view.clip]]
        if view.plain:
            return clip
        if clip_id not in self._views:
            if len(self._views) >= 64:
                self._views.clear()
            self._views[clip_id] = views.clip(clip, view)
        return self._views[clip_id]
