"""The built front end: / and /m/{id} serve index.html, /assets/* the Vite bundle, and other
files at the top of the dist dir (favicon …). Without a build, / says how to make one. Any
other path a browser asks for gets an HTML 404 page (`not_found_page`, from the app's error
handler); /api/* keeps its JSON errors."""

from __future__ import annotations

import html
from pathlib import Path

from fastapi import APIRouter, HTTPException
from fastapi.responses import FileResponse, HTMLResponse, Response

from interplay.api.deps import RepoDep, SettingsDep

router = APIRouter(include_in_schema=False)

NO_BUILD = """<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Interplay</title></head>
<body style="font-family: sans-serif; max-width: 40em; margin: 4em auto">
<h1>Interplay</h1><p>The front end has not been built yet. Run <code>make run</code> in the
repository (it builds <code>frontend/dist</code> and starts the server), then reload.</p>
<p>The API is up: see <a href="/docs">/docs</a>.</p></body></html>"""


# Its style is a same-origin file (the Content-Security-Policy takes no inline styles).
NOT_FOUND_CSS = """:root { color-scheme: dark light; --bg: #0f1115; --text: #e6e8ee; --muted: #8b93a5;
  --accent: #7aa2ff; }
@media (prefers-color-scheme: light) {
  :root { --bg: #f5f6f8; --text: #1b1f27; --muted: #5d6678; --accent: #2f64e0; } }
body { margin: 0; min-height: 100vh; display: grid; place-items: center; background: var(--bg);
  color: var(--text); font: 16px/1.5 "Inter", "Segoe UI", system-ui, "DejaVu Sans", sans-serif; }
main { max-width: 32em; padding: 24px; }
h1 { font-size: 22px; margin: 0 0 8px; }
p { margin: 0 0 12px; color: var(--muted); }
code { color: var(--text); word-break: break-all; }
a { color: var(--accent); }
"""
NOT_FOUND = """<!doctype html><html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>Not found · Interplay</title><link rel="stylesheet" href="/not-found.css"></head>
<body><main data-testid="not-found">
<h1>This page does not exist</h1>
<p>Nothing lives at <code>{path}</code>. A motion's link looks like <code>/m/&lt;id&gt;</code>.</p>
<p><a href="/">Open the Interplay studio</a></p>
</main></body></html>"""

# Paths whose errors stay JSON: the API, its schema and its docs pages.
_API_PREFIXES = ("/api/", "/openapi.json", "/docs", "/redoc")


def wants_page(path: str) -> bool:
    """A 404 at this path is answered with the HTML page (not /api/*)."""
    return path != "/api" and not path.startswith(_API_PREFIXES)


def not_found_page(path: str) -> HTMLResponse:
    """The HTML 404 page, naming the path asked for (escaped)."""
    return HTMLResponse(NOT_FOUND.replace("{path}", html.escape(path[:300])), status_code=404)


def _index(dist: Path, status_code: int = 200):
    index = dist / "index.html"
    if not index.is_file():
        return HTMLResponse(NO_BUILD, status_code=status_code)
    # The page is tiny and names hashed assets: always revalidate it.
    return FileResponse(index, media_type="text/html", status_code=status_code,
                        headers={"Cache-Control": "no-cache"})


def _file_under(root: Path, rel: str) -> Path:
    """`root/rel` if it is a file inside `root` (no escaping with .. or symlinks), else 404."""
    try:
        base = root.resolve(strict=True)
        path = (base / rel).resolve(strict=True)
    except (OSError, RuntimeError):
        raise HTTPException(404, "not found") from None
    if not path.is_relative_to(base) or not path.is_file():
        raise HTTPException(404, "not found")
    return path


@router.get("/")
def index(settings: SettingsDep):
    return _index(settings.frontend_dist)


@router.get("/m/{motion_id}")
def motion_page(motion_id: str, settings: SettingsDep, repo: RepoDep):
    # A bad share link still gets the page (with a 404 status): it asks the API for the motion
    # and shows the API's readable message, instead of leaving a person with raw JSON.
    return _index(settings.frontend_dist, 200 if repo.exists(motion_id) else 404)


@router.get("/assets/{path:path}")
def asset(path: str, settings: SettingsDep):
    # Hashed file names: cache for a year.
    return FileResponse(_file_under(settings.frontend_dist / "assets", path),
                        headers={"Cache-Control": "public, max-age=31536000, immutable"})


@router.get("/not-found.css")
def not_found_css() -> Response:
    return Response(NOT_FOUND_CSS, media_type="text/css", headers={"Cache-Control": "public, max-age=3600"})


@router.get("/{name}")
def top_file(name: str, settings: SettingsDep):
    return FileResponse(_file_under(settings.frontend_dist, name))
