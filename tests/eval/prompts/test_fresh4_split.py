"""The `fresh4` split of `interplay eval-prompts`: a third set of everyday prompts written blind
(without the studio's vocabulary or any output), 25 for one person and 35 for two. Its file
validates and holds only fresh4, its size and groups, unique ids and prompts new to every other
split, that every check and every parameter it names exists, that every check runs, and that
the command line and the report take the split."""

from __future__ import annotations

from interplay.eval.prompts.suite import FRESH, FRESH2, FRESH3, FRESH4, load_split, load_suite
from tests.helpers.blind_splits import (
    assert_checks_and_parameters_exist,
    assert_checks_run_on_a_capture,
    assert_command_line_reads,
    assert_file_holds_only,
    assert_pairs_check_between,
    assert_report_names_categories,
    assert_unique_and_new,
)


def fresh4():
    return load_split("fresh4")


def test_the_file_validates_and_holds_only_fresh4():
    assert_file_holds_only("fresh4", FRESH4)


def test_the_split_has_its_groups():
    ps = fresh4()
    one = [p for p in ps if p.persons == 1]
    two = [p for p in ps if p.persons == 2]
    assert len(one) == 25 and len(two) == 35
    assert all(p.category == "everyday" and p.edit is None and not p.contact for p in one)
    assert all(p.category == "two_person" and p.kind for p in two)
    assert len({p.kind for p in two}) >= 8
    assert all(6 <= p.seconds <= 8 for p in ps)
    assert_pairs_check_between(two)


def test_ids_and_prompts_are_unique_and_new():
    ps = fresh4()
    assert [p.id for p in ps] == [f"fresh4-one-{i:02d}" for i in range(1, 26)] + [
        f"fresh4-two-{i:02d}" for i in range(1, 36)]
    others = [p for path in (None, FRESH, FRESH2, FRESH3)
              for p in (load_suite(path) if path else load_suite())]
    assert_unique_and_new(ps, others)


def test_every_check_and_parameter_exists():
    assert_checks_and_parameters_exist(fresh4())


def test_every_check_runs_on_a_capture():
    assert_checks_run_on_a_capture(fresh4())


def test_the_command_line_reads_the_split(capsys):
    assert_command_line_reads("fresh4", capsys)


def test_the_report_names_its_categories():
    assert_report_names_categories(fresh4(), "fresh4")
