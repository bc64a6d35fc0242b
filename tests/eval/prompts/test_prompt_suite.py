"""The committed prompt suite of `interplay eval-prompts`."""

from __future__ import annotations

import collections
import json

import pytest

from interplay.eval.prompts.suite import CATEGORIES, SUITE, _prompt, load_suite, select
from interplay.motion.checks.named import CHECKS
from interplay.motion.clip import default_clips


def test_at_least_100_prompts_in_every_category_and_both_splits():
    prompts = load_suite()
    assert len(prompts) >= 100
    per = collections.Counter((p.category, p.split) for p in prompts)
    for cat in CATEGORIES:
        assert per[(cat, "dev")] >= 5 and per[(cat, "test")] >= 5, cat
    assert len(select(prompts, "dev")) + len(select(prompts, "test")) == len(prompts)


def test_two_person_prompts_cover_the_interaction_kinds():
    two = [p for p in load_suite() if p.persons == 2]
    kinds = collections.Counter((p.kind, p.split) for p in two)
    for k in ("greeting", "contact", "pushing", "following", "mirroring", "dancing"):
        assert kinds[(k, "dev")] + kinds[(k, "test")] >= 2, k
    assert all(p.category == "two_person" for p in two)
    assert all(any(CHECKS[c["check"]].persons == 2 or c.get("person") == "both" for c in p.checks)
               for p in two)


def test_prompts_are_not_the_data_labels():
    data = {c.prompt.lower().strip(" .") for c in default_clips()}
    for p in load_suite():
        assert p.prompt.lower().strip(" .") not in data, p.prompt
        assert not p.prompt.lower().startswith("a person ")         # the data's label form


def test_every_check_runs_with_its_parameters():
    import numpy as np
    walk = next(c for c in default_clips() if c.label == "walk").people[0]
    for p in load_suite():
        people = [walk, walk + np.array([1.0, 0, 0])] if p.persons == 2 else [walk]
        from interplay.motion.checks.named import run_check
        for spec in p.checks:
            r = run_check(people, spec)
            assert isinstance(r.passed, bool) and r.bound, (p.id, spec)
            json.dumps(r.to_json())


def test_the_suite_rejects_bad_prompts():
    good = json.loads(SUITE.read_text())["prompts"][0]
    for bad in ({"split": "train"}, {"category": "nope"}, {"persons": 3},
                {"checks": [{"check": "no_such_check"}]}, {"checks": []},
                {"checks": [{"check": "handshake"}]}, {"start": "flying"}):
        with pytest.raises(ValueError):
            _prompt({**good, **bad})
