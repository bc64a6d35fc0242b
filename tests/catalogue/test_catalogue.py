"""The catalogue is the vocabulary: it validates, every check it names exists, the pages and
listings people read are made from it, and no other module grows its own phrase patterns."""

from __future__ import annotations

import json

import pytest
from fastapi.testclient import TestClient

from interplay.api.app import create_app
from interplay.catalogue import listing
from interplay.catalogue.load import PATH, catalogue, read
from interplay.catalogue.schema import specs
from interplay.cli.main import main
from interplay.motion.checks.named import CHECKS, run_check
from interplay.planner.verbs import VERBS, lookup
from interplay.settings import Settings
from tests.helpers.api import FakeGenerator


def test_the_packaged_catalogue_validates_and_names_real_checks():
    cat = read(PATH)
    assert len(cat.action) >= 200
    for a in cat.action:
        for spec in specs(a, count=2, side="left"):
            assert spec["check"] in CHECKS, (a.name, spec)
        if a.counts and not a.made_by.primitive:    # captures are counted by their events
            assert a.counts_as in ("jump", "squat", "kick", "punch", "step"), a.name


def test_verbs_and_their_forms_come_from_the_catalogue():
    assert VERBS["walk"].speed == catalogue().get("walk").speed
    assert lookup("ran")[0].base == "run" and lookup("knelt")[0].base == "kneel"
    assert lookup("hopping")[0].base == "hop"          # the doubled consonant, from `doubles`


def test_a_bad_entry_is_refused_with_its_place(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('[[action]]\nname = "x"\nkind = "gesture"\n', encoding="utf-8")
    with pytest.raises(ValueError, match="needs names or phrases"):
        read(bad)
    bad.write_text('[[action]]\nname = "x"\nkind = "flying"\n', encoding="utf-8")
    with pytest.raises(ValueError, match="action.0.kind"):
        read(bad)


def test_an_entrys_checks_confirm_it_on_a_real_capture():
    from interplay.motion.clip import default_clips
    clip = next(c for c in default_clips() if "jump" in c.prompt.lower() and len(c.people) == 1)
    jump = specs(catalogue().get("jump"))
    assert all(run_check(list(clip.people), s).passed for s in jump), clip.id
    walk = next(c for c in default_clips() if c.prompt.lower().startswith("a person walks") and len(c.people) == 1)
    assert not all(run_check(list(walk.people[:1]), s).passed for s in jump), walk.id


def test_docs_actions_md_is_made_from_the_catalogue():
    doc = listing.DOC.read_text(encoding="utf-8")
    assert doc == listing.markdown(), "run: python -m interplay.catalogue.listing --write"


def test_the_cli_and_the_api_list_the_catalogue(tmp_path, capsys):
    assert main(["actions", "--json", "--kind", "pose"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert {r["name"] for r in rows} == {a.name for a in catalogue().of_kind("pose")}
    settings = Settings(var_dir=tmp_path, frontend_dist=tmp_path / "dist",
                        database_url=f"sqlite:///{tmp_path / 't.db'}", job_queue="embedded")
    with TestClient(create_app(settings, generator=FakeGenerator())) as client:
        body = client.get("/api/actions").json()
        assert body["count"] == len(listing.rows()) and any(r["name"] == "t-pose" for r in body["actions"])
        assert client.get("/api/actions", params={"kind": "manner"}).json()["count"] == len(
            catalogue().of_kind("manner"))
        assert client.get("/api/actions", params={"kind": "nonsense"}).status_code == 422


def test_every_entrys_checks_run_on_a_capture_with_and_without_a_count():
    from interplay.motion.clip import default_clips
    clip = next(c for c in default_clips() if len(c.people) == 1)
    for a in catalogue().action:
        people = list(clip.people) * (2 if a.persons == [2] else 1)    # a two-person entry: two people
        for count, side in ((None, None), (2, "left")):
            for spec in specs(a, count, side):
                run_check(people, spec)                      # raises on a parameter it lacks
    assert specs(catalogue().get("step")) == []             # steps: no count asked, no check
