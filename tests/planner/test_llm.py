"""The optional LLM planner against fake OpenAI-compatible endpoints (httpx.MockTransport, and
one real local HTTP server for `plan()`): good answers become plans, everything else falls
back to the embedded planner with the reason, and model output is never executed."""

import json
import threading
from http.server import BaseHTTPRequestHandler, HTTPServer

import httpx
import pytest

from interplay.planner.llm import extract_json, llm_plan
from interplay.planner.plan import embedded_plan, plan
from interplay.planner.schema import validate_plan
from interplay.settings import Settings

PROMPT = "a person does the wakanda salute, then jumps"
ANSWER = {
    "rewritten": "a person crosses both arms in front of the chest, then a person jumps",
    "reasons": ["wakanda salute → crossed arms"],
    "segments": [
        {"prompt": "a person crosses both arms in front of the chest", "base": "a person stands",
         "edits": {"left_arm": "crosses the arms", "right_arm": "crosses the arms",
                   "left_leg": None, "right_leg": "none"},
         "trajectory": None, "seconds": 2.0, "persons": [0], "repeat": 1},
        {"prompt": "a person jumps", "base": "a person jumps", "seconds": 1.5, "persons": [0],
         "why": "an extra key the model added"},
    ],
}


def _settings(**over):
    return Settings(**{"llm_base_url": "http://llm.test/v1", "llm_model": "fake-planner",
                       "llm_api_key": "sk-test", "llm_timeout_s": 0.5, **over})


def _reply(content, status=200):
    body = {"choices": [{"message": {"role": "assistant", "content": content}}]}
    return lambda request: httpx.Response(status, json=body)


def _run(handler, seconds=5.0, persons=1, **over):
    seen = []

    def record(request):
        seen.append(request)
        return handler(request)
    out = llm_plan(PROMPT, persons, seconds, _settings(**over),
                   fallback=lambda: embedded_plan(PROMPT, persons, seconds),
                   transport=httpx.MockTransport(record))
    return out, seen


def test_a_good_answer_is_the_plan_with_frames_scaled_to_the_request():
    p, seen = _run(_reply(json.dumps(ANSWER)), seconds=7.0)
    assert p.planner == "llm" and p.fallback_reason is None
    assert validate_plan(p.to_json()) == p
    assert [s.prompt for s in p.segments] == [s["prompt"] for s in ANSWER["segments"]]
    # 7 s is more than the 3.5 s asked: the jump keeps its 1.5 s, the standing pose (which can
    # last) takes the spare 3.5 s (durations.fit, as for the embedded planner)
    assert p.segments[-1].end == 140 and p.segments[0].end == 110
    assert p.segments[0].edits.right_leg is None and p.reasons[0] == "llm: planned by fake-planner"
    (req,) = seen
    assert str(req.url) == "http://llm.test/v1/chat/completions"
    assert req.headers["authorization"] == "Bearer sk-test"
    body = json.loads(req.content)
    assert body["model"] == "fake-planner" and body["temperature"] == 0
    system, user = body["messages"]
    assert "base" in system["content"] and '"segments"' in system["content"]   # the JSON schema
    assert PROMPT in user["content"] and "7 seconds" in user["content"]


def test_fenced_json_and_surrounding_words_are_accepted():
    content = "Here is the plan:\n```json\n" + json.dumps(ANSWER) + "\n```\nEnjoy!"
    p, _ = _run(_reply(content))
    assert p.planner == "llm" and len(p.segments) == 2


@pytest.mark.parametrize("handler,why", [
    (_reply("I would walk and then jump."), "no JSON object"),
    (_reply("{'segments': [1, 2,]}"), "not valid JSON"),
    (_reply(json.dumps({"rewritten": "x", "segments": [{"prompt": "a person jumps"}]})),
     "does not match the plan schema: segments.0.base"),
    (_reply(json.dumps({**ANSWER, "segments": [{**ANSWER["segments"][1], "seconds": -1}]})),
     "segments.0.seconds"),
    (_reply(json.dumps({**ANSWER, "segments": [{**ANSWER["segments"][1], "persons": [1]}]})),
     "persons [1] for a plan of 1 person"),
    (_reply(json.dumps({**ANSWER, "segments": [{**ANSWER["segments"][1],
                                                 "trajectory": {"shape": "pentagram"}}]})),
     "segments.0.trajectory.shape"),
    (_reply(json.dumps(ANSWER), status=500), "HTTP 500"),
    (lambda r: httpx.Response(200, json={"id": "x", "object": "error"}), "not an OpenAI chat completion"),
    (lambda r: httpx.Response(200, text="<html>gateway</html>"), "not an OpenAI chat completion"),
    (_reply(""), "empty"),
])
def test_bad_answers_fall_back_to_the_embedded_planner_with_the_reason(handler, why):
    p, _ = _run(handler)
    assert p.planner == "embedded" and why in p.fallback_reason, p.fallback_reason
    assert "fake-planner" in p.fallback_reason and "sk-test" not in p.fallback_reason
    assert p.to_json()["segments"] == embedded_plan(PROMPT, 1, 5.0).to_json()["segments"]


def test_timeouts_and_connection_errors_fall_back():
    def slow(request):
        raise httpx.ReadTimeout("no answer", request=request)

    def down(request):
        raise httpx.ConnectError("connection refused", request=request)
    p, _ = _run(slow, llm_timeout_s=0.5)
    assert p.planner == "embedded" and "timed out after 0.5 s" in p.fallback_reason
    p, _ = _run(down)
    assert "request failed (ConnectError" in p.fallback_reason


def test_model_output_is_data_never_code(tmp_path):
    marker = tmp_path / "pwned"
    evil = f"__import__('pathlib').Path({str(marker)!r}).write_text('x')"
    for content in (evil, json.dumps({**ANSWER, "rewritten": evil}),
                    json.dumps({**ANSWER, "segments": evil})):
        p, _ = _run(_reply(content))
        assert not marker.exists()
    assert p.fallback_reason and "segments" in p.fallback_reason
    with pytest.raises(ValueError, match="no JSON object"):
        extract_json("[1, 2, 3]")


class _FakeOpenAI(BaseHTTPRequestHandler):
    answer = json.dumps(ANSWER)

    def do_POST(self):                                   # noqa: N802 (http.server API)
        self.rfile.read(int(self.headers["Content-Length"]))
        body = json.dumps({"choices": [{"message": {"content": self.answer}}]}).encode()
        self.send_response(200 if self.path == "/v1/chat/completions" else 404)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, *args):
        pass


def test_plan_asks_the_configured_endpoint_and_falls_back_when_it_is_gone():
    server = HTTPServer(("127.0.0.1", 0), _FakeOpenAI)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    url = f"http://127.0.0.1:{server.server_port}/v1"
    try:
        p = plan(PROMPT, 1, 4.0, settings=_settings(llm_base_url=url, llm_api_key=None))
        assert p.planner == "llm" and p.seconds == 4.0
        wrong = plan(PROMPT, 1, 4.0, settings=_settings(llm_base_url=url + "/nope"))
        assert wrong.planner == "embedded" and "HTTP 404" in wrong.fallback_reason
    finally:
        server.shutdown()
        server.server_close()
    gone = plan(PROMPT, 1, 4.0, settings=_settings(llm_base_url=url))
    assert gone.planner == "embedded" and "request failed" in gone.fallback_reason
