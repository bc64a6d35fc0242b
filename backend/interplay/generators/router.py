"""The generator the studio and the CLI call: one Router over retrieval, SPAM and CODA that
picks, per request, which one makes it, and writes the reason into the plan.

- one person: SPAM when its weights load and are trained, else retrieval (`generator_reason`
  says why);
- two people: CODA when its weights load and are trained, else retrieval (with the reason);
- edits: SPAM, or `EditUnavailable` saying why not.

    gen = load_generator()                       # heavy loading once (clips, encoder, models)
    plan = gen.plan(Request("a person walks forward then jumps", seconds=6, seed=3))
    plan["generator"]                            # "spam" | "coda" | "retrieval"
    for start, chunk in gen.stream(req, plan): ...
"""

from __future__ import annotations

import logging
from collections.abc import Iterator
from functools import lru_cache
from pathlib import Path

import numpy as np

from interplay.generators.base import EditUnavailable, Request, generate_motion
from interplay.generators.coda.files import DEFAULT_DIR as CODA_DIR
from interplay.generators.coda.generator import CodaGenerator
from interplay.generators.coda.runtime import CodaRuntime
from interplay.generators.plan import GenerationPlan
from interplay.generators.retrieval.generator import RetrievalGenerator
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.generators.spam.generator import SpamGenerator
from interplay.generators.spam.runtime import DEFAULT_DIR as SPAM_DIR
from interplay.generators.spam.runtime import Edit, SpamRuntime
from interplay.generators.weights import placeholder_reason
from interplay.motion.clip import DATA_DIR, default_clips
from interplay.motion.motion import Motion
from interplay.settings import Settings, get_settings

log = logging.getLogger(__name__)
ONE_PERSON_ONLY = "SPAM generates one person; two people use retrieval"


class Router:
    """Retrieval always; SPAM (`spam`, or None with `reason`) for one person; CODA (`coda`, or
    None with `coda_reason`) for two."""

    def __init__(self, index: RetrievalIndex, spam: SpamRuntime | None = None,
                 reason: str | None = None, coda: CodaRuntime | None = None,
                 coda_reason: str | None = None):
        self.index, self.retrieval = index, RetrievalGenerator(index)
        self.spam, self.reason = spam, reason
        self.coda, self.coda_reason = coda, coda_reason
        self._spam = SpamGenerator(spam) if spam is not None else None
        self._coda = CodaGenerator(coda) if coda is not None else None

    @property
    def can_edit(self) -> bool:
        return self._spam is not None

    def redraw(self, plan: GenerationPlan, index: int, seed: int) -> GenerationPlan:
        """`plan` with retrieval segment `index` drawn again (the reviewer's re-draws)."""
        return self.retrieval.redraw(plan, index, seed)

    def _fallback_reason(self, req: Request) -> str | None:
        if req.persons == 1:
            return self.reason
        if self.coda_reason is not None:
            return self.coda_reason
        return self.reason if self._spam is None else ONE_PERSON_ONLY

    def plan(self, req: Request) -> GenerationPlan:
        if req.persons == 1 and self._spam is not None:
            return self._spam.plan(req)
        if req.persons == 2 and self._coda is not None:
            return self._coda.plan(req)
        plan = self.retrieval.plan(req)
        reason = self._fallback_reason(req)
        if reason is not None:
            plan.generator_reason = reason
        return plan

    def stream(self, req: Request, plan: GenerationPlan) -> Iterator[tuple[int, list[np.ndarray]]]:
        kind = plan.generator
        if kind == "spam":
            if self._spam is None:
                raise ValueError(f"this plan needs SPAM, which is not loaded: {self.reason}")
            return self._spam.stream(req, plan)
        if kind == "coda":
            if self._coda is None:
                raise ValueError(f"this plan needs CODA, which is not loaded: {self.coda_reason}")
            return self._coda.stream(req, plan)
        return self.retrieval.stream(req, plan)

    def edit(self, joints: np.ndarray, part: str | None, prompt: str,
             frames: tuple[int, int] | None = None, seed: int | None = None,
             context: str | None = None) -> tuple[Edit, dict]:
        """SPAM's edit of one person's joints (`SpamGenerator.edit`)."""
        if self._spam is None:
            raise EditUnavailable(f"editing needs the SPAM model: {self.reason}" if self.reason
                                  else "this generator cannot edit motions")
        return self._spam.edit(joints, part, prompt, frames, seed, context)

    def generate(self, req: Request) -> Motion:
        return generate_motion(self, req)


def _load(runtime, name: str, weights_dir: Path, encoder, allow_untrained: bool, fallback: str):
    """(runtime.load(weights_dir), None) when the weights load and are trained (or
    allow_untrained), else (None, why) with the reason logged."""
    reason = None if allow_untrained else placeholder_reason(weights_dir, name)
    if reason is None:
        try:
            return runtime.load(weights_dir, encoder=encoder), None
        except Exception as exc:   # missing, broken or foreign files: serve retrieval
            reason = f"{name} weights in {weights_dir} did not load ({type(exc).__name__}: {exc})"
    log.warning("%s: %s", fallback, reason)
    return None, reason


def load_spam(weights_dir: str | Path | None = None, encoder=None, allow_untrained: bool = False
              ) -> tuple[SpamRuntime | None, str | None]:
    """(runtime, None) when SPAM's weights load and are trained (or allow_untrained), else
    (None, why)."""
    return _load(SpamRuntime, "SPAM", Path(weights_dir or SPAM_DIR), encoder, allow_untrained,
                 "using retrieval only")


def load_coda(weights_dir: str | Path | None = None, encoder=None, allow_untrained: bool = False
              ) -> tuple[CodaRuntime | None, str | None]:
    """(runtime, None) when CODA's weights load and are trained, else (None, why)."""
    return _load(CodaRuntime, "CODA", Path(weights_dir or CODA_DIR), encoder, allow_untrained,
                 "two people use retrieval")


def with_spam(index: RetrievalIndex, weights_dir: str | Path | None = None,
              allow_untrained: bool = False) -> Router:
    """Retrieval with SPAM in front for one person when its weights load."""
    spam, reason = load_spam(weights_dir, index.encoder, allow_untrained)
    return Router(index, spam, reason)


def with_models(index: RetrievalIndex, spam_dir: str | Path | None = None,
                coda_dir: str | Path | None = None, allow_untrained: bool = False) -> Router:
    """Retrieval with SPAM (one person) and CODA (two people), each when its weights load."""
    spam, reason = load_spam(spam_dir, index.encoder, allow_untrained)
    coda, coda_reason = load_coda(coda_dir, index.encoder, allow_untrained)
    return Router(index, spam, reason, coda, coda_reason)


@lru_cache(maxsize=4)
def _build(data_dir: str, spam_dir: str | None, use_spam: bool, coda_dir: str | None) -> Router:
    from interplay.text.encoder import get_encoder

    index = RetrievalIndex(default_clips(data_dir), get_encoder())
    if not use_spam:
        return Router(index)
    return with_models(index, spam_dir, coda_dir)


def build_generator(data_dir: str | Path | None = None, spam_dir: str | Path | None = None,
                    coda_dir: str | Path | None = None, use_spam: bool = True) -> Router:
    """The router over the processed data set (models/data by default), built once per
    arguments: SPAM (models/weights/spam) for one person and CODA (models/weights/coda) for
    two when their weights load, else retrieval; use_spam=False gives retrieval alone."""
    return _build(str(data_dir or DATA_DIR), str(spam_dir) if spam_dir else None, use_spam,
                 str(coda_dir) if coda_dir else None)


def load_generator(settings: Settings | None = None, use_spam: bool = True) -> Router:
    """The generator the settings name (data, SPAM and CODA folders; the environment's when
    None): what the server, the CLI and the measurements load."""
    s = settings or get_settings()
    return build_generator(s.data_dir, s.spam_dir, s.coda_dir, use_spam)
