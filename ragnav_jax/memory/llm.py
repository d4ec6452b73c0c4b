"""A minimal OpenAI-compatible chat client for the optional LLM captioner and summariser (stdlib only).

The endpoint comes from the `llm` config section; the API key is read from the environment variable it
names at call time and is never written anywhere.
"""

from __future__ import annotations

import json
import os
import urllib.error
import urllib.request

from ragnav_jax.errors import UserError


class LLMError(UserError):
    """The LLM endpoint is off, unreachable or answered something unusable."""


def chat(llm_cfg, messages: list[dict], max_tokens: int = 200) -> str:
    """The assistant message text of one chat completion."""
    if not llm_cfg.base_url:
        raise LLMError("the LLM endpoint is off (llm.base_url is empty); use the template captioner/summariser")
    url = llm_cfg.base_url.rstrip("/") + "/chat/completions"
    body = {"model": llm_cfg.model, "messages": messages, "temperature": llm_cfg.temperature, "max_tokens": max_tokens}
    headers = {"Content-Type": "application/json"}
    key = os.environ.get(llm_cfg.api_key_env, "") if llm_cfg.api_key_env else ""
    if key:
        headers["Authorization"] = f"Bearer {key}"
    req = urllib.request.Request(url, data=json.dumps(body).encode(), headers=headers, method="POST")
    try:
        with urllib.request.urlopen(req, timeout=llm_cfg.timeout_s) as r:
            data = json.loads(r.read().decode("utf-8"))
        return str(data["choices"][0]["message"]["content"])
    except (urllib.error.URLError, TimeoutError, OSError) as e:
        raise LLMError(f"LLM endpoint {url} failed ({e.__class__.__name__}: {getattr(e, 'reason', e)})") from None
    except (ValueError, KeyError, IndexError, TypeError) as e:
        raise LLMError(f"LLM endpoint {url} gave an unusable answer ({e.__class__.__name__})") from None
