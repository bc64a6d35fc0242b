"""The motion store on real capture data, on SQLite and on a real PostgreSQL: exact round trip
of joints, ids, listing, versions, input checks, and reopening the same database from a second
engine (a server restart)."""

from __future__ import annotations

import base64
from datetime import datetime, timezone

import numpy as np
import pytest

from interplay.motion.clip import DATA_DIR, default_clips
from interplay.settings import Settings, get_settings
from interplay.store import MotionRepository, make_engine, valid_id


@pytest.fixture(scope="module")
def salsa():
    """A real two-person clip (CMU salsa) and a real one-person clip from the processed set."""
    clips = default_clips(str(get_settings().data_dir or DATA_DIR))
    two = next(c for c in clips if len(c.people) == 2)
    one = next(c for c in clips if len(c.people) == 1)
    return two, one


@pytest.fixture(params=["sqlite", "postgres"])
def url(request, tmp_path):
    """A SQLite file in a folder not made yet, or an empty database on a real PostgreSQL."""
    if request.param == "postgres":
        return Settings(database_url=request.getfixturevalue("pg_url")).db_url
    return f"sqlite:///{tmp_path / 'nested' / 'interplay.db'}"


def test_create_get_round_trips_real_clips_exactly(url, salsa):
    repo = MotionRepository(make_engine(url))
    for clip in salsa:
        people = [p[:80] for p in clip.people]
        plan = {"segments": [{"prompt": clip.prompt, "start": 0, "end": 80,
                              "persons": list(range(len(people)))}]}
        m = repo.create(prompt=clip.prompt, people=people, seconds=4.0, seed=9, plan=plan,
                        metrics={"foot_skating": 0.12}, highlights={"contacts": [[]] * 80})
        back = repo.get(m.id)
        assert back.persons == len(people) and back.frames == 80 and back.seconds == 4.0
        for a, b in zip(back.people, people):
            assert a.dtype == np.float32 and np.array_equal(a, b.astype(np.float32))
        assert (back.prompt, back.seed, back.plan, back.metrics) == (clip.prompt, 9, plan,
                                                                     {"foot_skating": 0.12})
        assert back.created_at.tzinfo is not None
        assert abs((datetime.now(timezone.utc) - back.created_at).total_seconds()) < 60


def test_ids_are_128_bit_url_safe_and_checked(url, salsa):
    repo = MotionRepository(make_engine(url))
    ids = {repo.create(prompt="p", people=[salsa[1].people[0][:5]], seconds=1).id
           for _ in range(20)}
    assert len(ids) == 20
    for i in ids:
        assert valid_id(i) and len(base64.urlsafe_b64decode(i + "==")) >= 16
    for bad in ("", "short", "../../etc/passwd", "a" * 65, "has space in it 1234567"):
        assert not valid_id(bad) and repo.get(bad) is None and not repo.exists(bad)
    assert repo.get("A" * 22) is None


def test_list_is_newest_first_and_versions_point_at_parents(url, salsa):
    repo = MotionRepository(make_engine(url))
    joints = salsa[1].people[0][:10]
    first = repo.create(prompt="a person walks", people=[joints], seconds=1)
    edit = repo.create(prompt="a person walks, waving", people=[joints + 0.01], seconds=1,
                       parent_id=first.id)
    listed = repo.list()
    assert [m.id for m in listed] == [edit.id, first.id]
    assert listed[0].parent_id == first.id and listed[0].frames == 10
    assert [m.id for m in repo.list(limit=1, offset=1)] == [first.id]


@pytest.mark.parametrize("people,msg", [
    ([], "at least one person"),
    ([np.zeros((10, 21, 3))], "(T, 22, 3)"),
    ([np.zeros((10, 22, 3)), np.zeros((9, 22, 3))], "same shape"),
    ([np.full((4, 22, 3), np.nan)], "NaN"),
])
def test_bad_joints_are_refused(url, people, msg):
    repo = MotionRepository(make_engine(url))
    with pytest.raises(ValueError, match=msg.replace("(", r"\(").replace(")", r"\)")):
        repo.create(prompt="p", people=people, seconds=1)
    assert repo.list() == []


def test_a_second_engine_on_the_same_file_reads_the_same_motion(url, salsa):
    two = salsa[0]
    first_engine = make_engine(url)
    m = MotionRepository(first_engine).create(prompt=two.prompt, people=two.people, seconds=3,
                                              seed=1, highlights={"min_distance": [0.3]})
    first_engine.dispose()
    again = MotionRepository(make_engine(url)).get(m.id)
    assert again is not None and again.created_at == m.created_at
    for a, b in zip(again.people, m.people):
        assert np.array_equal(a, b)
    assert again.highlights == {"min_distance": [0.3]}
