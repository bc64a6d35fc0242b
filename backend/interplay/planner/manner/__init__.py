"""How a step is done: held poses kept as "holds …" part edits (`holds`) and the direction of travel relative to facing (`travel`)."""
