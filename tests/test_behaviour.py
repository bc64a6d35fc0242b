"""The package layout can move files without changing what users get: ten fixed cases (SPAM,
CODA, retrieval for one and two people, a drawn and a preset path, a part edit, a reaction)
run through the API give exactly the motion JSON committed in tests/fixtures/behaviour/,
which the code before the move made (tests/fixtures/make_behaviour.py)."""

from __future__ import annotations

import json

import pytest

from tests.fixtures import make_behaviour


@pytest.fixture(scope="module")
def generated(tmp_path_factory):
    clients = make_behaviour.clients(tmp_path_factory.mktemp("behaviour"))
    for c in clients.values():
        c.__enter__()
    try:
        yield make_behaviour.generate_all(clients)
    finally:
        for c in clients.values():
            c.__exit__(None, None, None)


@pytest.mark.parametrize("name", [c[0] for c in make_behaviour.CASES])
def test_motion_json_is_unchanged(generated, name):
    expected = json.loads((make_behaviour.OUT / f"{name}.json").read_text())
    got = json.loads(json.dumps(generated[name], sort_keys=True))
    assert got["people"] == expected["people"], f"{name}: joints differ"
    assert got == expected
