"""What every blind prompt split (`fresh2`, `fresh3`, `fresh4`) must hold, shared by their
tests: its file holds it alone, every two-person prompt checks something between the two, ids
and prompts are unique and new, each check and parameter it names exists and runs on a capture,
and the command line and the report take the split."""

from __future__ import annotations

import collections
import inspect
import json
from pathlib import Path

import numpy as np

from interplay.eval.prompts.report import build_report, format_table
from interplay.eval.prompts.suite import SPLIT_FILES, SPLITS, Prompt, category_labels, load_split, load_suite
from interplay.motion.checks.named import CHECKS, run_check
from interplay.motion.clip import default_clips


def assert_file_holds_only(split: str, path: Path, blind: bool = True) -> list[Prompt]:
    """The split's file validates, holds that split alone and is the suite's file for it; its
    prompts."""
    raw = json.loads(path.read_text())
    assert {"about", "version", "prompts"} <= set(raw)
    if blind:
        assert "blind" in raw["about"]
    ps = load_split(split)
    assert len(ps) == len(raw["prompts"]) == len(load_suite(path))
    assert collections.Counter(p.split for p in ps) == {split: len(ps)}
    assert split in SPLITS and SPLIT_FILES[split] == path
    return ps


def assert_pairs_check_between(two: list[Prompt]) -> None:
    """Every two-person prompt checks something between the two people."""
    assert all(any(CHECKS[c["check"]].persons == 2 or c.get("person") == "both" for c in p.checks)
               for p in two)


def assert_unique_and_new(prompts: list[Prompt], others: list[Prompt], texts_new: bool = True) -> None:
    """Ids and prompt texts unique within the split; ids (and texts, unless `texts_new` is off)
    in none of `others`. Only the repeats are named: a failure must not print the other splits'
    prompts."""
    ids = [p.id for p in prompts]
    assert len(set(ids)) == len(ids)
    texts = [p.prompt.lower() for p in prompts]
    assert len(set(texts)) == len(texts)
    assert not set(ids) & {p.id for p in others}
    if texts_new:
        repeated = sorted(set(texts) & {p.prompt.lower() for p in others})
        assert not repeated


def assert_checks_and_parameters_exist(prompts: list[Prompt]) -> None:
    for p in prompts:
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


def assert_checks_run_on_a_capture(prompts: list[Prompt]) -> None:
    walk = next(c for c in default_clips() if c.label == "walk").people[0]
    for p in prompts:
        people = [walk, walk + np.array([1.0, 0, 0])] if p.persons == 2 else [walk]
        for spec in p.checks:
            r = run_check(people, spec)
            assert isinstance(r.passed, bool) and r.bound, (p.id, spec)
            json.dumps(r.to_json())


def assert_command_line_reads(split: str, capsys) -> None:
    from interplay.cli.main import build_parser, main
    assert main(["eval-prompts", "--split", split, "--ids", "no-such-id"]) == 2
    assert f"no prompts in split '{split}' with ids no-such-id" in capsys.readouterr().err
    args = build_parser().parse_args(["review-eval", "--honesty", "--split", split])
    assert args.split == split


def assert_report_names_categories(prompts: list[Prompt], split: str) -> None:
    report = build_report([], {}, prompts, [], split, 1, 0.0)
    assert report["categories"]["everyday"] == sum(p.persons == 1 for p in prompts)
    assert report["categories"]["two_person"] == sum(p.persons == 2 for p in prompts)
    text = format_table(report)
    assert category_labels(split)["everyday"] in text and "(dev)" not in text
    assert category_labels("dev")["everyday"] != category_labels(split)["everyday"]
