"""The review stage: captions, text–motion scores and commonsense checks per segment, and the corrections they ask for."""
