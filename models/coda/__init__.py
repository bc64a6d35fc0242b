"""CODA (paper 000, §3.1–3.3): a two-person CVQ-VAE with an interaction codebook (ICS) and
commonsense losses (CCL), and a conditional masked transformer (CMT) over both people's
pose tokens; trained with torch on CPU, exported to ONNX for `interplay.agents`."""
