"""SPAM (CoMA §4.2): body-part residual VQ-VAE + masked base/residual transformers, trained
with torch and exported to ONNX for the numpy/onnxruntime runtime."""
