"""The built front end: / and /m/{id} serve index.html, /assets/* the Vite bundle, and other
files at the top of the dist dir (favicon …). Without a build, / says how to make one."""

from __future__ import annotations

from pathlib import Path

from fastapi import APIRouter, HTTPException
from fastapi.responses import FileResponse, HTMLResponse

from interplay.api.deps import RepoDep, SettingsDep

router = APIRouter(include_in_schema=False)

NO_BUILD = """<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Interplay</title></head>
<body style="font-family: sans-serif; max-width: 40em; margin: 4em auto">
<h1>Interplay</h1><p>The front end has not been built yet. Run <code>make run</code> in the
repository (it builds <code>frontend/dist</code> and starts the server), then reload.</p>
<p>The API is up: see <a href="/docs">/docs</a>.</p></body></html>"""


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


@router.get("/{name}")
def top_file(name: str, settings: SettingsDep):
    return FileResponse(_file_under(settings.frontend_dist, name))
