"""Part-edit prompts in `interplay eval-prompts`' runner: the base motion goes through the
studio's edit (`pipeline.editing.edit_joints`) and the checks compare the edit with its base;
an edit the generator cannot make is a failed output with its reason, not a crash."""

from __future__ import annotations

import numpy as np

from interplay.eval.prompts.report import build_report, format_table, run
from interplay.eval.prompts.rows import Row
from interplay.eval.prompts.suite import Prompt
from interplay.motion import skeleton as sk
from interplay.motion.clip import default_clips

LOOK_UP = Prompt("fresh-x1", "fresh", "edits", "loiter", 1, 3.0,
                 ({"check": "head_pitch_over_base", "direction": "up"},
                  {"check": "rest_unchanged", "part": "head"}),
                 edit={"part": "head", "text": "gaze at the ceiling"})
PLAIN = Prompt("fresh-x2", "fresh", "single", "idle", 1, 3.0, ({"check": "stays_in_place"},))


def _standing() -> np.ndarray:
    return next(np.asarray(c.people[0], np.float32) for c in default_clips()
                if c.label == "respond (normal)")


class HeadTipper:
    """A stand-in editor: tips the head joint 40° back about the neck (looking up)."""
    reason = None
    can_edit = True

    def __init__(self):
        self.calls: list[tuple] = []

    def edit(self, joints, part, prompt, frames=None, seed=None, context=None):
        self.calls.append((part, prompt, context, seed))
        out = np.array(joints, dtype=np.float64)
        bone = out[:, sk.HEAD] - out[:, sk.NECK]
        left = out[:, sk.JOINT_INDEX["left_shoulder"]] - out[:, sk.JOINT_INDEX["right_shoulder"]]
        left /= np.linalg.norm(left, axis=1, keepdims=True)
        a = np.radians(40.0)
        axis = -left
        bone = (bone * np.cos(a) + np.cross(axis, bone) * np.sin(a)
                + axis * (axis * bone).sum(1, keepdims=True) * (1 - np.cos(a)))
        out[:, sk.HEAD] = out[:, sk.NECK] + bone

        class Edit:
            pass
        e = Edit()
        e.joints = out
        return e, {"part": part, "prompt": prompt, "seed": seed}


class NoHead(HeadTipper):
    def edit(self, joints, part, prompt, frames=None, seed=None, context=None):
        raise ValueError(f"unknown body part {part!r}")


def row(editor) -> Row:
    return Row("stub", (1,), lambda req: ([_standing()], {"generator": "stub"}), "a capture",
               editor)


def test_an_edit_prompt_is_judged_on_the_edit_against_its_base():
    editor = HeadTipper()
    results = run([row(editor)], [LOOK_UP, PLAIN], seeds=2)
    edits = [r for r in results if r["id"] == "fresh-x1"]
    assert all(r["all_passed"] for r in edits), edits[0]["checks"]
    assert editor.calls == [("head", "gaze at the ceiling", "loiter", 0),
                            ("head", "gaze at the ceiling", "loiter", 1)]
    # The plain prompt is not edited.
    assert len(editor.calls) == 2 and all(r["all_passed"] for r in results if r["id"] == "fresh-x2")


def test_an_edit_that_does_nothing_fails_its_checks():
    class Idle(HeadTipper):
        def edit(self, joints, part, prompt, frames=None, seed=None, context=None):
            e, entry = super().edit(joints, part, prompt, frames, seed, context)
            e.joints = np.array(joints, dtype=np.float64)
            return e, entry
    results = run([row(Idle())], [LOOK_UP], seeds=1)
    checks = {c["check"]: c["passed"] for c in results[0]["checks"]}
    assert checks == {"head_pitch_over_base": False, "rest_unchanged": True}


def test_an_edit_the_generator_cannot_make_is_a_failed_output_with_its_reason():
    results = run([row(NoHead())], [LOOK_UP, PLAIN], seeds=1)
    failed = next(r for r in results if r["id"] == "fresh-x1")
    assert failed["passed"] == 0 and failed["total"] == 2 and not failed["all_passed"]
    assert "unknown body part 'head'" in failed["error"]
    assert next(r for r in results if r["id"] == "fresh-x2")["all_passed"]
    rows = [row(NoHead())]
    report = build_report(rows, {}, [LOOK_UP, PLAIN], results, "fresh", 1, 1.0)
    assert report["categories"]["edits"] == 1 and report["table"]["stub"]["edits"]["checks"] == 0.0
    assert "part edits" in format_table(report)


def test_a_row_without_an_editor_fails_edit_prompts_only():
    results = run([Row("bare", (1,), lambda req: ([_standing()], {}), "no editor")],
                  [LOOK_UP, PLAIN], seeds=1)
    assert "no editor" in next(r for r in results if r["id"] == "fresh-x1")["error"]
    assert "error" not in next(r for r in results if r["id"] == "fresh-x2")
