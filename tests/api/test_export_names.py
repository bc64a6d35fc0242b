"""Export file names say what the motion is (issue 26): `interplay-<prompt words>-<id>.<ext>`,
slugified (ASCII, lower case, "-"), bounded at a word boundary, in every export's
Content-Disposition; the studio's download names are the same function (filenames.test.ts
checks the same cases)."""

from __future__ import annotations

import pytest

from interplay.api.filenames import MAX_WORDS_CHARS, export_name, slug
from tests.helpers.api import run_job

# the same cases as frontend/src/api/filenames.test.ts
CASES = [
    ("Two people shake hands!", "two-people-shake-hands"),
    ("  a person   walks, then JUMPS twice ", "a-person-walks-then-jumps-twice"),
    ("Café crème — à la française", "cafe-creme-a-la-francaise"),
    ("👋 🙂", ""),
    ("", ""),
    (None, ""),
    ("../../etc/passwd\"; rm -rf", "etc-passwd-rm-rf"),
    ("a person walks forward slowly then turns left and waves at a friend across the street",
     "a-person-walks-forward-slowly-then-turns-left"),
    ("x" * 80, "x" * MAX_WORDS_CHARS),
]


@pytest.mark.parametrize("prompt,words", CASES)
def test_slug(prompt, words):
    assert slug(prompt) == words
    assert len(slug(prompt)) <= MAX_WORDS_CHARS


def test_export_name():
    assert export_name("abc", "Two people hug", "glb") == "interplay-two-people-hug-abc.glb"
    assert export_name("abc", "", "json") == "interplay-abc.json"
    assert export_name("abc", "a jump", "bvh", "-person2") == "interplay-a-jump-abc-person2.bvh"


def test_every_export_is_named_after_its_prompt(fake_client):
    job, _ = run_job(fake_client, prompt="Two people shake hands!", persons=2, seconds=1)
    mid = job["motion_id"]
    want = {("json", None, None): f"interplay-two-people-shake-hands-{mid}.json",
            ("glb", None, None): f"interplay-two-people-shake-hands-{mid}.glb",
            ("glb", None, "false"): f"interplay-two-people-shake-hands-{mid}-skeleton.glb",
            ("bvh", 0, None): f"interplay-two-people-shake-hands-{mid}-person1.bvh",
            ("bvh", 1, None): f"interplay-two-people-shake-hands-{mid}-person2.bvh"}
    for (fmt, person, mesh), name in want.items():
        params = {"format": fmt, **({"person": person} if person is not None else {}),
                  **({"mesh": mesh} if mesh else {})}
        r = fake_client.get(f"/api/motions/{mid}/export", params=params)
        assert r.status_code == 200, r.text
        assert r.headers["content-disposition"] == f'attachment; filename="{name}"'
