"""The `fresh2` split of `interplay eval-prompts`: everyday prompts written blind (without the
studio's vocabulary or any output). Its file validates, its size and groups, unique ids, that
every check and every parameter it names exists, that every check runs, and that the command
line and the report take the split."""

from __future__ import annotations

import collections
import inspect
import json

import numpy as np

from interplay.eval.prompts.report import build_report, format_table
from interplay.eval.prompts.suite import FRESH, FRESH2, SPLITS, category_labels, load_split, load_suite
from interplay.motion.checks.named import CHECKS, run_check
from interplay.motion.clip import default_clips


def fresh2():
    return load_split("fresh2")


def test_the_file_validates_and_holds_only_fresh2():
    raw = json.loads(FRESH2.read_text())
    assert {"about", "version", "prompts"} <= set(raw)
    ps = fresh2()
    assert len(ps) == len(raw["prompts"]) == len(load_suite(FRESH2))
    assert collections.Counter(p.split for p in ps) == {"fresh2": len(ps)}
    assert "fresh2" in SPLITS


def test_the_split_has_its_groups():
    ps = fresh2()
    one = [p for p in ps if p.persons == 1]
    two = [p for p in ps if p.persons == 2]
    assert len(one) >= 45 and len(two) >= 15
    assert all(p.category == "everyday" and p.edit is None for p in one)
    assert all(p.category == "two_person" and p.kind for p in two)
    assert all(4 <= p.seconds <= 8 for p in ps)
    # every two-person prompt checks something between the two people
    assert all(any(CHECKS[c["check"]].persons == 2 or c.get("person") == "both" for c in p.checks)
               for p in two)


def test_ids_and_prompts_are_unique_and_new():
    ps = fresh2()
    ids = [p.id for p in ps]
    assert len(set(ids)) == len(ids)
    texts = [p.prompt.lower() for p in ps]
    assert len(set(texts)) == len(texts)
    others = {p.id for p in load_suite()} | {p.id for p in load_suite(FRESH)}
    assert not set(ids) & others


def test_every_check_and_parameter_exists():
    for p in fresh2():
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
    for p in fresh2():
        people = [walk, walk + np.array([1.0, 0, 0])] if p.persons == 2 else [walk]
        for spec in p.checks:
            r = run_check(people, spec)
            assert isinstance(r.passed, bool) and r.bound, (p.id, spec)
            json.dumps(r.to_json())


def test_the_command_line_reads_the_split(capsys):
    from interplay.cli.main import build_parser, main
    assert main(["eval-prompts", "--split", "fresh2", "--ids", "no-such-id"]) == 2
    assert "no prompts in split 'fresh2' with ids no-such-id" in capsys.readouterr().err
    args = build_parser().parse_args(["review-eval", "--honesty", "--split", "fresh2"])
    assert args.split == "fresh2"


def test_the_report_names_its_categories():
    ps = fresh2()
    report = build_report([], {}, ps, [], "fresh2", 1, 0.0)
    assert report["categories"]["everyday"] == sum(p.persons == 1 for p in ps)
    assert report["categories"]["two_person"] == sum(p.persons == 2 for p in ps)
    text = format_table(report)
    assert category_labels("fresh2")["everyday"] in text and "(dev)" not in text
    assert category_labels("dev")["everyday"] != category_labels("fresh2")["everyday"]
