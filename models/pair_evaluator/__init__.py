"""Text ↔ two-person-motion evaluator (contrastive, TMR-style): torch training and export.
The runtime is `interplay.review.pair_evaluator` (numpy + onnxruntime)."""
