"""Security headers on pages and API responses (a CSP the built studio works with), Retry-After
on every 429, and the WebSocket Origin check against the served host."""

from __future__ import annotations

import re
import shutil

import pytest
from fastapi import HTTPException
from fastapi.responses import JSONResponse
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect

from interplay.api.app import create_app
from interplay.api.security import CSP, DOCS_CSP
from interplay.settings import Settings
from tests.helpers.api import FakeGenerator, run_job
from tests.helpers.paths import REPO

DIST = REPO / "frontend" / "dist"


@pytest.fixture
def settings(tmp_path) -> Settings:
    """SQLite only (overrides the conftest's SQLite + PostgreSQL pair): nothing here depends on
    the database."""
    return Settings(var_dir=tmp_path / "var", frontend_dist=tmp_path / "dist",
                    database_url=f"sqlite:///{tmp_path / 'var' / 'test.db'}", job_queue="embedded")
COMMON = {"x-content-type-options": "nosniff", "x-frame-options": "DENY",
          "referrer-policy": "same-origin"}


def _directives(csp: str) -> dict[str, list[str]]:
    return {d.split()[0]: d.split()[1:] for d in csp.split(";") if d.strip()}


@pytest.fixture
def studio(settings, tmp_path):
    """The app serving a copy of the built front end (or a stand-in page without a build)."""
    dist = tmp_path / "dist"
    if (DIST / "index.html").exists():
        shutil.copytree(DIST, dist)
    app = create_app(settings.model_copy(update={"frontend_dist": dist}), generator=FakeGenerator())

    @app.get("/test/busy")
    def busy():                      # a 429 made without the header
        raise HTTPException(429, "busy")

    @app.get("/test/busy-response")
    def busy_response():             # a 429 returned, not raised
        return JSONResponse({"detail": "busy"}, status_code=429)

    @app.get("/test/busy-own")
    def busy_own():                  # a 429 that says its own Retry-After (the job queue's)
        raise HTTPException(429, "busy", headers={"Retry-After": "17"})

    with TestClient(app) as client:
        yield client


@pytest.mark.parametrize("path,status", [
    ("/", 200), ("/m/unknownmotionunknownmo", 404), ("/api/skeleton", 200),
    ("/api/motions/nope", 404), ("/openapi.json", 200), ("/no/such/thing", 404),
])
def test_every_response_has_the_security_headers(studio, path, status):
    r = studio.get(path)
    assert r.status_code == status
    for key, value in COMMON.items():
        assert r.headers[key] == value, key
    csp = _directives(r.headers["content-security-policy"])
    assert csp["frame-ancestors"] == ["'none'"] and csp["object-src"] == ["'none'"]
    assert csp["script-src"] == ["'self'"] and "'unsafe-inline'" not in r.headers["content-security-policy"]


def test_errors_and_413_have_them_too(studio):
    r = studio.post("/api/jobs", json={"prompt": ""})
    assert r.status_code == 422 and r.headers["x-content-type-options"] == "nosniff"
    assert "content-security-policy" in r.headers


def test_the_policy_allows_what_the_built_studio_loads():
    """Every script, style sheet, icon and preload of the built index.html is same-origin (or
    a data: URL where the policy allows one), nothing is inline, and the bundle evaluates no
    strings as code: the CSP does not break the studio."""
    html_path = DIST / "index.html"
    if not html_path.exists():
        pytest.skip("no front-end build (make run builds it)")
    html = html_path.read_text()
    csp = _directives(CSP)
    assert not re.search(r"<script(?![^>]*\bsrc=)[^>]*>", html), "inline script"
    assert "<style" not in html and not re.search(r"\sstyle=", html), "inline style"
    assert not re.search(r"\son[a-z]+\s*=", html, re.IGNORECASE), "inline event handler"
    for tag, url in re.findall(r"<(script|link)[^>]*?(?:src|href)=\"([^\"]+)\"", html):
        if url.startswith("data:"):
            assert tag == "link" and "data:" in csp["img-src"], url      # the favicon
        else:
            assert url.startswith("/") and not url.startswith("//"), url  # same origin
    for js in (DIST / "assets").glob("*.js"):
        code = js.read_text()
        assert "eval(" not in code and "new Function(" not in code, js.name
    assert "'self'" in csp["connect-src"]          # fetch /api/… and the ws:// stream


def test_the_docs_pages_get_the_policy_their_cdn_bundles_need(studio):
    r = studio.get("/docs")
    assert r.status_code == 200 and r.headers["content-security-policy"] == DOCS_CSP
    for src in re.findall(r"src=\"(https://[^/\"]+)", r.text):
        assert src in _directives(DOCS_CSP)["script-src"], src
    assert r.headers["x-frame-options"] == "DENY"


def test_every_429_carries_retry_after(studio, settings):
    for path in ("/test/busy", "/test/busy-response"):
        r = studio.get(path)
        assert r.status_code == 429 and r.headers["retry-after"] == str(settings.retry_after_s)
    r = studio.get("/test/busy-own")
    assert r.headers.get_list("retry-after") == ["17"]            # kept, not doubled
    assert studio.get("/api/skeleton").headers.get("retry-after") is None


# ---- WebSocket origin ---------------------------------------------------------------------

def _open(client, job, headers):
    return client.websocket_connect(job["stream"], headers=headers)


@pytest.mark.parametrize("origin", ["https://evil.example", "http://testserver.evil.example",
                                    "http://testserver:8001", "null", "file://"])
def test_a_websocket_from_a_foreign_origin_is_closed_with_4403(fake_client, origin):
    job, _ = run_job(fake_client, prompt="a person walks", seconds=1)
    with pytest.raises(WebSocketDisconnect) as exc:
        with _open(fake_client, job, {"origin": origin}) as ws:
            ws.receive_json()
    assert exc.value.code == 4403 and "is not allowed" in exc.value.reason


@pytest.mark.parametrize("headers", [{}, {"origin": "http://testserver"},
                                     {"origin": "https://TestServer:443", "host": "testserver"},
                                     {"origin": "http://testserver:80"}])
def test_same_origin_and_origin_less_clients_stream(fake_client, headers):
    job, _ = run_job(fake_client, prompt="a person walks", seconds=1)
    with _open(fake_client, job, headers) as ws:
        assert ws.receive_json()["type"] == "plan"


def test_extra_allowed_origins(settings):
    app = create_app(settings.model_copy(update={"allowed_origins": "http://localhost:5173, "
                                                                    "https://studio.example"}),
                     generator=FakeGenerator())
    with TestClient(app) as client:
        job, _ = run_job(client, prompt="a person walks", seconds=1)
        for origin in ("http://localhost:5173", "https://studio.example"):
            with _open(client, job, {"origin": origin}) as ws:
                assert ws.receive_json()["type"] == "plan"
        with pytest.raises(WebSocketDisconnect) as exc:
            with _open(client, job, {"origin": "https://other.example"}) as ws:
                ws.receive_json()
        assert exc.value.code == 4403
