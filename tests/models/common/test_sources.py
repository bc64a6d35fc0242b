"""`make train EXCLUDE_NONCOMMERCIAL=1` (models/common/sources.py): every trainer's clips drop
the non-commercial source, the record and the model card say so; by default every source is
used. Smoke-sized: a tiny evaluator trained for seconds, train_all's stages stubbed."""

from __future__ import annotations

import pytest

torch = pytest.importorskip("torch")

from interplay.data.licences import is_noncommercial  # noqa: E402
from interplay.motion.clip import default_clips  # noqa: E402
from models.common import sources  # noqa: E402
from models.common.sources import licence_section, training_clips, training_data  # noqa: E402


@pytest.fixture
def excluding(monkeypatch):
    monkeypatch.setenv(sources.ENV, "1")       # restored after the test


def _few(val: int = 0):
    """Two train clips (and `val` val clips) each of a Bandai Namco bow (non-commercial), an
    HDM05 squat and an HDM05 hop."""
    clips = default_clips()
    out = []
    for source, prompt in (("bandai-namco", "a person bows"),
                           ("hdm05", "a person squats down and stands back up"),
                           ("hdm05", "a person hops on both legs")):
        out += [c for c in clips if c.source == source and prompt in c.prompt and c.split == "train"][:2]
        out += [c for c in clips if c.source == source and prompt in c.prompt and c.split == "val"][:val]
    return out


def test_default_trains_on_every_source(monkeypatch):
    monkeypatch.setenv(sources.ENV, "0")
    clips = training_clips()
    assert {"bandai-namco", "hdm05", "cmu-bvh", "deepmimic"} <= {c.source for c in clips}
    info = training_data(clips)
    assert not info["excluded_noncommercial"] and info["noncommercial_clips"] > 0
    card = "\n".join(licence_section(info))
    assert "non-commercial use only" in card and "EXCLUDE_NONCOMMERCIAL=1" in card
    assert "HDM05" in card and "mocap.cs.cmu.edu" in card and "Xue Bin Peng" in card


def test_the_option_drops_noncommercial_clips_everywhere(excluding):
    clips = training_clips()
    assert clips and not any(is_noncommercial(c.licence) for c in clips)
    assert "bandai-namco" not in {c.source for c in clips}
    assert len(training_clips(clips=_few())) == 4
    info = training_data(clips)
    assert info["excluded_noncommercial"] and info["noncommercial_clips"] == 0
    card = "\n".join(licence_section(info))
    assert "--exclude-noncommercial" in card and "non-commercial use only" not in card
    # SPAM's tracks, too (the smoke-test path that bypasses the cache).
    from models.spam.data import load_tracks
    assert {t.clip_id.split(":")[0] for t in load_tracks(clips=_few())} == {"hdm05"}


def test_tiny_evaluator_trained_without_noncommercial_data_says_so(excluding, tmp_path):
    from models.evaluator.config import EvaluatorConfig
    from models.evaluator.export import export, model_card
    from models.evaluator.train import TINY, train

    cfg = EvaluatorConfig(**{**TINY, "steps": 4, "eval_every": 4, "batch_size": 4,
                             "max_frames": 40, "seconds": 60.0})
    ckpt = train(cfg, _few(val=1), log=lambda *_: None)
    info = ckpt["data"]["training_data"]
    assert info["sources"] == {"hdm05": 4} and info["excluded_noncommercial"]
    torch.save(ckpt, tmp_path / "evaluator.pt")
    export(tmp_path / "evaluator.pt", tmp_path / "w")
    table = {s: {"samples": 1, "texts": 1, "r_precision": [(0.0, 0.0)] * 3} for s in ("val", "test")}
    card = model_card(ckpt, table, 0.0, 1, tmp_path / "w")
    assert "## Training data and licence" in card and "--exclude-noncommercial" in card
    assert "Trained on: hdm05 (4 clips)" in card


def test_train_all_passes_the_option_to_every_stage(monkeypatch):
    import models.arflow.__main__ as arflow
    import models.coda.__main__ as coda
    import models.evaluator.export as evaluator_export
    import models.pair_evaluator.__main__ as pair_evaluator
    import models.spam.__main__ as spam
    from models import train_all

    seen: list[tuple[str, list[str], bool]] = []
    for name, mod in (("spam", spam), ("evaluator", evaluator_export), ("pair", pair_evaluator),
                      ("arflow", arflow), ("coda", coda)):
        monkeypatch.setattr(mod, "main", lambda argv=None, _n=name: seen.append(
            (_n, list(argv or []), sources.excluding_noncommercial())))
    # setenv (not delenv) so that monkeypatch restores the variable train_all sets directly.
    monkeypatch.setenv(sources.ENV, "0")
    train_all.main(["--scale", "0.1", "--exclude-noncommercial"])
    assert [s[0] for s in seen] == ["spam", "evaluator", "pair", "arflow", "coda"]
    assert all(on for _, _, on in seen)
    assert seen[0][1] == ["--all", "--scale", "0.1"] and seen[-1][1] == ["--all", "--scale", "0.1"]
    monkeypatch.setenv(sources.ENV, "0")
    seen.clear()
    train_all.main([])
    assert not any(on for _, _, on in seen)


def test_no_switch_left_on():
    assert not sources.excluding_noncommercial()
