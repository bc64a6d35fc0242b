"""Classifier-free guidance's two passes side by side on a 2-core CPU.

A guided step needs the transformer twice on the same tokens: with the prompt and without it.
Batched (B = 2, one session, two intra-op threads) the two passes share one graph call, but at
SPAM's sizes (≈124 tokens, d = 128) onnxruntime's intra-op threads mostly wait on each other
(measured on this machine, one base step: 9.3 ms batched on one thread, 8.4 ms on two, 6.9 ms
as two one-thread sessions run concurrently). So SPAM's base transformer gets a twin session
and the unconditional pass runs on a worker thread while the conditional one runs on the
caller's (onnxruntime releases the GIL while it computes). Not the residual transformer: with
int8 weights each session quantizes its own activations, and at guidance scale 5 the passes'
uncorrelated rounding showed as jitter (see `SpamRuntime.load`).

    pair = GuidedPair(graph)                    # graph: an OnnxGraph of one transformer
    cond, uncond = pair.both(cond_feeds, uncond_feeds)
"""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor

import numpy as np

from interplay.generators.spam.files import OnnxGraph


class GuidedPair:
    """Two one-thread sessions of the same graph; `both` runs two feeds concurrently. Safe to
    call from several threads at once (concurrent jobs queue on the one worker)."""

    def __init__(self, graph: OnnxGraph):
        self.main = graph
        self.twin = OnnxGraph(graph.path, graph.inputs, threads=1)
        self._pool = ThreadPoolExecutor(max_workers=1, thread_name_prefix="cfg-uncond")

    def both(self, first: dict[str, np.ndarray], second: dict[str, np.ndarray]
             ) -> tuple[np.ndarray, np.ndarray]:
        later = self._pool.submit(lambda: self.twin(**second))
        try:
            out = self.main(**first)
        finally:
            other = later.result()   # never leave the worker's result (or error) behind
        return out, other
