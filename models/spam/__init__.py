"""SPAM (CoMA §4.2): body-part residual VQ-VAE + masked base/residual transformers, trained
with torch and exported to ONNX for the numpy/onnxruntime runtime."""

import os

# OpenMP threads that spin while waiting are ~10× slower than passive ones on a CPU shared
# with other processes (measured: 13 s vs 0.7 s per VQ step on 2 busy cores). Only effective
# when set before torch is first imported.
os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
