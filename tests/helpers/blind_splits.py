"""What every blind prompt split (`fresh2`, `fresh3`, `fresh4`) must hold, shared by their
tests: each check and parameter it names exists and runs on a capture, and the command line and
the report take the split."""

from __future__ import annotations

import inspect
import json

import numpy as np

from interplay.eval.prompts.report import build_report, format_table
from interplay.eval.prompts.suite import Prompt, category_labels
from interplay.motion.checks.named import CHECKS, run_check
from interplay.motion.clip import default_clips


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
