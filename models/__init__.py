"""Training code (torch) of Interplay's models; the server only reads their ONNX exports."""
