"""The API's 422s are plain words (issue 26): "seconds must be at most 20 (got 999)", never
pydantic's "Input should be less than or equal to 20" nor a list; the field stays named first."""

from __future__ import annotations

import pytest

from interplay.pipeline.messages import plain

JOB = {"prompt": "a person walks", "persons": 1, "seconds": 2}


@pytest.mark.parametrize("body,detail", [
    ({**JOB, "seconds": 999}, "seconds must be at most 20 (got 999)"),
    ({**JOB, "seconds": 0}, "seconds must be at least 1 (got 0)"),
    ({**JOB, "seconds": -3}, "seconds must be at least 1 (got -3)"),
    ({**JOB, "persons": 3}, "persons must be 1 or 2 (got 3)"),
    ({**JOB, "seed": "7"}, 'seed must be a whole number (got "7")'),
    ({**JOB, "seed": -1}, "seed must be at least 0 (got -1)"),
    ({**JOB, "prompt": "   "}, "prompt must not be empty"),
    ({**JOB, "prompt": "x" * 10_000}, "prompt is 10000 characters long; the limit is 500"),
    ({**JOB, "seconds": True}, "seconds must be a number (got true)"),
    ({**JOB, "trajectory": {"shape": "circle", "size_m": 300}}, "trajectory: size_m must be at most 50"),
    ({**JOB, "seconds": 999, "persons": 3},
     "persons must be 1 or 2 (got 3); seconds must be at most 20 (got 999)"),
])
def test_job_422s_are_plain_words(fake_client, body, detail):
    r = fake_client.post("/api/jobs", json=body)
    assert r.status_code == 422, r.text
    assert r.json()["detail"] == detail
    assert "Input should" not in r.text and "Value error" not in r.text


def test_query_and_export_422s_are_plain_words(fake_client):
    r = fake_client.get("/api/motions", params={"client": "A" * 22, "limit": 99})
    assert r.json()["detail"] == 'limit must be at most 50 (got "99")'
    r = fake_client.get("/api/motions", params={"client": "A" * 22, "limit": "many"})
    assert r.json()["detail"] == 'limit must be a whole number (got "many")'
    r = fake_client.get("/api/motions", params={"client": "short"})
    assert r.json()["detail"] == 'client is not in the expected form (got "short")'
    r = fake_client.get("/api/motions/x/export", params={"format": "x"})
    assert r.json()["detail"] == 'format must be \'bvh\', \'glb\' or \'json\' (got "x")'


def test_plain_rewords_nested_messages():
    assert plain("segments.0.trajectory: size_m: Input should be greater than 0") == \
        "segments.0.trajectory: size_m must be more than 0"
    assert plain("Field required") == "is required"
    assert plain("List should have at most 3 items after validation, not 5") == \
        "must have at most 3 items (it has 5)"
