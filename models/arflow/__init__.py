"""ARFlow (action → reaction flow matching, x-prediction, causal transformer decoder),
trained with torch and exported to ONNX for the numpy/onnxruntime runtime
(`interplay.reaction.session`)."""
