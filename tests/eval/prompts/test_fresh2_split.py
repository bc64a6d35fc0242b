"""The `fresh2` split of `interplay eval-prompts`: everyday prompts written blind (without the
studio's vocabulary or any output). Its file validates, its size and groups, unique ids, that
every check and every parameter it names exists, that every check runs, and that the command
line and the report take the split."""

from __future__ import annotations

import collections
import json

from interplay.eval.prompts.suite import FRESH, FRESH2, SPLITS, load_split, load_suite
from interplay.motion.checks.named import CHECKS
from tests.helpers.blind_splits import (
    assert_checks_and_parameters_exist,
    assert_checks_run_on_a_capture,
    assert_command_line_reads,
    assert_report_names_categories,
)


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
    assert_checks_and_parameters_exist(fresh2())


def test_every_check_runs_on_a_capture():
    assert_checks_run_on_a_capture(fresh2())


def test_the_command_line_reads_the_split(capsys):
    assert_command_line_reads("fresh2", capsys)


def test_the_report_names_its_categories():
    assert_report_names_categories(fresh2(), "fresh2")
