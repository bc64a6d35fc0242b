"""The planner stage: a prompt → a Plan of timed segments (base motion, part edits, trajectory), embedded by default, an OpenAI-compatible LLM optionally. Entry: `planner.plan.plan`."""
