"""ARFlow (action → reaction flow matching, x-prediction, causal transformer decoder),
trained with torch and exported to ONNX for the numpy/onnxruntime runtime
(`interplay.reaction.session`)."""

import os

# Passive OpenMP waiting: far faster on a CPU shared with other processes (see models.spam).
os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
