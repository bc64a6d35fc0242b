"""The generator rows `interplay eval-prompts` compares, each turning a prompt and a seed into
people (one (T, 22, 3) array each) and the plan it made:

  retrieval  the retrieval generator alone (one and two people), plan → every frame
  spam       SPAM alone (one person only), plan → every frame
  coda       CODA alone (two people only), plan → every frame
  retrieve_edit  retrieval's clips with the plan's arm actions laid over them by IK and the
             feet put on the floor (`generators/retrieve_edit`), plan → every frame
  compose    interaction by composition alone (two people only: real single-person clips
             timed against each other, contacts by IK, `generators/interaction`), plan →
             every frame
  default    the product: the router (retrieve_edit, chosen by this benchmark) through the
             studio's whole pipeline, `orchestrate` with the evaluator the server loads:
             plan → generate → review rounds → trajectories

Rows are built from the generator the settings name (`load_generator`); a row whose model
did not load is skipped with the router's reason.

A part edit (the fresh split's `"edit"` prompts) is made on every row's base motion the way the
studio makes it: `pipeline.editing.edit_joints` with the server's generator, the router (the
studio edits whatever motion it holds with that one). An edit it cannot make raises, and the
benchmark records the prompt's checks as failed with the reason.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from interplay.generators.base import Request, generate_motion
from interplay.generators.coda.generator import CodaGenerator
from interplay.generators.interaction.generator import InteractionGenerator
from interplay.generators.retrieve_edit.generator import RetrieveEditGenerator
from interplay.generators.router import Router, load_generator
from interplay.generators.spam.generator import SpamGenerator
from interplay.pipeline.editing import edit_joints
from interplay.pipeline.orchestrator import default_evaluator, orchestrate
from interplay.settings import Settings

ROW_NAMES = ("retrieval", "spam", "coda", "retrieve_edit", "compose", "default")
Make = Callable[[Request], tuple[list[np.ndarray], dict]]


@dataclass(frozen=True)
class Row:
    name: str
    persons: tuple[int, ...]        # the prompts it can serve
    make: Make
    about: str
    editor: Any = None              # the generator part edits are made with (the router)


def _plain(gen) -> Make:
    def make(req: Request) -> tuple[list[np.ndarray], dict]:
        m = generate_motion(gen, req)
        return m.people, m.plan
    return make


def _pipeline(router: Router) -> Make:
    evaluator = default_evaluator()

    def make(req: Request) -> tuple[list[np.ndarray], dict]:
        out = orchestrate(router, req, lambda e: None, lambda s, c: None, evaluator=evaluator)
        return [np.asarray(p) for p in out.people], out.plan.to_json()
    return make


def edited(row: Row, prompt: str, people: list[np.ndarray], plan: dict, edit: dict,
           seed: int) -> tuple[list[np.ndarray], dict]:
    """(people, plan) after the studio's edit of `edit["part"]` from `edit["text"]` over the
    whole motion, made on `people` (the base motion of `prompt`) by the row's editor."""
    if row.editor is None:
        raise ValueError(f"row {row.name} has no editor for part edits")
    joints, plan, _, _ = edit_joints(row.editor, people, plan, prompt, edit["part"],
                                     edit["text"], None, seed)
    return [np.asarray(joints, dtype=np.float64)], plan


def load_rows(names=ROW_NAMES, settings: Settings | None = None
              ) -> tuple[list[Row], dict[str, str]]:
    """(the rows that load, {row: why skipped})."""
    unknown = [n for n in names if n not in ROW_NAMES]
    if unknown:
        raise ValueError(f"unknown row(s) {unknown}; expected some of {', '.join(ROW_NAMES)}")
    router = load_generator(settings)
    rows, skipped = [], {}
    for name in names:
        if name == "retrieval":
            rows.append(Row(name, (1, 2), _plain(router.retrieval),
                            "retrieval alone over the processed captures", router))
        elif name == "retrieve_edit":
            rows.append(Row(name, (1, 2), _plain(RetrieveEditGenerator(router.index)),
                            "retrieval + arm actions by IK + floor pass", router))
        elif name == "compose":
            rows.append(Row(name, (2,), _plain(InteractionGenerator(router.index)),
                            "interaction by composition alone (two people)", router))
        elif name == "spam":
            if router.spam is None:
                skipped[name] = router.reason or "SPAM is not loaded"
                continue
            rows.append(Row(name, (1,), _plain(SpamGenerator(router.spam)), "SPAM alone", router))
        elif name == "coda":
            if router.coda is None:
                skipped[name] = router.coda_reason or "CODA is not loaded"
                continue
            rows.append(Row(name, (2,), _plain(CodaGenerator(router.coda)), "CODA alone", router))
        else:
            rows.append(Row(name, (1, 2), _pipeline(router),
                            "the router (retrieve_edit) through plan → generate → review → "
                            "trajectory", router))
    return rows, skipped
