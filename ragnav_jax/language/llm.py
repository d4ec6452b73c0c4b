"""Optional LLM instruction parser through an OpenAI-compatible chat endpoint, with rule-parser fallback.

    chain, note = parse_with_fallback(text, cfg.llm)   # note: why the LLM was not used, or None

The endpoint is `cfg.llm.base_url` (empty = off; the memory captioner shares the setting). The API key
is read from the environment variable named by `cfg.llm.api_key_env` at call time; it is sent only in
the Authorization header and never logged, stored or put in an error message. The model's reply is
only ever read with `json.loads`, validated against TASKCHAIN_SCHEMA and rebuilt with
`TaskChain.from_dict`; on any failure (network, HTTP status, JSON, schema) the deterministic parser
answers instead.
"""

from __future__ import annotations

import dataclasses
import json
import os
import re
import urllib.error
import urllib.request
from collections.abc import Callable

from ragnav_jax.config import LLMConfig
from ragnav_jax.language.parser import MAX_CHARS, parse_instruction
from ragnav_jax.language.types import (
    COMPARATORS,
    READINGS,
    RELATION_TYPES,
    TASKCHAIN_SCHEMA,
    ParseError,
    TaskChain,
    derive_dependencies,
)

MAX_REPLY_BYTES = 1 << 20
# transport(url, headers, body, timeout_s) -> reply bytes; tests pass a fake one.
Transport = Callable[[str, dict, bytes, float], bytes]


class LLMError(Exception):
    """The endpoint could not give a usable task chain (the caller falls back to the rule parser)."""


def llm_enabled(cfg: LLMConfig | None, purpose: str = "parsing") -> bool:
    if cfg is None or not cfg.base_url or not cfg.model:
        return False
    return cfg.use_for_parsing if purpose == "parsing" else cfg.use_for_captions


def _scrub(msg: str, secret: str | None) -> str:
    if secret:
        msg = msg.replace(secret, "***")
    return msg[:300]


def urllib_transport(url: str, headers: dict, body: bytes, timeout_s: float) -> bytes:
    req = urllib.request.Request(url, data=body, headers=headers, method="POST")
    with urllib.request.urlopen(req, timeout=timeout_s) as resp:  # noqa: S310 (URL comes from the user's config)
        return resp.read(MAX_REPLY_BYTES + 1)


def chat_completion(cfg: LLMConfig, messages: list[dict], transport: Transport | None = None,
                    json_mode: bool = True) -> str:
    """Sends one chat request; returns the reply text. Raises LLMError (never with the key in it)."""
    key = os.environ.get(cfg.api_key_env, "") if cfg.api_key_env else ""
    headers = {"Content-Type": "application/json"}
    if key:
        headers["Authorization"] = f"Bearer {key}"
    payload = {"model": cfg.model, "messages": messages, "temperature": cfg.temperature}
    if json_mode:
        payload["response_format"] = {"type": "json_object"}
    url = cfg.base_url.rstrip("/") + "/chat/completions"
    try:
        raw = (transport or urllib_transport)(url, headers, json.dumps(payload).encode(), cfg.timeout_s)
    except urllib.error.HTTPError as e:
        raise LLMError(f"endpoint answered HTTP {e.code}") from None
    except Exception as e:  # noqa: BLE001 - any transport failure means "fall back"
        raise LLMError(_scrub(f"endpoint unreachable ({type(e).__name__}: {e})", key)) from None
    if len(raw) > MAX_REPLY_BYTES:
        raise LLMError("reply larger than 1 MiB")
    try:
        reply = json.loads(raw)
        content = reply["choices"][0]["message"]["content"]
    except (ValueError, KeyError, IndexError, TypeError):
        raise LLMError("reply is not an OpenAI-style chat completion") from None
    if not isinstance(content, str):
        raise LLMError("reply content is not text")
    return content


SYSTEM_PROMPT = f"""You turn a robot navigation instruction into a JSON task chain. Answer with one JSON object only.
Shape: {{"order": "strict"|"free", "subgoals": [{{"index": 0, "text": span, "target": TARGET, "room": string|null,
"location": {{"x": number, "y": number}}|null, "sensors": [{{"reading": R, "comparator": C, "value": number|null, "unit": ""|"c"|"f"|"%"}}]}}]}}
TARGET = {{"phrase": attributes+head as written, lower case, no article; "head": the noun (may be several words);
"attributes": descriptive words before the head; "relations": [{{"type": T, "anchor": TARGET}}]}}.
R in {list(READINGS)}; C in {list(COMPARATORS)} (max/min for superlatives like "warmest" with value null;
approx for "about"); values in Celsius, NDVI or percent. T in {list(RELATION_TYPES)}.
order is "free" only when the instruction says the order does not matter ("in any order", "whatever order is quickest").
Indices are 0..n-1 in visiting order. Do not invent objects."""


def _extract_json(content: str) -> dict:
    text = content.strip()
    fence = re.match(r"^```(?:json)?\s*(.*?)\s*```$", text, re.S)
    if fence:
        text = fence.group(1)
    try:
        data = json.loads(text)
    except ValueError:
        raise LLMError("reply is not JSON") from None
    if not isinstance(data, dict):
        raise LLMError("reply JSON is not an object")
    return data


def parse_with_llm(text: str, cfg: LLMConfig, transport: Transport | None = None) -> TaskChain:
    """Asks the endpoint for a chain; raises LLMError (endpoint/JSON) or ParseError (schema)."""
    messages = [{"role": "system", "content": SYSTEM_PROMPT}, {"role": "user", "content": text}]
    data = _extract_json(chat_completion(cfg, messages, transport))
    data = {k: v for k, v in data.items() if k in TASKCHAIN_SCHEMA["properties"]}
    data["instruction"] = text.strip()
    data["parser"] = "llm"
    data.pop("format", None)
    chain = TaskChain.from_dict(data, validate=True)
    if "dependencies" not in data:
        chain = dataclasses.replace(chain, dependencies=derive_dependencies(chain.subgoals, chain.order))
    return chain


def parse_with_fallback(text: str, cfg: LLMConfig | None = None,
                        transport: Transport | None = None) -> tuple[TaskChain, str | None]:
    """The LLM's chain when the endpoint is configured and answers well, else the rule parser's.

    Returns (chain, note): note says why the LLM was not used (None when it was, or when it is off).
    Bad instructions raise ParseError from the rule parser either way.
    """
    if not llm_enabled(cfg, "parsing"):
        return parse_instruction(text), None
    if not isinstance(text, str) or not text.strip() or len(text) > MAX_CHARS:
        return parse_instruction(text), None  # raises the rule parser's ParseError
    try:
        return parse_with_llm(text, cfg, transport), None
    except (LLMError, ParseError) as e:
        note = f"LLM parser not used ({e}); used the rule parser"
    return parse_instruction(text), note
