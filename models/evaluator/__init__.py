"""TMR-style text–motion evaluator: a motion encoder over the 239-d features and a projection
of the frozen MiniLM text embeddings into one 256-d space, trained with InfoNCE. Training and
export need torch; the runtime (`interplay.review.evaluator`) is numpy + onnxruntime."""
