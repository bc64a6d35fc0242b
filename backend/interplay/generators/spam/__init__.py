"""SPAM at run time: body-part masked token models over ONNX, generation and part/in-between edits."""
