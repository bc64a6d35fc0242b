"""Interplay: text to 3D human motion for one or two people, on CPU."""

__version__ = "0.1.0"
