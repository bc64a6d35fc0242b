"""Text-to-motion evaluation (Guo et al. 2022 / MoMask protocol) with the project's TMR-style
evaluator: the test set (`testset`), the metric maths (`metrics`), the rows to compare
(`rows`), part-edit fidelity (`edits`) and the report behind `interplay eval` (`report`)."""
