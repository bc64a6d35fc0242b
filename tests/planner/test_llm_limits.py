"""The LLM planner against a hostile endpoint: a real HTTP server on 127.0.0.1 in a thread that
drip-feeds its answer, sends 50 MB, nests JSON 50 000 deep, writes NaN, infinities, huge
numbers or wrong types. Every call ends by the one deadline (INTERPLAY_LLM_TIMEOUT_S for the
whole call, not per read), reads at most MAX_BODY bytes, and falls back to the embedded
planner with the reason in `fallback_reason`; none raises."""

from __future__ import annotations

import asyncio
import json
import math
import threading
import time
import tracemalloc
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import pytest

from interplay.planner.llm import MAX_BODY, llm_plan
from interplay.planner.plan import embedded_plan
from interplay.planner.schema import TrajectorySpec
from interplay.settings import Settings
from tests.planner.test_llm import ANSWER, PROMPT

SEGMENT = ANSWER["segments"][1]


def _envelope(content: str) -> bytes:
    return json.dumps({"choices": [{"message": {"role": "assistant", "content": content}}]}).encode()


class _Hostile(BaseHTTPRequestHandler):
    """Answers POST /v1/chat/completions as `server.behaviour` says; counts what it sent."""
    protocol_version = "HTTP/1.1"

    def do_POST(self):                                   # noqa: N802 (http.server API)
        self.rfile.read(int(self.headers["Content-Length"]))
        kind, payload = self.server.behaviour             # type: ignore[attr-defined]
        try:
            if kind == "body":                            # a whole body at once
                self._head(len(payload))
                self._send(payload)
            elif kind == "drip":                          # whitespace, one byte every 0.2 s
                body = _envelope(json.dumps(ANSWER))
                pad = int(payload / 0.2)
                self._head(pad + len(body))
                for _ in range(pad):
                    self._send(b" ")
                    time.sleep(0.2)
                self._send(body)
            elif kind == "flood":                         # 50 MB, no Content-Length
                self.send_response(200)
                self.send_header("Content-Type", "application/json")
                self.send_header("Connection", "close")
                self.end_headers()
                chunk = b" " * 65536
                for _ in range(payload // len(chunk)):
                    self._send(chunk)
            elif kind == "declared":                      # says 50 MB up front
                self._head(payload)
                self._send(b" " * 65536)
        except (BrokenPipeError, ConnectionResetError):
            pass                                          # the client stopped reading: good
        self.close_connection = True

    def _head(self, length: int) -> None:
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(length))
        self.end_headers()

    def _send(self, data: bytes) -> None:
        self.wfile.write(data)
        self.wfile.flush()
        self.server.sent += len(data)                     # type: ignore[attr-defined]

    def log_message(self, *args):
        pass


@pytest.fixture(scope="module")
def server():
    server = ThreadingHTTPServer(("127.0.0.1", 0), _Hostile)
    server.daemon_threads = True
    threading.Thread(target=server.serve_forever, daemon=True).start()
    yield server
    server.shutdown()
    server.server_close()


@pytest.fixture
def endpoint(server):
    server.sent = 0
    return server


def _plan(server, behaviour, timeout=5.0, seconds=5.0):
    server.behaviour = behaviour
    settings = Settings(llm_base_url=f"http://127.0.0.1:{server.server_port}/v1",
                        llm_model="hostile", llm_timeout_s=timeout)
    start = time.monotonic()
    p = llm_plan(PROMPT, 1, seconds, settings, fallback=lambda: embedded_plan(PROMPT, 1, seconds))
    return p, time.monotonic() - start


def _fell_back(p, why: str) -> None:
    assert p.planner == "embedded", p
    assert p.fallback_reason is not None and why in p.fallback_reason, p.fallback_reason
    assert p.fallback_reason.startswith("LLM planner 'hostile': ")
    assert p.to_json()["segments"] == embedded_plan(PROMPT, 1, 5.0).to_json()["segments"]


def test_a_good_answer_from_the_server_is_the_plan(endpoint):
    p, _ = _plan(endpoint, ("body", _envelope(json.dumps(ANSWER))))
    assert p.planner == "llm" and p.fallback_reason is None


def test_a_drip_fed_answer_ends_at_the_one_deadline(endpoint):
    # One byte every 0.2 s for 8 s, then a good answer: every read is quick, the whole is not.
    p, took = _plan(endpoint, ("drip", 8.0), timeout=1.0)
    _fell_back(p, "timed out after 1 s")
    assert took < 1.8, took


def test_an_answer_that_arrives_within_the_deadline_is_used(endpoint):
    p, took = _plan(endpoint, ("drip", 0.6), timeout=5.0)
    assert p.planner == "llm" and took < 5.0


def test_a_50_mb_answer_is_abandoned_past_the_cap_while_reading(endpoint):
    tracemalloc.start()
    try:
        p, _ = _plan(endpoint, ("flood", 50 * 2**20))
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    _fell_back(p, f"longer than {MAX_BODY} bytes")
    assert peak < 8 * MAX_BODY, peak                      # not the 50 MB (HEAD: ~10× that)
    assert endpoint.sent < 25 * 2**20, endpoint.sent      # the client stopped reading


def test_a_declared_50_mb_answer_is_refused_before_reading(endpoint):
    p, _ = _plan(endpoint, ("declared", 50 * 2**20))
    _fell_back(p, f"is {50 * 2**20} bytes long; the limit is {MAX_BODY}")


DEEP = "[" * 50_000 + "]" * 50_000          # 100 000 characters: inside MAX_ANSWER


@pytest.mark.parametrize("body,why", [
    # Nested 50 000 deep, in the plan and in the envelope: json raises RecursionError.
    (_envelope('{"rewritten": "x", "segments": ' + DEEP + "}"), "the answer is nested too deeply"),
    (b'{"choices": ' + DEEP.encode() + b"}", "not an OpenAI chat completion"),
    # NaN, infinities and numbers beyond a float or 4300 digits.
    (_envelope(json.dumps({**ANSWER, "segments": [{**SEGMENT, "trajectory": {
        "shape": "polyline", "waypoints": [[0, 0], [1, 1]]}}]}).replace("[1, 1]", "[NaN, 1]")),
     "NaN is not a JSON number"),
    (_envelope(json.dumps({**ANSWER, "segments": [{**SEGMENT, "seconds": 2}]})
               .replace('"seconds": 2', '"seconds": Infinity')), "Infinity is not a JSON number"),
    (_envelope(json.dumps({**ANSWER, "segments": [{**SEGMENT, "seconds": 2}]})
               .replace('"seconds": 2', '"seconds": 1e999')), "too large a number"),
    (_envelope(json.dumps({**ANSWER, "segments": [{**SEGMENT, "repeat": 2}]})
               .replace('"repeat": 2', '"repeat": 1' + "0" * 5000)), "not valid JSON"),
    (_envelope(json.dumps({**ANSWER, "segments": [{**SEGMENT, "trajectory": {
        "shape": "polyline", "waypoints": [[0, 0], [1e300, 1e300]]}}]})), "waypoints.1.0"),
    (_envelope(json.dumps({**ANSWER, "segments": [{**SEGMENT, "trajectory": {
        "shape": "line", "turn_at": {"clock": 3, "after_m": 1e12}}}]})), "after_m"),
    (_envelope(json.dumps({**ANSWER, "segments": [{**SEGMENT, "trajectory": {
        "shape": "circle", "size_m": 50, "turns": 20}}]})), "the limit is 200 m"),
    # Wrong types.
    (_envelope(json.dumps({**ANSWER, "segments": [{**SEGMENT, "seconds": "2"}]})),
     "segments.0.seconds"),
    (_envelope(json.dumps({**ANSWER, "segments": [{**SEGMENT, "persons": [True]}]})),
     "segments.0.persons.0"),
    (_envelope(json.dumps({**ANSWER, "segments": [{**SEGMENT, "trajectory": {
        "shape": "polyline", "waypoints": [[0, 0], [True, "1"]]}}]})), "waypoints.1"),
    (_envelope(json.dumps({**ANSWER, "segments": {"0": SEGMENT}})), "segments"),
    (_envelope(json.dumps({**ANSWER, "rewritten": ["x"]})), "rewritten"),
    (_envelope(json.dumps({**ANSWER, "reasons": "x" * 10_000})), "reasons"),
    (json.dumps({"choices": [{"message": {"content": {"rewritten": "x"}}}]}).encode(), "empty"),
    (json.dumps({"choices": "nope"}).encode(), "not an OpenAI chat completion"),
])
def test_malformed_answers_fall_back_with_the_reason(endpoint, body, why):
    p, _ = _plan(endpoint, ("body", body))
    _fell_back(p, why)
    assert len(p.fallback_reason) < 400


def test_a_nan_waypoint_fails_validation():
    with pytest.raises(ValueError, match="finite"):
        TrajectorySpec(shape="polyline", waypoints=[(0.0, 0.0), (math.nan, 1.0)])
    with pytest.raises(ValueError, match="finite"):
        TrajectorySpec(shape="free", waypoints=[(0.0, 0.0), (math.inf, 1.0)])


def test_the_planner_also_works_from_inside_a_running_event_loop(endpoint):
    async def inside():
        return _plan(endpoint, ("body", _envelope(json.dumps(ANSWER))))
    p, _ = asyncio.run(inside())
    assert p.planner == "llm"
