"""SPAM at run time (CoMA §4.2, numpy + onnxruntime): text → part tokens → joints, and the three
token-level edits (body part, in-between, blend).

    rt = SpamRuntime.load("models/weights/spam")
    joints = rt.generate("a person walks forward", frames=120, seed=3)           # (120, 22, 3)
    joints = rt.generate({"global": "a person walks", "left_arm": "waves"}, 120, seed=3)
    edited = rt.edit_parts(joints, ["left_upper"], "raises the left arm", seed=4)
    fixed = rt.inbetween(joints, 40, 80, "a person jumps", seed=5)
    joined = rt.blend(a, b, transition_frames=16, prompt="a person turns", seed=6)

Tokens: one per part (PART_NAMES order) per `downsample` (4) frames; base layer (4, n) plus
residual layers (4, Q, n). Generation is MoMask's: the base layer by masked decoding (cosine
schedule, Gumbel sampling, CFG with the conditional and unconditional passes run side by side
on twin one-thread sessions, `guided_pair`), the residual layers (CFG batched) greedily one by one, then `vq_decode` → denormalise → `features.decode` (joints
by forward kinematics on fixed bones, starting at the origin facing +Z). Motions longer than the
transformers' range (`max_tokens`, 10 s) are generated as pieces joined by blended transitions
(`spam_sequence`). Edits re-mask tokens of the input's own code sequence and keep everything
outside the edit from the input (`spam_edits`, `motion_splice`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from pathlib import Path
from typing import cast

import numpy as np

from interplay.generators import masked_decoding as md
from interplay.generators.spam.cfg_sessions import GuidedPair
from interplay.generators.spam.edits import (
    Edit,
    blend,
    edit,
    transition_codes,
)  # noqa: F401
from interplay.generators.spam.files import SpamConfig, load_files
from interplay.generators.spam.sequence import Assembler, layout
from interplay.generators.spam.splice import seam_corrected
from interplay.motion import skeleton as sk
from interplay.settings import REPO_ROOT

DEFAULT_DIR = REPO_ROOT / "models" / "weights" / "spam"
PARTS = sk.PART_NAMES
GLOBAL_KEYS = ("global", "body", "whole_body", "all")
Texts = str | Mapping[str, str]


def part_texts(texts: Texts) -> list[str]:
    """The four part prompts: one string for all parts, or {part or alias or "global": text}
    where parts without their own prompt get the global one."""
    if isinstance(texts, str):
        if not texts.strip():
            raise ValueError("the prompt is empty")
        return [texts.strip()] * len(PARTS)
    if not isinstance(texts, Mapping):
        raise ValueError(f"texts must be a string or a dict of part prompts, got {type(texts).__name__}")
    glob, per = None, {}
    for key, text in texts.items():
        if not isinstance(text, str) or not text.strip():
            raise ValueError(f"prompt for {key!r} is empty")
        if key.strip().lower() in GLOBAL_KEYS:
            glob = text.strip()
        else:
            per[sk.resolve_part(key)] = text.strip()
    if glob is None and len(per) < len(PARTS):
        missing = [p for p in PARTS if p not in per]
        raise ValueError(f"no prompt for {missing}: give a 'global' prompt for the other parts")
    # glob is set whenever a part has no prompt of its own (checked above)
    return [per[p] if p in per else cast(str, glob) for p in PARTS]


class SpamRuntime:
    def __init__(self, config: SpamConfig, normalizer, graphs: Mapping, encoder=None,
                 foot_lock: bool = True, pairs: Mapping[str, GuidedPair] | None = None):
        self.config, self.normalizer, self.graphs = config, normalizer, graphs
        # Transformers whose guided passes run side by side (`guided_pair`); the others batch
        # the conditional and unconditional passes into one call.
        self.pairs = dict(pairs or {})
        self._blank: dict[int, np.ndarray] = {}    # n → unconditional logits of all-[MASK]
        self._encoder = encoder
        # Generated bodies hover and their planted feet slide (floating and foot skating in
        # docs/eval.md): generation puts each stretch on the floor and holds planted feet with
        # leg IK (`footlock.ground`, `footlock.lock_feet`); edits keep the input's legs.
        self.foot_lock = foot_lock

    @classmethod
    def load(cls, weights_dir: str | Path = DEFAULT_DIR, encoder=None, threads: int = 1,
             precision: str | None = None, foot_lock: bool = True,
             parallel_cfg: bool = True) -> "SpamRuntime":
        """Sessions built once; the graphs are run once on a tiny input so a broken export
        fails here (ValueError / FileNotFoundError), not on the first request. precision:
        "fp32" | "int8" transformers (None: what config.json ships). threads: intra-op threads
        per session; parallel_cfg: the base transformer also gets a twin session and its guided
        steps run their two passes concurrently (docs/bench.md: one thread per session and the
        passes side by side is the fastest of the layouts measured on the 2-core CPU)."""
        config, normalizer, graphs = load_files(weights_dir, threads, precision)
        # Only the base transformer: with int8 weights each session quantizes its own
        # activations, so the two passes' rounding no longer cancels in cond − uncond, and the
        # residual layers' guidance (scale 5) amplified that into jitter (test split, 2 repeats:
        # foot skating 0.071 batched, 0.077 base side by side, 0.092 both; docs/bench.md).
        pairs = {"base": GuidedPair(graphs["base"])} if parallel_cfg else {}
        runtime = cls(config, normalizer, graphs, encoder, foot_lock, pairs)
        runtime.check()
        return runtime

    # -- graphs ------------------------------------------------------------------------------
    def check(self) -> None:
        c, n = self.config, 2
        codes = np.zeros((1, 4, c.Q, n), dtype=np.int64)
        shapes = {
            "vq_decode": (self.graphs["vq_decode"](codes=codes).shape, (1, n * c.downsample, c.feature_dim)),
            "vq_encode": (self.graphs["vq_encode"](motion=np.zeros(
                (1, n * c.downsample, c.feature_dim), np.float32)).shape, (1, 4, c.Q, n)),
            "base": (self._base(codes[:, :, 0], np.zeros((1, 4, c.text_dim), np.float32),
                                np.ones(1, np.float32)).shape, (1, 4, n, c.K)),
        }
        if c.Q > 1:
            shapes["residual"] = (self._residual(codes, 1, np.zeros((1, 4, c.text_dim), np.float32),
                                                 np.ones(1, np.float32)).shape, (1, 4, n, c.K))
        for name, (got, want) in shapes.items():
            if tuple(got) != want:
                raise ValueError(f"{name} graph gives shape {tuple(got)}, the contract says {want}")

    @staticmethod
    def _base_feeds(tokens, text, cond) -> dict[str, np.ndarray]:
        return {"tokens": tokens.astype(np.int64), "text": text, "cond": cond}

    @staticmethod
    def _residual_feeds(codes, layer: int, text, cond) -> dict[str, np.ndarray]:
        return {"tokens": codes.astype(np.int64), "text": text, "cond": cond,
                "layer": np.full(codes.shape[0], layer, dtype=np.int64)}

    def _base(self, tokens, text, cond) -> np.ndarray:
        return self.graphs["base"](**self._base_feeds(tokens, text, cond))

    def _residual(self, codes, layer: int, text, cond) -> np.ndarray:
        return self.graphs["residual"](**self._residual_feeds(codes, layer, text, cond))

    def _guided(self, name: str, text: np.ndarray, scale: float):
        """`fn(tokens, *extra) -> logits (4, n, K)` of transformer `name` ("base" or
        "residual", extra = (layer,)) with classifier-free guidance: the conditional and
        unconditional passes side by side (`self.pairs`) or as one batch of two; only the
        conditional pass when scale = 1."""
        feeds: Callable[..., dict[str, np.ndarray]] = (
            self._base_feeds if name == "base" else self._residual_feeds)
        graph, pair = self.graphs[name], self.pairs.get(name)
        one, zero = np.ones(1, np.float32), np.zeros(1, np.float32)
        if scale == 1.0:
            def cond_only(tokens, *extra):
                return graph(**feeds(tokens[None], *extra, text[None], one))[0]
            return cond_only
        if pair is not None:
            def side_by_side(tokens, *extra):
                first = feeds(tokens[None], *extra, text[None], one)
                if name == "base" and (tokens == self.config.mask_id).all():
                    return md.guided(graph(**first)[0], self._blank_uncond(pair, tokens.shape[-1]),
                                     scale)
                cond, uncond = pair.both(first, feeds(tokens[None], *extra, text[None], zero))
                return md.guided(cond[0], uncond[0], scale)
            return side_by_side

        def batched(tokens, *extra):
            out = graph(**feeds(np.stack([tokens, tokens]), *extra, np.stack([text, text]),
                                np.array([1.0, 0.0], np.float32)))
            return md.guided(out[0], out[1], scale)
        return batched

    def _blank_uncond(self, pair: GuidedPair, n: int) -> np.ndarray:
        """Unconditional base logits (4, n, K) of n all-[MASK] steps: the unconditional pass
        sees no text, so generation's first step is the same for every prompt and needs only
        its conditional pass (kept per n, computed on the twin session as `both` would)."""
        got = self._blank.get(n)
        if got is None:
            tokens = np.full((1, len(PARTS), n), self.config.mask_id, np.int64)
            text = np.zeros((1, len(PARTS), self.config.text_dim), np.float32)
            got = self._blank[n] = pair.twin(**self._base_feeds(tokens, text,
                                                                np.zeros(1, np.float32)))[0]
        return got

    # -- text and codes ----------------------------------------------------------------------
    @property
    def encoder(self):
        if self._encoder is None:
            from interplay.text.encoder import get_encoder
            self._encoder = get_encoder()
        return self._encoder

    def text_embedding(self, texts: Texts) -> np.ndarray:
        """(4, 384) float32: each part's prompt embedding."""
        return self.encoder.encode(part_texts(texts)).astype(np.float32)

    def tokens_for(self, frames: int) -> int:
        return -(-int(frames) // self.config.downsample)

    def encode_codes(self, feats: np.ndarray) -> np.ndarray:
        """Codes (4, Q, ⌈T/4⌉) of features (T, 239) (not normalised; the last frame is repeated
        to fill the last token)."""
        t, ds = feats.shape[0], self.config.downsample
        pad = self.tokens_for(t) * ds - t
        x = self.normalizer.normalize(np.concatenate([feats, np.repeat(feats[-1:], pad, 0)]))
        return self.graphs["vq_encode"](motion=x[None].astype(np.float32))[0].astype(np.int64)

    def decode_codes(self, codes: np.ndarray) -> np.ndarray:
        """Features (4n, 239), denormalised, of codes (4, Q, n)."""
        out = self.graphs["vq_decode"](codes=np.asarray(codes, np.int64)[None])[0]
        return self.normalizer.denormalize(out).astype(np.float64)

    def fill(self, codes: np.ndarray, editable: np.ndarray, text: np.ndarray,
             rng: np.random.Generator, force: np.ndarray | None = None, cfg: float | None = None,
             steps: int | None = None, temperature: float | None = None,
             cfg_residual: float | None = None) -> np.ndarray:
        """Codes (4, Q, n) with the `editable` (4, n) base tokens re-decoded by masked decoding
        and residual tokens predicted again where the base token changed or `force` (default:
        everywhere editable). Sequences longer than max_tokens go window by window."""
        c = self.config
        cfg = c.cfg if cfg is None else cfg
        steps = c.steps if steps is None else steps
        temperature = c.temperature if temperature is None else temperature
        out = np.asarray(codes, dtype=np.int64).copy()
        editable = np.asarray(editable, dtype=bool)
        force = editable if force is None else (np.asarray(force, dtype=bool) & editable)
        base_fn = self._guided("base", text, cfg)
        res_fn = self._guided("residual", text, c.cfg_residual if cfg_residual is None
                              else cfg_residual)
        windows = md.token_windows(editable, c.max_tokens)
        before = out[:, 0].copy()
        for lo, elo, ehi, hi in windows:
            mask = np.zeros_like(editable)
            mask[:, elo:ehi] = editable[:, elo:ehi]
            out[:, 0, lo:hi] = md.fill_base(out[:, 0, lo:hi], mask[:, lo:hi], base_fn, c.mask_id,
                                            steps, rng, temperature, c.topk_ratio)
        redo = editable & ((out[:, 0] != before) | force)
        for lo, elo, ehi, hi in windows:
            mask = np.zeros_like(redo)
            mask[:, elo:ehi] = redo[:, elo:ehi]
            out[:, :, lo:hi] = md.fill_residual(out[:, :, lo:hi], mask[:, lo:hi],
                                                res_fn)
        return out

    # -- generation --------------------------------------------------------------------------
    def generate_codes(self, texts: Texts, tokens: int, rng: np.random.Generator, **kw
                       ) -> np.ndarray:
        """Codes (4, Q, tokens) of a new motion, tokens ≤ max_tokens."""
        if not 1 <= tokens <= self.config.max_tokens:
            raise ValueError(f"one piece is 1–{self.config.max_tokens} tokens, got {tokens}")
        codes = np.zeros((len(PARTS), self.config.Q, tokens), dtype=np.int64)
        return self.fill(codes, np.ones((len(PARTS), tokens), bool), self.text_embedding(texts),
                         rng, **kw)

    def stream(self, segments: list[tuple[Texts, int]], seed: int, **kw
               ) -> Iterator[tuple[int, np.ndarray]]:
        """(start frame, joints (n, 22, 3)) for consecutive segments [(texts, frames), …], in
        order, exactly sum(frames) frames; pieces ≤ 10 s joined by blended transitions; each
        piece's frames are yielded as soon as they are final."""
        pieces = layout([f for _, f in segments], self.config.max_tokens, self.config.downsample)
        rng = np.random.default_rng(seed)
        total = sum(int(f) for _, f in segments)
        out = Assembler(total, lock=self.foot_lock)
        prev = None
        for piece in pieces:
            texts = segments[piece.segment][0]
            codes = self.generate_codes(texts, piece.tokens, rng, **kw)
            feats = self.decode_codes(codes)
            if prev is not None and piece.transition > 0:
                window, ca = transition_codes(self, prev[0], codes, piece.transition, texts,
                                              rng, **kw)
                w = self.decode_codes(window)
                ds = self.config.downsample
                a, b = ca * ds, (ca + piece.transition) * ds
                mid = seam_corrected(w[a:b], prev[1][-1] - w[a - 1] if a else 0 * w[0],
                                     feats[0] - w[b] if b < len(w) else 0 * w[0])
                yield from out.add(mid)
            yield from out.add(feats)
            prev = (codes, feats)

    def generate(self, texts: Texts, frames: int, seed: int, cfg: float | None = None,
                 steps: int | None = None, temperature: float | None = None,
                 cfg_residual: float | None = None) -> np.ndarray:
        """Joints (frames, 22, 3) float64 for one global prompt or per-part prompts."""
        if not isinstance(frames, (int, np.integer)) or frames < 1:
            raise ValueError(f"frames must be a positive integer, got {frames!r}")
        part_texts(texts)  # validate before any model call
        chunks = [c for _, c in self.stream([(texts, int(frames))], seed, cfg=cfg, steps=steps,
                                            temperature=temperature, cfg_residual=cfg_residual)]
        return np.concatenate(chunks)

    # -- edits (spam_edits) ---------------------------------------------------------------
    def edit(self, joints: np.ndarray, parts: list[str] | None, prompt: str, seed: int,
             frames: tuple[int, int] | None = None, context: str | None = None,
             keep_noise: float = 0.1, **sampling) -> Edit:
        """`parts` (None: whole body) over `frames` re-generated; see `spam_edits.edit`."""
        return edit(self, joints, parts, prompt, seed, frames, context, keep_noise, **sampling)

    def edit_parts(self, joints: np.ndarray, parts: list[str], prompt: str, seed: int,
                   keep_noise: float = 0.1, cfg: float | None = None, **kw) -> np.ndarray:
        """Joints with `parts` re-generated from `prompt`, the rest kept."""
        return edit(self, joints, parts, prompt, seed, keep_noise=keep_noise, cfg=cfg, **kw).joints

    def inbetween(self, joints: np.ndarray, start: int, end: int, prompt: str, seed: int, **kw
                  ) -> np.ndarray:
        """Joints with frames [start, end) re-generated for the whole body, the rest kept."""
        return edit(self, joints, None, prompt, seed, frames=(start, end), **kw).joints

    def blend(self, a_joints: np.ndarray, b_joints: np.ndarray, transition_frames: int,
              prompt: str, seed: int, **sampling) -> np.ndarray:
        """a + `transition_frames` new frames + b; see `spam_edits.blend`."""
        return blend(self, a_joints, b_joints, transition_frames, prompt, seed, **sampling)
