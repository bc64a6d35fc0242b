"""The `fresh` split of `interplay eval-prompts`: its size, that its content words are unknown to
the code at the commit that added it, that the vocabulary snapshot is what that commit's code
gives, and that every prompt's checks run."""

from __future__ import annotations

import collections
import json
import subprocess

import numpy as np
import pytest

from interplay.eval.prompts import vocabulary as V
from interplay.eval.prompts.suite import FRESH, _prompt, load_split, load_suite
from interplay.motion.checks.named import CHECKS, run_check
from interplay.motion.clip import default_clips


def fresh():
    return load_split("fresh")


def test_the_split_has_its_groups():
    ps = fresh()
    assert len(ps) >= 60
    one = [p for p in ps if p.persons == 1 and p.edit is None]
    two = [p for p in ps if p.persons == 2]
    edits = [p for p in ps if p.edit is not None]
    assert len(one) >= 40 and len(two) >= 15 and len(edits) >= 5
    assert sum(p.edit["part"] == "head" for p in edits) >= 3
    assert all(p.category == "edits" for p in edits) and all(p.category == "two_person" for p in two)
    # Every check is a named check measured on the joints; edits check the rest of the body too.
    assert all(any(CHECKS[c["check"]].base for c in p.checks) for p in edits)


def test_dev_and_test_are_untouched_by_it():
    suite = load_suite()
    assert {p.split for p in suite} == {"dev", "test"}
    assert load_split("test") == [p for p in suite if p.split == "test"]
    texts = {p.prompt.lower() for p in suite}
    data = {c.prompt.lower().strip(" .") for c in default_clips()}
    for p in fresh():
        assert p.prompt.lower() not in texts and p.prompt.lower() not in data, p.prompt


def snapshot_known() -> V.Known:
    return V.Known(V.load_snapshot()["words"])


def test_no_content_word_of_a_fresh_prompt_is_in_the_code():
    known = snapshot_known()
    hits = {}
    for p in fresh():
        texts = [p.prompt] + ([p.edit["text"]] if p.edit else [])
        words = [w for t in texts for w in V.content_words(t)]
        assert words, f"{p.id}: no content word"
        bad = {w: known.why(w) for w in words if known.why(w)}
        if bad:
            hits[p.id] = bad
    assert hits == {}


def test_the_rule_catches_the_code_s_words_and_their_inflections():
    known = snapshot_known()
    for word in ("walk", "walking", "jumps", "waved", "squatting", "kick", "punches"):
        assert known.why(word), word                        # the planner's actions
    assert known.why("wrestling") and known.why("chasing")  # stems the planner matches as prefixes
    assert known.why("saluting") == "salute"                # an inflection of a table word
    assert V.content_words("Two people toast each other's glasses") == ["toast", "glasses"]
    assert not known.why("juggling") and not known.why("piggyback")


def test_the_vocabulary_reads_literals_not_docstrings_nor_the_benchmark():
    src = '"""Docstring about zebras."""\nX = {"hopScotch": r"\\bwalk(s|ed)?\\b"}\nY = f"a {X} b_c"\n'
    assert V.words_of_source(src) == {"hop", "scotch", "walk", "s", "ed", "a", "b", "c"}
    assert V.scanned("backend/interplay/planner/lexicon.py")
    assert V.scanned("backend/interplay/catalogue/actions.toml")          # word lists as data
    assert V.words_of_file("x.toml", '[squat]\nforms = ["squats"]  # deep') == {"squat", "forms",
                                                                              "squats", "deep"}
    assert not V.scanned("backend/interplay/eval/prompts/suite.py")
    assert not V.scanned("backend/interplay/motion/checks/named.py")


def _git_has(commit: str) -> bool:
    try:
        return subprocess.run(["git", "cat-file", "-e", f"{commit}^{{commit}}"], cwd=V.ROOT,
                              capture_output=True).returncode == 0
    except OSError:
        return False


def test_the_snapshot_is_what_its_commit_gives():
    snap = V.load_snapshot()
    if not _git_has(snap["commit"]):
        pytest.skip(f"git or commit {snap['commit'][:10]} is not available here")
    assert snap["excluded"] == list(V.EXCLUDED)
    assert snap["words"] == V.words_at(snap["commit"])


def test_every_fresh_check_runs_on_a_capture():
    walk = next(c for c in default_clips() if c.label == "walk").people[0]
    for p in fresh():
        people = [walk, walk + np.array([1.0, 0, 0])] if p.persons == 2 else [walk]
        for spec in p.checks:
            r = run_check(people, spec, base=people)
            assert isinstance(r.passed, bool) and r.bound, (p.id, spec)
            json.dumps(r.to_json())


def test_edit_entries_are_validated():
    good = json.loads(FRESH.read_text())["prompts"]
    edit = next(d for d in good if "edit" in d)
    plain = next(d for d in good if "edit" not in d and d["persons"] == 1)
    assert _prompt(edit).edit == edit["edit"]
    for bad in ({**edit, "edit": {"part": "head"}}, {**edit, "persons": 2},
                {**plain, "checks": [{"check": "rest_unchanged"}]}):
        with pytest.raises(ValueError):
            _prompt(bad)
    counts = collections.Counter(p.split for p in fresh())
    assert set(counts) == {"fresh"}


def test_the_command_line_reads_the_fresh_split(capsys):
    from interplay.cli.main import main
    assert main(["eval-prompts", "--split", "fresh", "--ids", "no-such-id"]) == 2
    assert "no prompts in split 'fresh' with ids no-such-id" in capsys.readouterr().err
