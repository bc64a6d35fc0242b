"""Stored motions over HTTP: GET, export (BVH per person, Motion JSON), skeleton, the pages
(/, /m/{id}, /assets), share-id shape and entropy, and persistence across a restart."""

from __future__ import annotations

import base64
import re

import numpy as np
import pytest
from fastapi.testclient import TestClient

from interplay.api.app import create_app
from interplay.motion import skeleton as sk
from interplay.motion.motion import Motion
from tests.helpers.api import FakeGenerator, run_job

MISSING = "AAAAAAAAAAAAAAAAAAAAAA"            # well-formed, never handed out
MALFORMED = ["x", "not-an-id!", "%2E%2E%2Fetc", "a" * 300]


@pytest.fixture
def client(real_client):
    return real_client


@pytest.fixture
def two_person(client):
    job, events = run_job(client, prompt="two people dance salsa", persons=2, seconds=2,
                          seed=11)
    assert events[-1]["type"] == "done"
    return job["motion_id"]


@pytest.mark.parametrize("motion_id", [MISSING, *MALFORMED])
def test_unknown_or_malformed_ids_are_404_json(client, motion_id):
    for url in (f"/api/motions/{motion_id}", f"/api/motions/{motion_id}/export?format=bvh"):
        r = client.get(url)
        assert r.status_code == 404, (url, r.text)
        assert "no motion" in r.json()["detail"] or r.json()["detail"] == "not found"


def test_get_carries_the_digests_of_the_jobs_done_event(fake_client):
    job, events = run_job(fake_client, prompt="a person walks", seconds=2, seed=3)
    done = events[-1]
    assert done["type"] == "done" and done["digest"]
    stored = fake_client.get(f"/api/motions/{job['motion_id']}").json()
    assert (stored["digest"], stored["frame_digests"]) == (done["digest"], done["frame_digests"])
    assert len(stored["frame_digests"]) == len(stored["people"][0]["joints"])


@pytest.mark.parametrize("motion_id", [MISSING, MALFORMED[0]])
def test_a_bad_share_link_gets_the_page_with_a_404_status(client, motion_id):
    # The page then asks the API and shows its readable message (not raw JSON).
    r = client.get(f"/m/{motion_id}")
    assert r.status_code == 404 and r.headers["content-type"].startswith("text/html")


def test_json_export_round_trips_through_motion(client, two_person):
    r = client.get(f"/api/motions/{two_person}/export?format=json")
    assert r.status_code == 200
    # interplay-<prompt words>-<id>.<ext> (api/filenames.py)
    assert f'-{two_person}.json"' in r.headers["content-disposition"]
    assert 'filename="interplay-' in r.headers["content-disposition"]
    motion = Motion.from_json(r.json())
    stored = client.get(f"/api/motions/{two_person}").json()
    assert motion.frames == 40 and len(motion.people) == 2 and motion.seed == 11
    for a, b in zip(motion.people, stored["people"]):
        assert np.array_equal(a, np.asarray(b["joints"], dtype=np.float32))
    assert motion.metrics == stored["metrics"] and motion.plan == stored["plan"]


@pytest.mark.parametrize("person", [0, 1])
def test_bvh_export_is_one_person_per_file(client, two_person, person):
    r = client.get(f"/api/motions/{two_person}/export", params={"format": "bvh",
                                                                     "person": person})
    assert r.status_code == 200, r.text
    # named as the studio names people: person=0 is "Person 1", the file "…-person1.bvh"
    assert f"-person{person + 1}.bvh" in r.headers["content-disposition"]
    assert r.text.startswith("HIERARCHY")
    from interplay.motion.formats.bvh import read_bvh
    bvh = read_bvh(r.text)
    joints = np.asarray(client.get(f"/api/motions/{two_person}").json()
                        ["people"][person]["joints"])
    pos = bvh.positions()
    assert pos.shape[0] == joints.shape[0]
    idx = [bvh.names.index(n) for n in sk.JOINT_NAMES]
    assert np.abs(pos[:, idx] - joints).max() < 2e-3


def test_glb_export_is_one_binary_glb_for_both_people(client, two_person):
    import pygltflib
    r = client.get(f"/api/motions/{two_person}/export?format=glb")
    assert r.status_code == 200 and r.headers["content-type"] == "model/gltf-binary"
    assert f'-{two_person}.glb"' in r.headers["content-disposition"]
    doc = pygltflib.GLTF2.load_from_bytes(r.content)
    assert len(doc.skins) == len(doc.meshes) == 2 and len(doc.animations) == 1
    bare = client.get(f"/api/motions/{two_person}/export", params={"format": "glb", "mesh": "false"})
    assert bare.status_code == 200 and len(bare.content) < len(r.content) / 2
    assert f'-{two_person}-skeleton.glb"' in bare.headers["content-disposition"]
    assert pygltflib.GLTF2.load_from_bytes(bare.content).meshes == []


@pytest.mark.parametrize("query,word", [
    ("format=fbx", "format"), ("format=glb&mesh=maybe", "mesh"),
    ("format=bvh&person=2", "person"), ("format=bvh&person=-1", "person"),
    ("format=bvh&person=one", "person")])
def test_bad_export_queries_are_422(client, two_person, query, word):
    r = client.get(f"/api/motions/{two_person}/export?{query}")
    assert r.status_code == 422 and word in r.json()["detail"], r.text


def test_bvh_of_a_missing_second_person_is_422(client):
    job, _ = run_job(client, prompt="a person waves", persons=1, seconds=1)
    r = client.get(f"/api/motions/{job['motion_id']}/export?format=bvh&person=1")
    assert r.status_code == 422 and "1 person" in r.json()["detail"]


def test_skeleton_describes_joints_parts_and_colours(client):
    s = client.get("/api/skeleton").json()
    assert s["joints"] == list(sk.JOINT_NAMES) and s["parents"] == list(sk.PARENTS)
    assert set(s["parts"]) == set(s["colours"]) == set(sk.PART_NAMES)
    for j, part in enumerate(s["joint_part"]):
        assert j in s["parts"][part], (sk.JOINT_NAMES[j], part)
    rest = np.asarray(s["rest"])
    assert rest.shape == (22, 3) and rest[sk.HEAD, 1] > rest[sk.PELVIS, 1] > rest[sk.LEFT_FOOT, 1]


def test_ids_are_url_safe_unguessable_and_distinct(client):
    ids = []
    for _ in range(4):
        job = client.post("/api/jobs", json={"prompt": "a person walks", "seconds": 1}).json()
        ids += [job["job_id"], job["motion_id"]]
    assert len(set(ids)) == len(ids)
    for i in ids:
        assert re.fullmatch(r"[A-Za-z0-9_-]{22,}", i)
        assert len(base64.urlsafe_b64decode(i + "=" * (-len(i) % 4))) >= 16   # ≥ 128 bits
    # 8 ids × 22 chars of random base64: a character should not dominate.
    chars = "".join(ids)
    assert max(chars.count(c) for c in set(chars)) < len(chars) / 8


def test_pages_without_a_build_say_how_to_make_one(client, two_person):
    for url in ("/", f"/m/{two_person}"):
        r = client.get(url)
        assert r.status_code == 200 and "make run" in r.text
    assert client.get("/assets/index.js").status_code == 404
    assert client.get("/docs").status_code == 200
    assert "/api/jobs" in client.get("/openapi.json").json()["paths"]


def test_pages_serve_the_built_front_end(client, settings, two_person):
    dist = settings.frontend_dist
    (dist / "assets").mkdir(parents=True)
    (dist / "index.html").write_text("<!doctype html><div id=root></div>")
    (dist / "assets" / "index-abc.js").write_text("console.log(1)")
    (dist / "favicon.svg").write_text("<svg/>")
    (settings.var_dir / "secret.txt").write_text("no")
    for url in ("/", f"/m/{two_person}"):
        r = client.get(url)
        assert r.status_code == 200 and "id=root" in r.text, url
    r = client.get("/assets/index-abc.js")
    assert r.status_code == 200 and r.text == "console.log(1)" and "immutable" in r.headers[
        "cache-control"]
    assert client.get("/favicon.svg").text == "<svg/>"
    for url in ("/assets/missing.js", "/assets/..%2Findex.html",
                "/assets/%2E%2E/%2E%2E/var/secret.txt", "/nothing-here"):
        r = client.get(url)
        assert r.status_code == 404 and r.headers["content-type"].startswith("text/html"), url
        assert "This page does not exist" in r.text, url      # never the file itself


@pytest.mark.parametrize("url", ["/m/", "/nothing-here", "/m/abc/def", "/some/deep/path",
                                 "/apidocs", "/%3Cscript%3Ealert(1)%3C/script%3E"])
def test_unknown_pages_get_an_html_404_page(fake_client, url):
    r = fake_client.get(url)
    assert r.status_code == 404, url
    assert r.headers["content-type"].startswith("text/html"), (url, r.headers)
    assert "This page does not exist" in r.text and 'href="/"' in r.text
    assert "<script>" not in r.text           # the path is shown escaped
    css = fake_client.get("/not-found.css")      # its style: a file (no inline styles under the CSP)
    assert css.status_code == 200 and css.headers["content-type"].startswith("text/css")


@pytest.mark.parametrize("url", ["/api/nothing", "/api/motions/AAAAAAAAAAAAAAAAAAAAAA",
                                 "/api/jobs/AAAAAAAAAAAAAAAAAAAAAA", "/api"])
def test_api_paths_keep_json_404s(fake_client, url):
    r = fake_client.get(url)
    assert r.status_code == 404, url
    assert r.headers["content-type"].startswith("application/json"), url
    assert r.json()["detail"]


def test_a_motion_reopens_identically_after_a_restart(settings, real_generator):
    with TestClient(create_app(settings, generator=real_generator)) as first:
        job, events = run_job(first, prompt="two people dance", persons=2, seconds=1.5, seed=5)
        before = first.get(f"/api/motions/{job['motion_id']}").json()
        bvh_before = first.get(f"/api/motions/{job['motion_id']}/export?format=bvh&person=1").text
    with TestClient(create_app(settings, generator=FakeGenerator())) as second:
        after = second.get(f"/api/motions/{job['motion_id']}")
        assert after.status_code == 200 and after.json() == before
        assert second.get(f"/api/motions/{job['motion_id']}/export?format=bvh&person=1").text \
            == bvh_before
        assert second.get(f"/m/{job['motion_id']}").status_code == 200
