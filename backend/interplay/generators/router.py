"""The generator the studio and the CLI call: one Router over retrieval, SPAM and CODA that
picks, per request, which one makes it, and writes the reason into the plan.

- one person: retrieve-then-edit (`generators/retrieve_edit`: captured clips, the plan's arm
  actions laid over them, feet on the floor), chosen by `interplay eval-prompts`: on the dev
  split it passed 0.59 of the one-person checks against retrieval's 0.45 and SPAM's 0.17
  (docs/eval.md has the test-split table);
- two people: interaction by composition (`generators/interaction`: each person from real
  single-person clips, timed against each other, touching where the prompt asks), which the
  same benchmark measured above retrieval and CODA (dev split: 1.00 against 0.58 and 0.32 of
  the two-person checks); what it does not compose (a couple dancing, jumping together) goes
  to retrieve-then-edit over the two-person captures, and the plan says why; CODA stays
  loaded as a row of the benchmark and for its own requests;
- edits: an arm pose by IK where the edit names one, else SPAM, or `EditUnavailable`
  saying why not.

    gen = load_generator()                       # heavy loading once (clips, encoder, models)
    plan = gen.plan(Request("a person walks forward then jumps", seconds=6, seed=3))
    plan["generator"]          # "retrieve_edit" | "compose" (the defaults) | "spam" | "coda" | "retrieval"
    for start, chunk in gen.stream(req, plan): ...
"""

from __future__ import annotations

import logging
from collections.abc import Iterator
from functools import lru_cache
from pathlib import Path

import numpy as np

from interplay.generators.base import EditUnavailable, Request, generate_motion, random_seed
from interplay.generators.coda.files import DEFAULT_DIR as CODA_DIR
from interplay.generators.coda.generator import CodaGenerator
from interplay.generators.coda.runtime import CodaRuntime
from interplay.generators.coverage import cover
from interplay.generators.interaction.generator import NAME as COMPOSE
from interplay.generators.interaction.generator import InteractionGenerator
from interplay.generators.plan import GenerationPlan
from interplay.generators.primitives.edit import head_edit
from interplay.generators.retrieval.generator import RetrievalGenerator
from interplay.generators.retrieval.index import RetrievalIndex
from interplay.generators.retrieve_edit.generator import RetrieveEditGenerator
from interplay.generators.retrieve_edit.leg_edit import leg_edit
from interplay.generators.retrieve_edit.part_edit import pose_edit
from interplay.generators.spam.generator import SpamGenerator
from interplay.generators.spam.runtime import DEFAULT_DIR as SPAM_DIR
from interplay.generators.spam.runtime import Edit, SpamRuntime
from interplay.generators.weights import placeholder_reason
from interplay.motion import skeleton as sk
from interplay.motion.clip import DATA_DIR, default_clips
from interplay.motion.motion import Motion
from interplay.settings import Settings, get_settings

log = logging.getLogger(__name__)


class Router:
    """Retrieve-then-edit plans every request; SPAM (`spam`, or None with `reason`) makes the
    part edits and plays plans that name it, CODA (`coda`, or None with `coda_reason`) plays
    plans that name it (the benchmark's rows)."""

    def __init__(self, index: RetrievalIndex, spam: SpamRuntime | None = None,
                 reason: str | None = None, coda: CodaRuntime | None = None,
                 coda_reason: str | None = None, default: str = "retrieve_edit"):
        if default not in ("retrieve_edit", "retrieval"):
            raise ValueError(f"default must be retrieve_edit or retrieval, got {default!r}")
        self.default = default
        self.index, self.retrieval = index, RetrievalGenerator(index)
        self.retrieve_edit = RetrieveEditGenerator(index)
        self.compose = InteractionGenerator(index, retrieval=self.retrieve_edit)
        self.spam, self.reason = spam, reason
        self.coda, self.coda_reason = coda, coda_reason
        self._spam = SpamGenerator(spam) if spam is not None else None
        self._coda = CodaGenerator(coda) if coda is not None else None

    @property
    def can_edit(self) -> bool:
        return self._spam is not None

    def redraw(self, plan: GenerationPlan, index: int, seed: int) -> GenerationPlan:
        """`plan` with retrieval segment `index` drawn again (the reviewer's re-draws)."""
        if plan.generator == "retrieve_edit":
            out = self.retrieve_edit.redraw(plan, index, seed)
        else:
            out = self.retrieval.redraw(plan, index, seed)
        cover(out, self.index)
        return out

    def plan(self, req: Request) -> GenerationPlan:
        """The default generator's plan: retrieve-then-edit for one person, composition for
        two (retrieve-then-edit where it composes nothing; see the module's note for the
        measurements that chose them), or retrieval alone when built so."""
        if self.default == "retrieval":
            plan = self.retrieval.plan(req)
        elif req.persons == 2:
            plan = self.compose.plan(req)
        else:
            plan = self.retrieve_edit.plan(req)
        cover(plan, self.index)
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
        if kind == COMPOSE:
            return self.compose.stream(req, plan)
        if kind == "retrieve_edit":
            return self.retrieve_edit.stream(req, plan)
        return self.retrieval.stream(req, plan)

    def edit(self, joints: np.ndarray, part: str | None, prompt: str,
             frames: tuple[int, int] | None = None, seed: int | None = None,
             context: str | None = None) -> tuple[Edit, dict]:
        """One person's joints with a part re-made from `prompt`: an arm pose the IK can hold
        (`retrieve_edit.part_edit`: raised, T-pose, crossed, on the hips, forward, a wave)
        by IK over the frames, which the edit benchmark measured holding where SPAM's
        re-generation did not; one leg's kick from a captured kick of that leg
        (`retrieve_edit.leg_edit`: SPAM's edit gave no kick and moved the untouched joints
        30–50 cm); the head (part "head": look, nod, shake) by the head primitive
        (`primitives.edit`: only the head joint moves), never SPAM; anything else by SPAM's
        edit (`SpamGenerator.edit`)."""
        if isinstance(prompt, str) and prompt.strip():
            s = seed if seed is not None else random_seed()
            if (part or "").strip().lower() == "head":
                return _head_edit(joints, prompt, frames, self.index.encoder, s)
            made = pose_edit(joints, part, prompt, frames)
            if made is not None:
                return _laid_edit(*made, limbs=made[1]["arms"], seed=s)
            kicked = leg_edit(joints, part, prompt, frames, self.retrieval, s)
            if kicked is not None:
                return _laid_edit(*kicked, limbs=[kicked[1]["leg"]], seed=s)
        if self._spam is None:
            raise EditUnavailable(f"this edit needs the SPAM model: {self.reason}" if self.reason
                                  else "this generator cannot edit motions")
        return self._spam.edit(joints, part, prompt, frames, seed, context)

    def generate(self, req: Request) -> Motion:
        return generate_motion(self, req)


def _head_edit(joints: np.ndarray, prompt: str, frames: tuple[int, int] | None, encoder,
               seed: int) -> tuple[Edit, dict]:
    """A head edit by the head primitive (`primitives.edit`): only the head joint moves."""
    out, entry = head_edit(joints, prompt, frames, encoder)
    entry["parts"], entry["seed"] = ["head"], seed
    a, b = entry["frames"]
    return Edit(joints=out, parts=("head",), frames=(int(a), int(b)), masked_tokens=0, steps=0,
                untouched_change_cm=entry["untouched_change_cm"],
                untouched_pose_change_cm=entry["untouched_change_cm"],
                model_untouched_change_cm=0.0), entry


def _laid_edit(out: np.ndarray, entry: dict, limbs: list[str], seed: int) -> tuple[Edit, dict]:
    """An edit made by laying a pose or a captured kick over the limbs named (no tokens
    decoded), as the `Edit` SPAM's edits return, and its plan entry."""
    parts = tuple(sk.resolve_part(x) for x in limbs)
    entry["parts"], entry["seed"] = list(parts), seed
    a, b = entry["frames"]
    return Edit(joints=out, parts=parts, frames=(int(a), int(b)), masked_tokens=0, steps=0,
                untouched_change_cm=entry["untouched_change_cm"],
                untouched_pose_change_cm=entry["untouched_change_cm"],
                model_untouched_change_cm=0.0), entry


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
        return Router(index, default="retrieval")
    return with_models(index, spam_dir, coda_dir)


def build_generator(data_dir: str | Path | None = None, spam_dir: str | Path | None = None,
                    coda_dir: str | Path | None = None, use_spam: bool = True) -> Router:
    """The router over the processed data set (models/data by default), built once per
    arguments: retrieve-then-edit plans every request; SPAM (models/weights/spam) and CODA
    (models/weights/coda) are loaded when their weights are (edits, the benchmark's rows,
    plans that name them); use_spam=False gives retrieval alone (no models, no edits
    laid over the captures)."""
    return _build(str(data_dir or DATA_DIR), str(spam_dir) if spam_dir else None, use_spam,
                 str(coda_dir) if coda_dir else None)


def load_generator(settings: Settings | None = None, use_spam: bool = True) -> Router:
    """The generator the settings name (data, SPAM and CODA folders; the environment's when
    None): what the server, the CLI and the measurements load."""
    s = settings or get_settings()
    return build_generator(s.data_dir, s.spam_dir, s.coda_dir, use_spam)
