"""Retrieval: captured windows found by text, cut and stitched into one continuous motion."""
