"""HTTP hardening for every request and response (`install(app, settings)` in the app factory):

- a request-body limit (`INTERPLAY_MAX_BODY_BYTES`, 256 KiB): a larger body is answered 413 with
  a readable JSON message before anything parses it, whether it declares a Content-Length or
  streams without one (the bytes are counted as they arrive, at most limit + one chunk is held);
- security headers on every response, pages and API alike: a Content-Security-Policy the built
  studio works with (its scripts, styles and fetches are same-origin; images may be data: or
  blob: URLs), a looser one for FastAPI's /docs and /redoc pages (their CDN scripts and
  inline start-up script), X-Content-Type-Options nosniff, X-Frame-Options DENY with
  frame-ancestors 'none', Referrer-Policy same-origin;
- `Retry-After` on every 429 that does not already carry one (`INTERPLAY_RETRY_AFTER_S`, 5 s),
  whichever route or exception made it;
- `origin_allowed(websocket)`: the WebSocket Origin check against the served host.
"""

from __future__ import annotations

import json
from typing import Any
from urllib.parse import urlsplit

from fastapi import HTTPException
from starlette.types import ASGIApp, Message, Receive, Scope, Send
from starlette.websockets import WebSocket

CSP = "; ".join([
    "default-src 'self'",
    "script-src 'self'",
    "style-src 'self'",
    "img-src 'self' data: blob:",
    "font-src 'self' data:",
    "connect-src 'self'",
    "worker-src 'self' blob:",
    "object-src 'none'",
    "base-uri 'self'",
    "form-action 'self'",
    "frame-ancestors 'none'",
])
# FastAPI's Swagger UI and ReDoc pages load their bundles from jsDelivr, start with an inline
# script, and ReDoc takes Google fonts and a blob: worker. Nothing user-made is on them.
DOCS_CSP = "; ".join([
    "default-src 'self'",
    "script-src 'self' 'unsafe-inline' https://cdn.jsdelivr.net",
    "style-src 'self' 'unsafe-inline' https://cdn.jsdelivr.net https://fonts.googleapis.com",
    "img-src 'self' data: https://fastapi.tiangolo.com https://cdn.redoc.ly",
    "font-src 'self' data: https://fonts.gstatic.com",
    "connect-src 'self'",
    "worker-src 'self' blob:",
    "object-src 'none'",
    "base-uri 'self'",
    "frame-ancestors 'none'",
])
HEADERS = {
    "x-content-type-options": "nosniff",
    "x-frame-options": "DENY",
    "referrer-policy": "same-origin",
    "cross-origin-opener-policy": "same-origin",
}
WS_FORBIDDEN = 4403        # close code for a WebSocket from a foreign origin


def too_large_message(limit: int, declared: int | None = None) -> str:
    size = f"{declared} bytes" if declared is not None else "longer"
    return f"request body too large: the limit is {limit} bytes, this one is {size}"


class _TooLarge(HTTPException):
    """Raised while the body is read past the limit; an HTTPException so that FastAPI's body
    parsing passes it on (it turns other errors into 400) and the app answers 413."""

    def __init__(self, limit: int) -> None:
        super().__init__(413, too_large_message(limit))


class Hardening:
    """ASGI middleware: the body limit, the headers and Retry-After (see the module doc)."""

    def __init__(self, app: ASGIApp, max_body: int, retry_after_s: int,
                 docs_paths: frozenset[str]) -> None:
        self.app, self.max_body, self.retry_after = app, max_body, str(retry_after_s)
        self.docs_paths = docs_paths

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        csp = DOCS_CSP if scope.get("path") in self.docs_paths else CSP
        started = False

        async def send_hardened(message: Message) -> None:
            nonlocal started
            if message["type"] == "http.response.start":
                started = True
                headers = [(k, v) for k, v in message.get("headers", [])]
                have = {k.decode("latin-1").lower() for k, _ in headers}
                extra = {**HEADERS, "content-security-policy": csp}
                if message["status"] == 429:
                    extra["retry-after"] = self.retry_after
                headers += [(k.encode(), v.encode()) for k, v in extra.items() if k not in have]
                message = {**message, "headers": headers}
            await send(message)

        declared = _content_length(scope)
        if declared is not None and declared > self.max_body:
            await self._too_large(send_hardened, declared)
            return
        received = 0

        async def receive_counted() -> Message:
            nonlocal received
            message = await receive()
            if message["type"] == "http.request":
                received += len(message.get("body", b""))
                if received > self.max_body:
                    raise _TooLarge(self.max_body)
            return message

        try:
            await self.app(scope, receive_counted, send_hardened)
        except _TooLarge:
            if started:            # the app answered before reading it all: nothing to add
                return
            await self._too_large(send_hardened, None)

    async def _too_large(self, send: Send, declared: int | None) -> None:
        body = json.dumps({"detail": too_large_message(self.max_body, declared)}).encode()
        await send({"type": "http.response.start", "status": 413,
                    "headers": [(b"content-type", b"application/json"),
                                (b"content-length", str(len(body)).encode()),
                                (b"connection", b"close")]})
        await send({"type": "http.response.body", "body": body})


def _content_length(scope: Scope) -> int | None:
    for key, value in scope.get("headers", []):
        if key.lower() == b"content-length":
            try:
                return int(value)
            except ValueError:
                return None
    return None


def install(app: Any, settings: Any) -> None:
    """Add the middleware to `app` (outermost of the app's own middleware, so it sees the body
    before any route and every response after every handler)."""
    docs = frozenset(p for p in (app.docs_url, app.redoc_url, app.swagger_ui_oauth2_redirect_url)
                     if p)
    app.add_middleware(Hardening, max_body=settings.max_body_bytes,
                       retry_after_s=settings.retry_after_s, docs_paths=docs)


def _origin_key(scheme: str, netloc: str) -> tuple[str, str]:
    """(scheme family, host[:port] without a default port), lower case."""
    scheme = scheme.lower()
    host = netloc.lower().rsplit("@", 1)[-1]
    default = {"http": ":80", "ws": ":80", "https": ":443", "wss": ":443"}.get(scheme)
    if default and host.endswith(default):
        host = host[: -len(default)]
    return ({"ws": "http", "wss": "https"}.get(scheme, scheme), host)


def origin_allowed(websocket: WebSocket, extra: str = "") -> tuple[bool, str]:
    """Whether a WebSocket may connect, and why not: no Origin header (the CLI, tests, other
    programs) or the served host's own origin (the Host the request came to, in either scheme;
    a browser page from another site sends its own Origin), or one of `extra`'s
    comma-separated origins (INTERPLAY_ALLOWED_ORIGINS, e.g. behind a proxy that rewrites Host)."""
    origin = websocket.headers.get("origin")
    if origin is None:
        return True, ""
    parts = urlsplit(origin.strip())
    if not parts.scheme or not parts.netloc:
        return False, _reason(f"origin {origin!r} is not allowed")
    key = _origin_key(parts.scheme, parts.netloc)
    host = websocket.headers.get("host", "")
    served = {_origin_key(s, host) for s in ("http", "https")} if host else set()
    allowed = served | {_origin_key(p.scheme, p.netloc) for p in
                        (urlsplit(o.strip()) for o in extra.split(",") if o.strip())}
    if key in allowed:
        return True, ""
    return False, _reason(f"origin {origin!r} is not allowed on host {host!r}")


def _reason(text: str) -> str:
    """A close reason: at most 123 bytes of UTF-8 (the WebSocket limit)."""
    data = text.encode()
    return text if len(data) <= 123 else data[:120].decode(errors="ignore") + "…"
