"""`interplay eval` end to end on the real test split (the cheap rows), and row loading."""

import json

import numpy as np
import pytest

from interplay.cli import evals
from interplay.cli import main as cli
from interplay.eval import rows as R
from interplay.eval.report import EvalConfig, evaluate_row, format_table
from interplay.eval.testset import split_samples
from interplay.motion.clip import default_clips


def test_cli_eval_real_row_json(capsys):
    assert cli.main(["eval", "--rows", "real", "--repeats", "3", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    real = report["rows"]["real"]
    assert report["test_set"]["samples"] == real["motions"] > 50
    for k in ("top1", "top2", "top3"):
        assert 0.5 < real[k][0] <= 1.0 and real[k][1] >= 0
    assert real["top1"][0] <= real["top2"][0] <= real["top3"][0]
    assert real["fid"][0] > 0                   # bootstrap resamples: the noise floor, not 0
    assert "multimodality" not in real          # real motion has no generations per text
    assert real["ground_penetration"][0] < 0.01 and real["bone_deviation"][0] < 0.005


def test_cli_eval_refuses_unknown_rows(capsys):
    assert cli.main(["eval", "--rows", "real,nope"]) == 2
    assert "nope" in capsys.readouterr().err
    assert cli.main(["eval", "--rows", "real", "--repeats", "1"]) == 2


def test_cli_eval_validation_split_and_sampling_arguments(capsys):
    assert cli.main(["eval", "--rows", "real", "--repeats", "2", "--split", "val", "--json"]) == 0
    val = json.loads(capsys.readouterr().out)
    test = {s.clip for s in split_samples(default_clips(), "test")}
    assert 10 < val["test_set"]["samples"] and val["config"]["split"] == "val"
    assert not test & {s.clip for s in split_samples(default_clips(), "val")}
    assert evals._sampling_args(["cfg=2.5", "steps=5", "mode=inpaint"]) == [
        ("cfg", 2.5), ("steps", 5), ("mode", "inpaint")]
    assert cli.main(["eval", "--rows", "real", "--sampling", "cfg"]) == 2
    assert "KEY=VALUE" in capsys.readouterr().err


def test_spam_row_takes_sampling_overrides():
    row = R.load_row("spam", default_clips(), {"cfg": 2.5, "steps": 3, "mode": "inpaint"})
    a = row.generate("a person walks forward", 40, 1)
    assert a.shape == (40, 22, 3)
    with pytest.raises(TypeError):
        R.load_row("spam", default_clips(), {"nope": 1}).generate("a person jumps", 40, 1)


class _FakeEvaluator:
    """Embeds a motion by its mean pelvis height (enough to tell shuffled motions apart)."""

    def embed_motion(self, motions):
        return np.array([[m[:, 0, 1].mean(), m[:, :, 1].std(), 1.0] for m in motions])


def test_generated_row_uses_every_generation_and_shuffling_hurts():
    """A 'generator' that returns the real capture scores like real data; one that returns
    other prompts' captures scores worse, with the same evaluator and texts."""
    samples = split_samples(default_clips(), "test")[:30]
    ev = _FakeEvaluator()
    real = ev.embed_motion([s.joints for s in samples])
    by_text = {}
    for s in samples:
        by_text.setdefault(s.text, s.joints)
    calls = []

    def copy(text, frames, seed):
        calls.append(seed)
        return next(s.joints for s in samples if s.text == text and s.frames == frames)

    def wrong(text, frames, seed):
        other = next(t for t in by_text if t != text)
        j = by_text[other]
        return np.resize(j, (frames,) + j.shape[1:])
    cfg = EvalConfig(repeats=3, rounds=2, mm_generations=3)
    texts = real.copy()                                   # text embedding = its own motion's
    good = evaluate_row(R.Row("copy", "generated", generate=copy), samples, real, texts, ev, cfg)
    n_texts = len({s.text for s in samples})
    assert len(calls) == good["motions"] == n_texts * 3 + (len(samples) - n_texts) * 2
    bad = evaluate_row(R.Row("wrong", "generated", generate=wrong), samples, real, texts, ev, cfg)
    assert good["fid"][0] < bad["fid"][0]
    assert good["mm_dist"][0] < bad["mm_dist"][0]
    assert good["multimodality"][0] == pytest.approx(0.0, abs=1e-9)   # the same capture each time
    report = {"test_set": {"samples": 30, "clips": 30, "texts": n_texts}, "config": {"repeats": 3},
              "rows": {"copy": good, "wrong": bad}, "edits": {}, "skipped": {"x": "why"},
              "seconds": 1.0}
    table = format_table(report)
    assert "copy" in table and "wrong" in table and "skipped x: why" in table


def test_rows_without_trained_weights_are_skipped(tmp_path, monkeypatch):
    monkeypatch.setattr(R, "WEIGHTS", tmp_path / "models" / "weights")
    (tmp_path / "models" / "weights" / "spam").mkdir(parents=True)
    with pytest.raises(R.Skip, match="no weights"):
        R.load_row("spam", [])
    (tmp_path / "models" / "weights" / "spam" / "config.json").write_text("{}")
    (tmp_path / "models" / "weights" / "spam" / "MODEL_CARD.md").write_text("UNTRAINED placeholder")
    with pytest.raises(R.Skip, match="placeholder"):
        R.load_row("spam_vq", [])
    with pytest.raises(R.Skip, match="not exported"):
        R.load_row("single_vq", [])
    with pytest.raises(ValueError, match="unknown row"):
        R.load_row("nope", [])
