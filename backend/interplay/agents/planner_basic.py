"""Deprecated name of the planner's JSON entry point, kept so callers written against the first
rule-based planner keep working: `basic_plan` is now `planner.plan_json` (the embedded
planner, or the configured LLM). New code imports `interplay.agents.planner`."""

from __future__ import annotations

from .planner import plan_json


def basic_plan(prompt: str, persons: int = 1, seconds: float = 6.0) -> dict:
    """The plan JSON for a prompt (see planner.plan)."""
    return plan_json(prompt, persons, seconds)
