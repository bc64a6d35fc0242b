"""The checks against the labels of the larger captured sources (Bandai-Namco's motion
dataset, DeepMimic's clips, CMU's karate kata): each labelled action passes its check and the
others do not. Skipped where the processed data set does not hold that source."""

from __future__ import annotations

import collections

import numpy as np
import pytest

from interplay.motion.checks import named as N
from interplay.motion.clip import default_clips


def family(source: str, label: str) -> list:
    out = [c for c in default_clips() if c.source == source and c.label.split(" (")[0] == label]
    if not out:
        pytest.skip(f"no {source} clips labelled {label!r} in the processed data")
    return out


def rate(clips, **spec) -> float:
    return float(np.mean([N.run_check(c.people, spec).passed for c in clips]))


def test_bandai_waves_are_waves_with_the_named_hand_and_raised_hands_are_not():
    left, right = family("bandai-namco", "wave-left-hand"), family("bandai-namco", "wave-right-hand")
    assert rate(left, check="wave", hand="left") >= 0.8
    assert rate(right, check="wave", hand="right") >= 0.8
    assert rate(left, check="wave", hand="right") <= 0.05
    assert rate(right, check="wave", hand="left") <= 0.05
    held = family("bandai-namco", "raise-up-left-hand") + family("bandai-namco", "raise-up-right-hand")
    assert rate(held, check="wave") <= 0.05                       # a held arm is not a wave
    raised = family("bandai-namco", "raise-up-left-hand")
    assert rate(raised, check="hand_raised", hand="left", level="head", min_s=0.5) >= 0.8
    assert rate(raised, check="hand_raised", hand="right", level="head", min_s=0.5) <= 0.05


def test_bandai_walks_back_bows_and_dashes():
    back, walk = family("bandai-namco", "walk-back"), family("bandai-namco", "walk")
    assert rate(back, check="travel_direction", direction="backward") >= 0.9
    assert rate(walk, check="travel_direction", direction="backward") == 0.0
    assert rate(walk, check="travel_direction", direction="forward") >= 0.9
    assert rate(family("bandai-namco", "bow"), check="bow") >= 0.8
    for lab in ("walk", "walk-back", "raise-up-both-hands"):
        assert rate(family("bandai-namco", lab), check="bow") == 0.0
    assert rate(family("bandai-namco", "dash"), check="speed_band", band="run") >= 0.9
    assert rate(walk, check="speed_band", band="run") <= 0.05


def test_nothing_in_walks_counts_as_a_kick_punch_or_jump():
    walk = family("bandai-namco", "walk")
    counts = collections.Counter()
    for c in walk:
        for name in ("kick", "punch", "jump_count", "wave"):
            counts[name] += N.run_check(c.people, {"check": name}).passed
    assert sum(counts.values()) == 0, counts


def test_karate_kata_punches_and_deepmimic_crawls():
    kata = family("cmu-asfamc", "Heiansyodan")
    assert rate(kata, check="punch", at_least=3) == 1.0
    crawl = family("deepmimic", "crawl")
    assert rate(crawl, check="crawl") == 1.0
    assert rate(family("deepmimic", "walk"), check="crawl") == 0.0
