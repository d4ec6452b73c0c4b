"""The optional LLM parser: a fake OpenAI-compatible server on 127.0.0.1, schema validation, fallback,
and the API key kept out of outputs and errors."""

import json
import threading
from http.server import BaseHTTPRequestHandler, HTTPServer

import pytest

from ragnav_jax.cli import main
from ragnav_jax.config import LLMConfig
from ragnav_jax.language.llm import LLMError, chat_completion, llm_enabled, parse_with_fallback, parse_with_llm
from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.language.types import ParseError

SECRET = "sk-test-0123456789-secret"
GOOD = {
    "order": "free",
    "subgoals": [
        {"index": 0, "text": "the defibrillator", "target": {"phrase": "defibrillator", "head": "defibrillator"}},
        {"index": 1, "text": "the plant", "target": {"phrase": "plant", "head": "plant", "attributes": [],
         "relations": [{"type": "near", "anchor": {"phrase": "window", "head": "window"}}]},
         "room": None, "location": {"x": 1.5, "y": 2}, "sensors": [{"reading": "ndvi", "comparator": "max", "value": None}]},
    ],
}


class _Handler(BaseHTTPRequestHandler):
    replies: list = []
    seen: list = []

    def do_POST(self):  # noqa: N802
        body = json.loads(self.rfile.read(int(self.headers["Content-Length"])))
        type(self).seen.append({"path": self.path, "auth": self.headers.get("Authorization"), "body": body})
        status, content = type(self).replies.pop(0) if type(self).replies else (200, json.dumps(GOOD))
        if isinstance(content, dict):
            data = json.dumps(content).encode()
        else:
            data = json.dumps({"choices": [{"message": {"role": "assistant", "content": content}}]}).encode()
        self.send_response(status)
        self.send_header("Content-Type", "application/json")
        self.end_headers()
        self.wfile.write(data)

    def log_message(self, *a):
        pass


@pytest.fixture
def server():
    _Handler.replies, _Handler.seen = [], []
    httpd = HTTPServer(("127.0.0.1", 0), _Handler)
    t = threading.Thread(target=httpd.serve_forever, kwargs={"poll_interval": 0.02}, daemon=True)
    t.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}/v1", _Handler
    httpd.shutdown()
    httpd.server_close()


def _cfg(url, **kw):
    kw.setdefault("timeout_s", 5.0)
    return LLMConfig(base_url=url, model="fake-model", api_key_env="RAGNAV_TEST_KEY", **kw)


def test_llm_chain_is_validated_and_used(server, monkeypatch):
    url, h = server
    monkeypatch.setenv("RAGNAV_TEST_KEY", SECRET)
    chain, note = parse_with_fallback("Find the defibrillator and the healthiest plant by the window, any order.", _cfg(url))
    assert note is None and chain.parser == "llm" and chain.order == "free"
    assert [s.target.head for s in chain.subgoals] == ["defibrillator", "plant"]
    assert chain.subgoals[1].sensors[0].comparator == "max" and chain.subgoals[1].location.x == 1.5
    assert [d.type for d in chain.dependencies] == ["spatial"]  # derived when the model gives none
    req = h.seen[0]
    assert req["path"] == "/v1/chat/completions" and req["auth"] == f"Bearer {SECRET}"
    assert req["body"]["model"] == "fake-model" and req["body"]["messages"][-1]["role"] == "user"
    assert SECRET not in json.dumps(chain.to_dict())


@pytest.mark.parametrize(
    "reply",
    [
        (200, "this is not json"),
        (200, "__import__('os').system('touch /tmp/ragnav_pwned')"),
        (200, json.dumps({"subgoals": []})),
        (200, json.dumps({"order": "sometimes", "subgoals": GOOD["subgoals"]})),
        (200, json.dumps({"subgoals": [{"index": 3, "target": {"phrase": "x", "head": "x"}}]})),
        (200, json.dumps({"subgoals": [{"index": 0, "target": {"phrase": "x", "head": "x"},
                                        "sensors": [{"reading": "ndvi", "comparator": "gt", "value": None}]}]})),
        (200, {"unexpected": "shape"}),
        (500, "server error"),
        (401, "unauthorised"),
    ],
)
def test_any_bad_reply_falls_back_to_the_rule_parser(server, monkeypatch, reply, tmp_path):
    url, h = server
    h.replies.append(reply)
    monkeypatch.setenv("RAGNAV_TEST_KEY", SECRET)
    text = "First go to the sofa, then the fridge."
    chain, note = parse_with_fallback(text, _cfg(url))
    assert chain == parse_instruction(text) and chain.parser == "rules"
    assert note and "rule parser" in note and SECRET not in note
    assert not (tmp_path / "ragnav_pwned").exists()


def test_unreachable_endpoint_falls_back_and_never_leaks_the_key(monkeypatch):
    monkeypatch.setenv("RAGNAV_TEST_KEY", SECRET)
    cfg = _cfg("http://127.0.0.1:9/v1", timeout_s=0.5)
    chain, note = parse_with_fallback("go to the sofa", cfg)
    assert chain.parser == "rules" and "unreachable" in note and SECRET not in note
    with pytest.raises(LLMError) as e:
        chat_completion(cfg, [{"role": "user", "content": "hi"}])
    assert SECRET not in str(e.value)


def test_monkeypatched_transport_and_off_switch():
    seen = {}

    def transport(url, headers, body, timeout):
        seen["headers"] = headers
        return json.dumps({"choices": [{"message": {"content": "```json\n" + json.dumps(GOOD) + "\n```"}}]}).encode()

    cfg = _cfg("http://llm.invalid/v1")
    assert parse_with_llm("find two things", cfg, transport).parser == "llm"
    assert "Authorization" not in seen["headers"]  # no key in the environment: no header
    assert not llm_enabled(LLMConfig()) and not llm_enabled(_cfg("http://x/v1", use_for_parsing=False))
    chain, note = parse_with_fallback("go to the sofa", LLMConfig(), transport)
    assert chain.parser == "rules" and note is None
    with pytest.raises(ParseError):  # empty input never reaches the endpoint
        parse_with_fallback("  ", cfg, transport)


def test_cli_parse_with_llm_endpoint(server, monkeypatch, capsys):
    url, h = server
    monkeypatch.setenv("RAGNAV_TEST_KEY", SECRET)
    argv = ["parse", "--llm", "--json", "--set", f"llm.base_url={url}", "--set", "llm.model=m",
            "--set", "llm.api_key_env=RAGNAV_TEST_KEY", "find the defibrillator"]
    assert main(argv) == 0
    out = capsys.readouterr()
    assert json.loads(out.out)["parser"] == "llm" and SECRET not in out.out + out.err
    h.replies.append((200, "garbage"))
    assert main(argv) == 0
    out = capsys.readouterr()
    assert json.loads(out.out)["parser"] == "rules" and "note" in out.err and SECRET not in out.out + out.err
