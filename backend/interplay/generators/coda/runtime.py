"""CODA at run time (paper 000 §3.3, numpy + onnxruntime): text → both people's motion tokens by
iterative masked decoding → joints of the pair.

    rt = CodaRuntime.load("models/weights/coda")
    pair = rt.generate("two people shake hands", seconds=6, seed=3)     # (2, 120, 22, 3) world
    for start, people in rt.stream([("two people hug", 80), ("they wave", 60)], seed=1):
        ...                                                             # people (2, n, 22, 3)

Tokens: one per person per `downsample` (4) frames, laid out (2, n) (row 0 the first person).
Each window starts fully masked (after its context tokens); every step the masked-token
transformer (`cmt`) predicts all positions of both people at once, tokens are drawn (Gumbel,
top-k, temperature), and the least confident are masked again on the cosine schedule
(`masked_decoding.fill_base`). Classifier-free guidance batches the conditional pass (MiniLM
text) with the unconditional one (zero text). `decode` turns both token rows into normalised
joints with the interaction codebook's residual added inside the graph.

Windows and frames: the model sees the pair in its canonical frame (the first person's pelvis
at the XZ origin facing +Z on the window's first frame). Motions longer than one window, and
every plan segment after the first, are generated window by window (`window_tokens`, the
length the transformer was trained at): the last `CONTEXT` tokens'
frames of what is already made are moved into their own canonical frame and re-encoded
(`encode`), kept fixed as context, and the rest of the window is decoded after them, so each
window continues the motion (and a new segment its predecessor's tail) under its own text.
The decoder's edge tokens are dropped: one before the motion's first kept frame and one after
each window's last kept frame (the next window re-makes those frames with context). Decoded
frames are moved back to the world; at a seam each person's ground offset to the frame before
moves the whole new window and the rest of the difference fades out over `SEAM` frames; bones
are put back on fixed lengths (`kinematics.fit_to_skeleton`, each person's offsets fitted once
on the first window) and the floor is put at y = 0.
"""

from __future__ import annotations

from pathlib import Path
from typing import Iterator

import numpy as np

from interplay.generators import masked_decoding as md
from interplay.generators.coda.files import DEFAULT_DIR, CodaConfig, Normalizer, load_files
from interplay.motion import skeleton as sk
from interplay.motion.kinematics import facing_angle, fit_offsets, fit_to_skeleton, floor_height
from interplay.motion.rotations import yaw_matrix

CONTEXT = 5      # tokens (1 s) of the motion so far that a following window sees
SEAM = 8         # frames over which a window's offset to the previous frame fades out
CHUNK = 40       # frames per streamed chunk at most


def canonical_transform(first_pose: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(rot (3, 3), shift (3,)) taking world points p to the canonical frame rot·p + shift of
    the first person's pose (22, 3): pelvis at the XZ origin facing +Z, heights kept."""
    rot = yaw_matrix(-facing_angle(first_pose))
    shift = -(rot @ first_pose[sk.PELVIS])
    shift[1] = 0.0
    return rot, shift


class CodaRuntime:
    def __init__(self, config: CodaConfig, normalizer: Normalizer, graphs: dict, encoder=None):
        self.config, self.normalizer, self.graphs = config, normalizer, graphs
        self._encoder = encoder

    @classmethod
    def load(cls, weights_dir: str | Path = DEFAULT_DIR, encoder=None, threads: int = 2
             ) -> "CodaRuntime":
        """Sessions built once and run on a tiny input, so a broken export fails here."""
        config, normalizer, graphs = load_files(weights_dir, threads)
        rt = cls(config, normalizer, graphs, encoder)
        rt.check()
        return rt

    # -- graphs ------------------------------------------------------------------------------
    def check(self) -> None:
        c, n = self.config, 2
        got = {
            "encode": self.graphs["encode"](x=np.zeros((1, n * c.downsample, c.dim), np.float32)).shape,
            "decode": self._decode_raw(np.zeros((1, n), np.int64), np.zeros((1, n), np.int64))[0].shape,
            "cmt": self.graphs["cmt"](codes=np.full((1, 2, n), c.mask_id, np.int64),
                                      text=np.zeros((1, 384), np.float32)).shape,
        }
        want = {"encode": (1, n), "decode": (1, n * c.downsample, c.dim), "cmt": (1, 2, n, c.codes)}
        for name in want:
            if tuple(got[name]) != want[name]:
                raise ValueError(f"CODA {name} graph gives shape {tuple(got[name])}, the "
                                 f"contract says {want[name]}")

    def _decode_raw(self, a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        g = self.graphs["decode"]
        out = g.session.run(None, {"codes_a": a.astype(np.int64), "codes_b": b.astype(np.int64)})
        names = [o.name for o in g.session.get_outputs()]
        return (out[names.index("x_a")], out[names.index("x_b")]) if "x_a" in names else tuple(out[:2])

    @property
    def encoder(self):
        if self._encoder is None:
            from interplay.text.encoder import get_encoder
            self._encoder = get_encoder()
        return self._encoder

    def text_embedding(self, prompt: str) -> np.ndarray:
        """(384,) float32 MiniLM embedding; zeros (unconditional) for an empty prompt."""
        if not isinstance(prompt, str):
            raise ValueError(f"the prompt must be a string, got {type(prompt).__name__}")
        if not prompt.strip():
            return np.zeros(384, np.float32)
        return np.asarray(self.encoder.encode([prompt.strip()])[0], np.float32)

    def encode(self, pair: np.ndarray) -> np.ndarray:
        """Codes (2, T/4) of a pair (2, T, 22, 3) in its canonical frame (T a multiple of 4)."""
        pair = np.asarray(pair, np.float64)
        if pair.ndim != 4 or pair.shape[0] != 2 or pair.shape[1] % self.config.downsample:
            raise ValueError(f"encode takes (2, 4k, 22, 3) joints, got {pair.shape}")
        return self.graphs["encode"](x=self.normalizer.normalize(pair)).astype(np.int64)

    def decode(self, codes: np.ndarray) -> np.ndarray:
        """Joints (2, 4n, 22, 3) float64 in the canonical frame of codes (2, n)."""
        codes = np.asarray(codes, np.int64)
        xa, xb = self._decode_raw(codes[0:1], codes[1:2])
        return self.normalizer.denormalize(np.concatenate([xa, xb]))

    def logits_fn(self, text: np.ndarray, cfg: float):
        """tokens (2, n) → guided logits (2, n, K): the conditional and unconditional passes
        as one batch of two (the conditional pass alone when cfg = 1)."""
        cmt = self.graphs["cmt"]
        if cfg == 1.0:
            return lambda tokens: cmt(codes=tokens[None].astype(np.int64), text=text[None])[0]
        texts = np.stack([text, np.zeros_like(text)]).astype(np.float32)

        def fn(tokens):
            out = cmt(codes=np.stack([tokens, tokens]).astype(np.int64), text=texts)
            return md.guided(out[0], out[1], cfg)
        return fn

    def fill(self, codes: np.ndarray, editable: np.ndarray, text: np.ndarray,
             rng: np.random.Generator, steps: int | None = None, cfg: float | None = None,
             temperature: float | None = None) -> np.ndarray:
        """Codes (2, n ≤ max_tokens) with the `editable` positions decoded by iterative masked
        decoding; the others are context, passed as given and kept."""
        c = self.config
        if codes.shape[-1] > c.max_tokens:
            raise ValueError(f"one window is at most {c.max_tokens} tokens, got {codes.shape[-1]}")
        return md.fill_base(codes, editable, self.logits_fn(text, c.cfg if cfg is None else cfg),
                            c.mask_id, c.steps if steps is None else steps, rng,
                            c.temperature if temperature is None else temperature, c.topk_ratio)

    # -- generation --------------------------------------------------------------------------
    def stream(self, segments: list[tuple[str, int]], seed: int, **sampling
               ) -> Iterator[tuple[int, np.ndarray]]:
        """(start frame, joints (2, n ≤ 40, 22, 3) world) for consecutive segments
        [(prompt, frames), …], in order, exactly sum(frames) frames; later windows continue
        from the last CONTEXT tokens of the frames before them (see the module doc)."""
        c, ds = self.config, self.config.downsample
        for text, frames in segments:
            if not isinstance(frames, (int, np.integer)) or frames < 1:
                raise ValueError(f"segment frames must be positive integers, got {frames!r}")
            self.text_embedding(text)                      # validate before any model call
        rng = np.random.default_rng(seed)
        hist = np.zeros((2, 0, sk.NUM_JOINTS, 3))
        offsets = None
        for text, frames in segments:
            emb, left = self.text_embedding(text), int(frames)
            while left > 0:
                ctx = min(CONTEXT, hist.shape[1] // ds, c.window_tokens // 2)
                if ctx:
                    past = hist[:, hist.shape[1] - ctx * ds:]
                    rot, shift = canonical_transform(past[0, 0])
                    ctx_codes = self.encode(past @ rot.T + shift)
                else:
                    rot, shift, ctx_codes = np.eye(3), np.zeros(3), np.zeros((2, 0), np.int64)
                # Edge tokens: the decoder's first and last frames of a window are its worst,
                # so the motion's first window makes one token before the kept frames, and
                # every window one after them; both are dropped (a later window re-makes the
                # frames after a dropped last token with context).
                lead = 0 if ctx else 1
                new = min(-(-left // ds) + lead + 1, c.window_tokens - ctx)
                codes = np.concatenate([ctx_codes, np.zeros((2, new), np.int64)], axis=1)
                editable = np.zeros(codes.shape, bool)
                editable[:, ctx:] = True
                codes = self.fill(codes, editable, emb, rng, **sampling)
                world = (self.decode(codes) - shift) @ rot          # rot is orthonormal
                keep = min(left, (new - lead - 1) * ds)
                out = world[:, (ctx + lead) * ds:(ctx + lead) * ds + keep]
                if ctx:
                    fade = np.clip(1.0 - np.arange(1, keep + 1) / (SEAM + 1), 0.0, None)
                    jump = hist[:, -1] - world[:, ctx * ds - 1]                 # (2, 22, 3)
                    # Where each person stands drifts in the decoded context (the window's
                    # absolute positions): that ground offset moves the whole new window, so
                    # its velocities are kept; the rest of the difference (pose) fades out.
                    ground = jump[:, sk.PELVIS] * np.array([1.0, 0.0, 1.0])       # (2, 3)
                    out = (out + ground[:, None, None]
                           + (jump - ground[:, None])[:, None] * fade[None, :, None, None])
                if offsets is None:
                    offsets = [fit_offsets(p) for p in out]
                out = np.stack([fit_to_skeleton(p, o)[0] for p, o in zip(out, offsets)])
                if hist.shape[1] == 0:                  # the floor at y = 0, once
                    out[..., 1] -= floor_height(list(out))
                # a frame whose lowest joint sinks below the floor (the decoder's window edge
                # does, by up to ~0.1 m) is lifted onto it
                out[..., 1] -= np.minimum(out[..., 1].min(axis=2), 0.0)[..., None]
                start = hist.shape[1]
                hist = np.concatenate([hist, out], axis=1)
                for a in range(0, keep, CHUNK):
                    yield start + a, out[:, a:a + CHUNK]
                left -= keep

    def generate(self, prompt: str, seconds: float, seed: int, **sampling) -> np.ndarray:
        """Joints (2, round(seconds·20), 22, 3) float64 of both people, world frame."""
        if not isinstance(seconds, (int, float)) or not 0 < seconds <= 60:
            raise ValueError(f"seconds must be in (0, 60], got {seconds!r}")
        frames = max(1, round(seconds * sk.FPS))
        return np.concatenate([c for _, c in self.stream([(prompt, frames)], seed, **sampling)],
                              axis=1)
