"""What the model packages share: checkpoints that carry their config (`checkpoint`), ONNX
export and its check against torch (`onnx_export`), training budgets and learning-rate
schedules (`schedule`), and the contrastive loss of the evaluators (`contrastive`)."""
