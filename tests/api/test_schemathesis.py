"""A bounded schemathesis run over every operation of the OpenAPI schema, in-process against the
ASGI app (a fake generator, SQLite): requests made from the schema, valid ones and invalid
ones, must never get a server error (5xx), and every JSON error says what was wrong in a
string `detail`. Small on purpose (MAX_EXAMPLES per operation and mode, derandomized, no
example database): a smoke run in the suite; SCHEMATHESIS_MAX_EXAMPLES=500 for a longer one.
(Driven through hypothesis directly: schemathesis' own pytest plugin does not run under
pytest 9.)"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

import pytest
import schemathesis
from hypothesis import HealthCheck, given, settings
from hypothesis.errors import Unsatisfiable
from schemathesis import GenerationMode
from schemathesis.python import asgi

from interplay.api.app import create_app
from interplay.settings import Settings
from tests.helpers.api import FakeGenerator

MAX_EXAMPLES = int(os.environ.get("SCHEMATHESIS_MAX_EXAMPLES", "15"))
_TMP = Path(tempfile.mkdtemp(prefix="interplay-schemathesis-"))
APP = create_app(Settings(var_dir=_TMP / "var", frontend_dist=_TMP / "dist",
                          database_url=f"sqlite:///{_TMP / 'var' / 'test.db'}",
                          job_queue="embedded", max_pending_jobs=4),
                 generator=FakeGenerator())
SCHEMA = schemathesis.openapi.from_asgi("/openapi.json", APP)
OPERATIONS = {r.ok().label: r.ok() for r in SCHEMA.get_all_operations()}


@pytest.fixture(scope="module", autouse=True)
def _app_lifespan():
    yield                           # schemathesis starts the app's lifespan on the first call
    asgi.shutdown_lifespans()       # and this ends it: job threads, database


def test_every_operation_is_covered():
    assert {"POST /api/jobs", "GET /api/jobs/{job_id}", "POST /api/motions/{motion_id}/edit",
            "GET /api/motions/{motion_id}/export", "GET /api/skeleton"} <= set(OPERATIONS)


@pytest.mark.parametrize("mode", [GenerationMode.POSITIVE, GenerationMode.NEGATIVE],
                         ids=["valid", "invalid"])
@pytest.mark.parametrize("label", sorted(OPERATIONS))
def test_no_request_gets_a_server_error(label, mode):
    @given(case=OPERATIONS[label].as_strategy(generation_mode=mode))
    @settings(max_examples=MAX_EXAMPLES, deadline=None, database=None, derandomize=True,
              suppress_health_check=list(HealthCheck))
    def check(case):
        response = case.call()
        assert response.status_code < 500, (response.status_code, response.text[:500],
                                            case.as_curl_command())
        content_type = (response.headers.get("content-type") or [""])[0]
        if response.status_code >= 400 and content_type.startswith("application/json"):
            detail = response.json().get("detail")
            assert isinstance(detail, str) and detail, response.text[:500]
    try:
        check()
    except Unsatisfiable:
        # Only for invalid requests, where the schema leaves none to make (a free string id).
        assert mode == GenerationMode.NEGATIVE
        pytest.skip(f"no invalid request can be made from the schema of {label}")
