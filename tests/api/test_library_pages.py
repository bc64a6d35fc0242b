"""My motions pages through everything a client made (issue 26): `limit` a page, `next` the
cursor of the page after (keyset: motions made meanwhile neither repeat nor shift a page),
`total` all of them; no silent cap at 20 or 50."""

from __future__ import annotations

from tests.api.test_library import A, B, _job


def _page(client, **params):
    r = client.get("/api/motions", params={"client": A, **params})
    assert r.status_code == 200, r.text
    return r.json()


def test_pages_cover_every_motion_once_newest_first(fake_client):
    made = [_job(fake_client, f"a person walks {i}", A) for i in range(7)]
    _job(fake_client, "someone else", B)
    seen, after, pages = [], None, 0
    while True:
        page = _page(fake_client, limit=3, **({"after": after} if after else {}))
        assert page["total"] == 7
        seen += [m["id"] for m in page["motions"]]
        pages += 1
        after = page["next"]
        if after is None:
            break
        assert after == page["motions"][-1]["id"]
    assert pages == 3 and seen == made[::-1]
    # one page that holds them all has no next
    assert _page(fake_client, limit=7)["next"] is None


def test_a_motion_made_meanwhile_does_not_shift_the_next_page(fake_client):
    made = [_job(fake_client, f"a person jumps {i}", A) for i in range(4)]
    first = _page(fake_client, limit=2)
    newer = _job(fake_client, "a person sits down", A)
    second = _page(fake_client, limit=2, after=first["next"])
    assert [m["id"] for m in second["motions"]] == made[::-1][2:]
    assert second["total"] == 5 and newer not in [m["id"] for m in second["motions"]]


def test_a_cursor_of_another_client_or_unknown_is_a_readable_422(fake_client):
    theirs = _job(fake_client, "a person waves", B)
    _job(fake_client, "a person waves", A)
    for after in (theirs, "u" * 22, "not an id!"):
        r = fake_client.get("/api/motions", params={"client": A, "after": after})
        assert r.status_code == 422, r.text
        assert "start from the first page" in r.json()["detail"]
