"""ONNX export of one torch module with named inputs and outputs and dynamic axes, and the
check of an exported file against torch; every model package writes its graphs with these
(TorchScript exporter, opset 17, which onnxruntime on the server runs)."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import torch
import torch.nn as nn

OPSET = 17


def export_graph(module: nn.Module, inputs: tuple, path: str | Path, input_names: list[str],
                 output_names: list[str], dynamic_axes: dict, opset: int = OPSET) -> Path:
    """module (put in eval mode) traced on `inputs` and written to path, without gradients
    and with the exporter's tracing warnings silenced."""
    with torch.no_grad(), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        torch.onnx.export(module.eval(), inputs, str(path), input_names=input_names,
                          output_names=output_names, dynamic_axes=dynamic_axes,
                          opset_version=opset, dynamo=False)
    return Path(path)


def max_error(module: nn.Module, inputs: tuple, path: str | Path) -> float:
    """Largest |onnxruntime − torch| over the outputs of the graph at path and of module (eval
    mode) on the same inputs (in the graph's input order); for integer outputs, the share of
    entries that differ."""
    import onnxruntime as ort

    sess = ort.InferenceSession(str(path), providers=["CPUExecutionProvider"])
    got = sess.run(None, {i.name: t.numpy() for i, t in zip(sess.get_inputs(), inputs)})
    with torch.no_grad():
        want = module.eval()(*inputs)
    want = want if isinstance(want, tuple) else (want,)
    worst = 0.0
    for g, w in zip(got, want):
        if g.dtype == np.int64:
            worst = max(worst, float((g != w.numpy()).mean()))
        else:
            worst = max(worst, float(np.abs(g - w.numpy()).max()))
    return worst
