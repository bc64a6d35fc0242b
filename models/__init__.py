"""Training code (torch) of Interplay's models; the server only reads their ONNX exports.

Every model command (`python -m models.<name>`, `python -m models.train_all`) imports this
package first, before torch: OpenMP threads that spin while waiting are ~10× slower than
passive ones on a CPU shared with other processes (measured: 13 s vs 0.7 s per SPAM VQ step on
2 busy cores), and the policy only takes effect when set before torch is first imported."""

import os

os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
