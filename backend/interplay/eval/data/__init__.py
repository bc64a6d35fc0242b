"""Prompt sets the measurements run on. `table8_prompts.json`: CoMA's 40 challenging prompts
(Table 8) with the paper's labels (segment counts, part edits, trajectories, context).
`prompts.json`: the suite of `interplay eval-prompts` (`interplay.eval.prompts.suite`)."""

from pathlib import Path

TABLE8 = Path(__file__).parent / "table8_prompts.json"
