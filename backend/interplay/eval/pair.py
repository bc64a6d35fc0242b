"""Two-person generation on held-out pairs (`interplay eval-pair`): test windows, the rows that
generate pairs (real, retrieval, CODA and its ablations), per-window scores and the embedding
FID is computed in.

Rows: `coda_raw` is the shipped CODA weights' raw samples, `coda` the product's pipeline on
the same samples (seeds are per window and repeat, so the two see the same raw pairs):
planted feet held and the contact refinement for prompts that ask for a touch
(`agents.pair_finish`); the ablations are raw.

Test set: every 4 s window (80 frames, stride 80) of the test split's two-person clips, people
in the clip's order, moved to the pair's canonical frame (`pairs.canonical_window`); captured
salsa and composed (SYNTHETIC) windows are reported separately. Each window's prompt is its
clip's prompt; a generated row makes one pair per window from that prompt, 80 frames.

Scores per window (both people averaged where single-person): IV (mean sphere-lens volume,
cm³ per frame), IF (share of frames where the bodies overlap), contact frames (a hand within
3 cm of the other's body), foot skating (m/s of planted feet), bone deviation (m),
penetration (mean depth, cm, of the deepest overlap between the two bodies per frame; 0 apart).

FID: embeddings from the learned pair evaluator (`agents.pair_evaluator`) when its weights
load; otherwise the statistics embedding of `agents.reaction_eval` (window statistics of
each person in the other's frame, standardised + PCA fitted on the train split's windows), and
the report says which.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.metrics import pair_geometry, person_metrics
from interplay.motion.pair.windows import canonical_window, pair_windows

WINDOW = STRIDE = 80
WEIGHTS = Path(__file__).resolve().parents[3] / "models" / "weights"
CODA_ROWS = ("coda", "coda_noics", "coda_nogdm", "coda_noppl")
# coda_raw: the shipped weights' raw samples; coda: the product's pipeline on them (the
# contact refinement of `agents.contact_refine` for prompts that ask for a touch).
# compose: interaction by composition alone; default: the product's router through the job
# pipeline (composition or retrieve-then-edit, the penetration pass, review rounds).
ROW_NAMES = ("real", "retrieval", "compose", "default", "coda_raw") + CODA_ROWS
SCORES = ("iv_cm3", "if", "contact_frames", "foot_skating", "bone_deviation", "penetration_cm")
Generate = Callable[[str, int, int], np.ndarray]     # (prompt, frames, seed) → (2, frames, 22, 3)


class Skip(Exception):
    """A row that cannot run here; the message says why."""


@dataclass
class PairSet:
    windows: np.ndarray     # (N, 2, L, 22, 3) canonical
    prompts: list[str]
    synthetic: np.ndarray   # (N,) bool
    clip_ids: list[str]

    def __len__(self) -> int:
        return len(self.prompts)

    def subset(self, sel) -> "PairSet":
        idx = np.flatnonzero(sel) if np.asarray(sel).dtype == bool else np.asarray(sel)
        return PairSet(self.windows[idx], [self.prompts[i] for i in idx], self.synthetic[idx],
                       [self.clip_ids[i] for i in idx])


def pair_set(split: str = "test", clips=None, window: int = WINDOW, stride: int = STRIDE) -> PairSet:
    from interplay.motion.clip import default_clips
    clips = [c for c in (clips or default_clips()) if c.split == split and len(c.people) == 2]
    w = pair_windows(clips, window, stride, roles="as_is", mirror=False)
    prompts = {c.id: c.prompt for c in clips}
    return PairSet(w.joints.astype(np.float64), [prompts[i] for i in w.clip_ids], w.synthetic,
                   list(w.clip_ids))


def window_scores(pair: np.ndarray) -> np.ndarray:
    """The SCORES of one window (2, L, 22, 3)."""
    a, b = np.asarray(pair[0], np.float64), np.asarray(pair[1], np.float64)
    g = pair_geometry(a, b)
    people = [person_metrics(a), person_metrics(b)]
    return np.array([g["volume"].mean(), g["overlap"].mean(),
                     (g["hand_gap"] <= 0.03).any(axis=(1, 2)).sum(),
                     np.mean([p["foot_skating"] for p in people]),
                     np.mean([p["bone_deviation"] for p in people]),
                     np.clip(-g["min_distance"], 0.0, None).mean() * 100.0])


# -- FID embedding ---------------------------------------------------------------------------
class StatsEmbedding:
    """reaction_eval's statistics of each person in the pair (standardised, PCA) → (N, 16)."""
    name = "statistics embedding (reaction_eval: standardised window statistics + PCA on train)"

    def __init__(self, reference: np.ndarray):
        from interplay.eval.reaction import Embedding
        self.emb = Embedding(self.stats(reference))

    @staticmethod
    def stats(windows: np.ndarray) -> np.ndarray:
        from interplay.eval.reaction import window_stats
        w = np.stack([canonical_window(np.asarray(x, np.float64)) for x in windows])
        return np.concatenate([window_stats(w[:, 0], w[:, 1]), window_stats(w[:, 1], w[:, 0])],
                              axis=1)

    def __call__(self, windows: np.ndarray) -> np.ndarray:
        return self.emb(self.stats(windows))


class LearnedEmbedding:
    name = "learned pair evaluator (models/weights/pair_evaluator)"

    def __init__(self, evaluator):
        self.evaluator = evaluator

    def __call__(self, windows: np.ndarray) -> np.ndarray:
        return np.asarray(self.evaluator.embed(windows), np.float64)


def fid_embedding(train: PairSet):
    """The learned pair evaluator when it loads, else the statistics embedding."""
    try:
        from interplay.review.pair_evaluator import PairEvaluator
        return LearnedEmbedding(PairEvaluator.load())
    except Exception:   # not there yet (or broken): the documented statistics fallback
        return StatsEmbedding(train.windows)


# -- rows ------------------------------------------------------------------------------------
_INDEX: dict[int, tuple] = {}


def _train_index(clips):
    """The retrieval index over the train split of `clips`, built once for every row that
    draws from it (the text embeddings are the costly part)."""
    if id(clips) not in _INDEX:
        from interplay.generators.retrieval.index import RetrievalIndex
        from interplay.text.encoder import get_encoder
        _INDEX.clear()          # one clip list at a time; it is kept so its id stays its own
        _INDEX[id(clips)] = (clips, RetrievalIndex([c for c in clips if c.split == "train"],
                                                   get_encoder()))
    return _INDEX[id(clips)][1]


def _retrieval(clips) -> Generate:
    from interplay.generators.base import Request
    from interplay.generators.retrieval.generator import RetrievalGenerator
    gen = RetrievalGenerator(_train_index(clips))

    def generate(prompt: str, frames: int, seed: int) -> np.ndarray:
        req = Request(prompt, persons=2, seconds=frames / sk.FPS, seed=seed)
        chunks = [people for _, people in gen.stream(req, gen.plan(req))]
        return np.stack([np.concatenate([c[i] for c in chunks])[:frames] for i in range(2)])
    return generate


def _stack(people, frames: int) -> np.ndarray:
    return np.stack([np.asarray(p, np.float64)[:frames] for p in people])


def _compose(clips) -> Generate:
    from interplay.generators.base import Request, generate_motion
    from interplay.generators.interaction.generator import InteractionGenerator
    gen = InteractionGenerator(_train_index(clips))

    def generate(prompt: str, frames: int, seed: int) -> np.ndarray:
        req = Request(prompt, persons=2, seconds=frames / sk.FPS, seed=seed)
        return _stack(generate_motion(gen, req).people, frames)
    return generate


def _default(clips) -> Generate:
    """The studio's path over the train split's clips (no models: two people need none; the
    review scores by caption agreement)."""
    from interplay.generators.base import Request
    from interplay.generators.router import Router
    from interplay.pipeline.orchestrator import orchestrate
    router = Router(_train_index(clips))

    def generate(prompt: str, frames: int, seed: int) -> np.ndarray:
        req = Request(prompt, persons=2, seconds=frames / sk.FPS, seed=seed)
        out = orchestrate(router, req, lambda e: None, lambda s, c: None)
        return _stack(out.people, frames)
    return generate


def _coda(weights: Path, product: bool = False) -> Generate:
    from interplay.generators.coda.finish import finish_pair
    from interplay.generators.coda.runtime import CodaRuntime
    from interplay.generators.weights import placeholder_reason
    if not (weights / "config.json").is_file():
        raise Skip(f"no weights in models/weights/{weights.name}")
    why = placeholder_reason(weights, "CODA")
    if why:
        raise Skip(why.replace(str(WEIGHTS.parents[1]) + "/", ""))
    try:
        rt = CodaRuntime.load(weights)
    except Exception as exc:
        raise Skip(f"models/weights/{weights.name} did not load ({type(exc).__name__})") from None

    def generate(prompt: str, frames: int, seed: int) -> np.ndarray:
        pair = np.concatenate([c for _, c in rt.stream([(prompt, frames)], seed)], axis=1)
        return finish_pair(pair, prompt)[0] if product else pair
    return generate


def load_row(name: str, clips, weights: Path = WEIGHTS) -> Generate | None:
    """None for the real row; Skip when the row's weights are missing or untrained."""
    if name == "real":
        return None
    if name == "retrieval":
        return _retrieval(clips)
    if name == "compose":
        return _compose(clips)
    if name == "default":
        return _default(clips)
    if name == "coda_raw":
        return _coda(Path(weights) / "coda")
    if name in CODA_ROWS:
        return _coda(Path(weights) / name, product=name == "coda")
    raise ValueError(f"unknown row {name!r}; expected one of {ROW_NAMES}")
