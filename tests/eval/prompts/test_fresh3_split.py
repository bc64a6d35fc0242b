"""The `fresh3` split of `interplay eval-prompts`: a second set of everyday prompts written blind
(without the studio's vocabulary or any output), 30 for one person and 30 for two. Its file
validates and holds only fresh3, its size and groups, unique ids and prompts new to every other
split, that every check and every parameter it names exists, that every check runs, and that
the command line and the report take the split."""

from __future__ import annotations

import collections
import inspect
import json

import numpy as np

from interplay.eval.prompts.report import build_report, format_table
from interplay.eval.prompts.suite import (
    FRESH,
    FRESH2,
    FRESH3,
    SPLIT_FILES,
    SPLITS,
    category_labels,
    load_split,
    load_suite,
)
from interplay.motion.checks.named import CHECKS, run_check
from interplay.motion.clip import default_clips


def fresh3():
    return load_split("fresh3")


def test_the_file_validates_and_holds_only_fresh3():
    raw = json.loads(FRESH3.read_text())
    assert {"about", "version", "prompts"} <= set(raw)
    assert "blind" in raw["about"]
    ps = fresh3()
    assert len(ps) == len(raw["prompts"]) == len(load_suite(FRESH3))
    assert collections.Counter(p.split for p in ps) == {"fresh3": len(ps)}
    assert "fresh3" in SPLITS and SPLIT_FILES["fresh3"] == FRESH3


def test_the_split_has_its_groups():
    ps = fresh3()
    one = [p for p in ps if p.persons == 1]
    two = [p for p in ps if p.persons == 2]
    assert len(one) == 30 and len(two) == 30
    assert all(p.category == "everyday" and p.edit is None and not p.contact for p in one)
    assert all(p.category == "two_person" and p.kind for p in two)
    assert len({p.kind for p in two}) >= 8
    assert all(4 <= p.seconds <= 8 for p in ps)
    # every two-person prompt checks something between the two people
    assert all(any(CHECKS[c["check"]].persons == 2 or c.get("person") == "both" for c in p.checks)
               for p in two)


def test_ids_and_prompts_are_unique_and_new():
    ps = fresh3()
    ids = [p.id for p in ps]
    assert len(set(ids)) == len(ids)
    texts = [p.prompt.lower() for p in ps]
    assert len(set(texts)) == len(texts)
    others = [p for path in (None, FRESH, FRESH2) for p in (load_suite(path) if path else load_suite())]
    assert not set(ids) & {p.id for p in others}
    # only the repeats are named (a failure must not print the other splits' prompts)
    repeated = sorted(set(texts) & {p.prompt.lower() for p in others})
    assert not repeated


def test_every_check_and_parameter_exists():
    for p in fresh3():
        assert 1 <= len(p.checks) <= 3, p.id
        for spec in p.checks:
            params = dict(spec)
            name = params.pop("check")
            assert name in CHECKS, (p.id, name)
            check = CHECKS[name]
            assert not check.base, (p.id, name)
            assert check.persons <= p.persons, (p.id, name)
            # one-person checks take (BodyFrame, …), two-person (a, b, fa, fb, …)
            sig = list(inspect.signature(check.fn).parameters.values())[1 if check.persons == 1 else 4:]
            known = {x.name for x in sig}
            if check.persons == 1:
                who = params.pop("person", None)
                assert who in (None, 0, 1, "any", "both") and (who is None or p.persons == 2), (p.id, name)
            assert set(params) <= known, (p.id, name, set(params) - known)


def test_every_check_runs_on_a_capture():
    walk = next(c for c in default_clips() if c.label == "walk").people[0]
    for p in fresh3():
        people = [walk, walk + np.array([1.0, 0, 0])] if p.persons == 2 else [walk]
        for spec in p.checks:
            r = run_check(people, spec)
            assert isinstance(r.passed, bool) and r.bound, (p.id, spec)
            json.dumps(r.to_json())


def test_the_command_line_reads_the_split(capsys):
    from interplay.cli.main import build_parser, main
    assert main(["eval-prompts", "--split", "fresh3", "--ids", "no-such-id"]) == 2
    assert "no prompts in split 'fresh3' with ids no-such-id" in capsys.readouterr().err
    args = build_parser().parse_args(["review-eval", "--honesty", "--split", "fresh3"])
    assert args.split == "fresh3"


def test_the_report_names_its_categories():
    ps = fresh3()
    report = build_report([], {}, ps, [], "fresh3", 1, 0.0)
    assert report["categories"]["everyday"] == sum(p.persons == 1 for p in ps)
    assert report["categories"]["two_person"] == sum(p.persons == 2 for p in ps)
    text = format_table(report)
    assert category_labels("fresh3")["everyday"] in text and "(dev)" not in text
    assert category_labels("dev")["everyday"] != category_labels("fresh3")["everyday"]
