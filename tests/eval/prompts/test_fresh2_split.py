"""The `fresh2` split of `interplay eval-prompts`: everyday prompts written blind (without the
studio's vocabulary or any output). Its file validates, its size and groups, unique ids, that
every check and every parameter it names exists, that every check runs, and that the command
line and the report take the split."""

from __future__ import annotations

from interplay.eval.prompts.suite import FRESH, FRESH2, load_split, load_suite
from tests.helpers.blind_splits import (
    assert_checks_and_parameters_exist,
    assert_checks_run_on_a_capture,
    assert_command_line_reads,
    assert_file_holds_only,
    assert_pairs_check_between,
    assert_report_names_categories,
    assert_unique_and_new,
)


def fresh2():
    return load_split("fresh2")


def test_the_file_validates_and_holds_only_fresh2():
    assert_file_holds_only("fresh2", FRESH2, blind=False)


def test_the_split_has_its_groups():
    ps = fresh2()
    one = [p for p in ps if p.persons == 1]
    two = [p for p in ps if p.persons == 2]
    assert len(one) >= 45 and len(two) >= 15
    assert all(p.category == "everyday" and p.edit is None for p in one)
    assert all(p.category == "two_person" and p.kind for p in two)
    assert all(4 <= p.seconds <= 8 for p in ps)
    assert_pairs_check_between(two)


def test_ids_and_prompts_are_unique_and_new():
    assert_unique_and_new(fresh2(), load_suite() + load_suite(FRESH), texts_new=False)


def test_every_check_and_parameter_exists():
    assert_checks_and_parameters_exist(fresh2())


def test_every_check_runs_on_a_capture():
    assert_checks_run_on_a_capture(fresh2())


def test_the_command_line_reads_the_split(capsys):
    assert_command_line_reads("fresh2", capsys)


def test_the_report_names_its_categories():
    assert_report_names_categories(fresh2(), "fresh2")
