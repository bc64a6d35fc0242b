"""`interplay eval-prompts`: a benchmark of what users type. `suite` loads the committed prompts
(`eval/data/prompts.json`: categories, dev and test splits, each prompt's persons, seconds and
checks), `rows` the generators compared (retrieval, SPAM, CODA, the product default through the
studio's pipeline), `report` runs every row on every prompt it can serve over seeds, judges
each output with `interplay.motion.checks` and writes the results and the motions."""
