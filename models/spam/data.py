"""SPAM's training data: one feature track per person of every clip (salsa pairs give two
single-person tracks), left/right mirrored copies of the train tracks, their prompts and part
captions, cached in models/cache/ (gitignored) so only the first run pays for IK.

Mirroring happens on joints before encoding: x → -x and left_*/right_* joints swapped (the
offsets likewise); texts swap the words "left"/"right"; part captions swap sides.
"""

from __future__ import annotations

import hashlib
import json
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from interplay.motion import skeleton as sk
from interplay.motion.clip import DATA_DIR, Caption
from interplay.motion.features import Normalizer, encode
from models.common.sources import excluding_noncommercial, training_clips

from .config import PARTS

CACHE_DIR = Path(__file__).resolve().parents[1] / "cache"
CACHE_VERSION = 2

# Joint index of each joint's mirror image (left_* ↔ right_*).
MIRROR_JOINTS = np.array([
    sk.JOINT_INDEX[n.replace("left_", "§").replace("right_", "left_").replace("§", "right_")]
    for n in sk.JOINT_NAMES])
MIRROR_PART = {"left_upper": "right_upper", "right_upper": "left_upper",
               "left_lower": "right_lower", "right_lower": "left_lower", "body": "body"}


def mirror_joints(joints: np.ndarray) -> np.ndarray:
    """Joints or offsets (..., 22, 3) reflected through the YZ plane, left/right swapped."""
    out = np.array(joints[..., MIRROR_JOINTS, :], dtype=np.float64)
    out[..., 0] *= -1.0
    return out


def mirror_text(text: str) -> str:
    """Swap the words left and right (case kept)."""
    def sub(m: re.Match) -> str:
        w = m.group(0)
        r = "right" if w.lower() == "left" else "left"
        return r.capitalize() if w[0].isupper() else r
    return re.sub(r"\b(left|right)\b", sub, text, flags=re.IGNORECASE)


def person_prompt(prompt: str, people: int) -> str:
    """A clip's prompt said of one of its people ("two people dance salsa" → "a person
    dances salsa")."""
    if people == 1:
        return prompt
    m = re.match(r"^two people (\w+)(.*)$", prompt)
    if not m:
        return prompt
    verb = m.group(1)
    verb = verb + "es" if verb.endswith(("s", "sh", "ch", "x")) else verb + "s"
    return f"a person {verb}{m.group(2)}"


def person_captions(captions: list[Caption], person: int) -> list[Caption]:
    """The captions of one person: "person k: …" prefixed ones of that person (prefix
    stripped), unprefixed ones apply to everyone."""
    out = []
    for c in captions:
        m = re.match(r"^person (\d+): (.*)$", c.text)
        if m is None:
            out.append(c)
        elif int(m.group(1)) == person + 1:
            out.append(Caption(c.start, c.end, c.part, m.group(2)))
    return out


@dataclass
class Track:
    """One person's motion as features, with its texts."""
    features: np.ndarray             # (T, 239) float32, not normalised
    offsets: np.ndarray              # (22, 3) rest offsets (for decoding to joints)
    prompt: str
    captions: list[Caption] = field(default_factory=list)
    split: str = "train"
    clip_id: str = ""
    mirrored: bool = False
    licence: str = ""

    def prompt_for(self, part: str, start: int, end: int) -> str:
        """The caption of `part` overlapping frames [start, end) most, else the prompt."""
        best, best_overlap = self.prompt, 0
        for c in self.captions:
            overlap = min(end, c.end) - max(start, c.start)
            if c.part == part and overlap > best_overlap:
                best, best_overlap = c.text, overlap
        return best


def build_tracks(clips) -> list[Track]:
    """Every person of every real clip as a Track; train tracks also mirrored. Synthetic
    (composed) pairs are left out: they re-use real single-person clips, with IK edits."""
    tracks = []
    for clip in (c for c in clips if not c.synthetic):
        for i, (joints, offsets) in enumerate(zip(clip.people, clip.offsets)):
            prompt = person_prompt(clip.prompt, len(clip.people))
            caps = person_captions(clip.captions, i)
            tracks.append(Track(encode(joints, offsets), np.asarray(offsets, np.float32),
                                prompt, caps, clip.split, clip.id, False, clip.licence))
            if clip.split == "train":
                mcaps = [Caption(c.start, c.end, MIRROR_PART[c.part], mirror_text(c.text))
                         for c in caps]
                moff = mirror_joints(offsets)
                tracks.append(Track(encode(mirror_joints(joints), moff), moff.astype(np.float32),
                                    mirror_text(prompt), mcaps, clip.split, clip.id, True,
                                    clip.licence))
    return tracks


def _data_key(data_dir: Path) -> str:
    h = hashlib.sha1(f"v{CACHE_VERSION}{'-commercial' if excluding_noncommercial() else ''}".encode())
    for p in sorted(Path(data_dir).glob("*")):
        if p.suffix in (".npz", ".json"):
            h.update(p.name.encode() + p.read_bytes())
    return h.hexdigest()[:12]


def load_tracks(data_dir: str | Path = DATA_DIR, cache_dir: str | Path = CACHE_DIR,
                clips=None) -> list[Track]:
    """Tracks of the processed set (its training clips: `models.common.sources`), from the
    cache when it matches the data (else built and cached). `clips` (a subset, e.g. for the
    smoke tests) bypasses the cache; the non-commercial switch applies to it too."""
    if clips is not None:
        return build_tracks(training_clips(clips=clips))
    cache = Path(cache_dir) / f"tracks-{_data_key(Path(data_dir))}"
    if (cache / "tracks.json").exists():
        meta = json.loads((cache / "tracks.json").read_text())
        with np.load(cache / "features.npz") as z:
            feats, offsets = z["features"], z["offsets"]
        return [Track(feats[m["start"]:m["start"] + m["frames"]], offsets[i], m["prompt"],
                      [Caption(**c) for c in m["captions"]], m["split"], m["clip_id"],
                      m["mirrored"], m["licence"]) for i, m in enumerate(meta)]
    tracks = build_tracks(training_clips(data_dir))
    cache.mkdir(parents=True, exist_ok=True)
    starts = np.cumsum([0] + [len(t.features) for t in tracks])
    np.savez(cache / "features.npz", features=np.concatenate([t.features for t in tracks]),
             offsets=np.stack([t.offsets for t in tracks]))
    (cache / "tracks.json").write_text(json.dumps([
        {"start": int(s), "frames": len(t.features), "prompt": t.prompt,
         "captions": [vars(c) for c in t.captions], "split": t.split, "clip_id": t.clip_id,
         "mirrored": t.mirrored, "licence": t.licence} for s, t in zip(starts, tracks)]))
    return tracks


def fit_normalizer(tracks: list[Track]) -> Normalizer:
    """Per-dim mean/std over the train tracks (mirrored included: the data is symmetric)."""
    return Normalizer.fit([t.features for t in tracks if t.split == "train"])


class TextBank:
    """Every distinct text of the tracks embedded once with MiniLM; rows by string."""

    def __init__(self, tracks: list[Track], cache_dir: str | Path | None = CACHE_DIR):
        texts = sorted({t.prompt for t in tracks} | {c.text for t in tracks for c in t.captions})
        self.row = {s: i for i, s in enumerate(texts)}
        key = hashlib.sha1("\n".join(texts).encode()).hexdigest()[:12]
        path = Path(cache_dir) / f"text-{key}.npy" if cache_dir else None
        if path is not None and path.exists():
            self.emb = np.load(path)
        else:
            from interplay.text.encoder import get_encoder
            self.emb = get_encoder().encode(texts)
            if path is not None:
                path.parent.mkdir(parents=True, exist_ok=True)
                np.save(path, self.emb)

    def __call__(self, texts: list[str]) -> np.ndarray:
        return self.emb[[self.row[t] for t in texts]]


def part_texts(track: Track, start: int, end: int, part_prompts: bool) -> list[str]:
    """The four texts of a window (PARTS order): the global prompt repeated, or each part's
    caption covering most of the window."""
    if not part_prompts:
        return [track.prompt] * len(PARTS)
    return [track.prompt_for(p, start, end) for p in PARTS]


def sample_windows(tracks: list[Track], rng: np.random.Generator, batch: int,
                   length: int) -> list[tuple[int, int]]:
    """`batch` random (track index, start frame) windows of `length` frames, tracks drawn in
    proportion to how many windows they hold (tracks shorter than `length` never)."""
    counts = np.array([max(len(t.features) - length + 1, 0) for t in tracks], dtype=np.float64)
    if counts.sum() == 0:
        raise ValueError(f"no track holds {length} frames")
    idx = rng.choice(len(tracks), size=batch, p=counts / counts.sum())
    return [(int(i), int(rng.integers(0, counts[i]))) for i in idx]
