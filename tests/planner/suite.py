"""The eval-prompts suite's dev prompts for the planner tests (the test split is the benchmark:
never tuned on, so never read here)."""

import json

from interplay.eval.data import TABLE8
from interplay.planner.plan import embedded_plan
from interplay.planner.vocabulary import load_vocabulary

SUITE = {p["id"]: p for p in json.loads((TABLE8.parent / "prompts.json").read_text())["prompts"]}


def dev(prompt_id: str) -> dict:
    item = SUITE[prompt_id]
    assert item["split"] == "dev", f"{prompt_id} is in the {item['split']} split"
    return item


def plan_of(prompt_id: str):
    """The embedded plan of a dev prompt, with its persons and seconds."""
    item = dev(prompt_id)
    return embedded_plan(item["prompt"], item["persons"], item["seconds"], load_vocabulary)
