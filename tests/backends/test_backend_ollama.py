"""The `ollama` backend against recorded Ollama `/api/*` responses.

No Ollama server can run here, so a local http.server replays responses recorded from
Ollama's API documentation (see recorded/README.md) and the real `ollama` client talks to it.
These tests check our side of the protocol (what we send, how we read what comes back),
not a model's behaviour.
"""

from __future__ import annotations

from collections.abc import Callable

import pytest
from backend_servers import Reply, ScriptedServer, free_port, recorded
from drivetwin.orchestrator.backends import (
    BackendTimeout,
    BackendUnavailable,
    InvalidOutput,
    load_backend,
)
from drivetwin.orchestrator.backends.ollama_backend import PRESETS, OllamaBackend

pytest.importorskip("ollama", reason="needs the llm extra (ollama client)")

AGE_SCHEMA = {
    "type": "object",
    "properties": {"age": {"type": "integer"}, "available": {"type": "boolean"}},
    "required": ["age", "available"],
}
AGE_PROMPT = [
    {
        "role": "user",
        "content": "Ollama is 22 years old and busy saving the world. Return a JSON object "
        "with the age and availability.",
    }
]
Start = Callable[[dict[tuple[str, str], Reply]], ScriptedServer]


def chat_server(start: Start, reply: Reply) -> ScriptedServer:
    return start({("POST", "/api/chat"): reply})


def test_structured_chat_sends_the_schema_as_format_and_returns_checked_json(
    scripted_server: Start,
) -> None:
    server = chat_server(scripted_server, Reply(recorded("ollama_chat_structured.json")))
    backend = load_backend("ollama", "llama3.1", host=server.url)

    result = backend.chat(AGE_PROMPT, schema=AGE_SCHEMA, temperature=0.0, seed=7, max_tokens=64)

    sent = server.requests[0]["json"]
    assert sent["model"] == "llama3.1:8b"
    assert sent["format"] == AGE_SCHEMA
    assert sent["stream"] is False
    assert sent["options"] == {"temperature": 0.0, "seed": 7, "num_predict": 64}
    assert sent["messages"] == AGE_PROMPT
    assert result.data == {"age": 22, "available": False}
    assert (result.prompt_tokens, result.completion_tokens) == (34, 12)
    assert result.backend == "ollama" and result.latency_s > 0


def test_plain_chat_returns_the_text_and_token_counts(scripted_server: Start) -> None:
    server = chat_server(scripted_server, Reply(recorded("ollama_chat_plain.json")))
    result = load_backend("ollama", "llama3.2", host=server.url).chat(
        [{"role": "user", "content": "why is the sky blue?"}]
    )
    assert result.text == "Hello! How are you today?"
    assert (result.prompt_tokens, result.completion_tokens) == (26, 298)
    assert result.data is None
    assert "format" not in server.requests[0]["json"]


@pytest.mark.parametrize(("preset", "tag"), sorted(PRESETS.items()))
def test_presets_are_the_papers_models(preset: str, tag: str) -> None:
    assert OllamaBackend(preset).model == tag


def test_a_model_the_server_lacks_names_the_pull_command(scripted_server: Start) -> None:
    body = recorded("ollama_model_not_found.json")
    server = chat_server(scripted_server, Reply(body, status=404))
    with pytest.raises(BackendUnavailable) as caught:
        load_backend("ollama", "mistral", host=server.url).chat(AGE_PROMPT)
    assert caught.value.fix == "ollama pull mistral:7b-instruct-v0.2"
    assert "not found" in str(caught.value)


def test_statuses_mark_pulled_presets_usable_and_name_the_pull_for_the_rest(
    scripted_server: Start,
) -> None:
    server = scripted_server({("GET", "/api/tags"): Reply(recorded("ollama_tags.json"))})
    rows = {row.model: row for row in OllamaBackend.statuses(host=server.url)}
    assert rows["llama3.1:8b"].usable
    assert not rows["gemma2:9b"].usable and rows["gemma2:9b"].fix == "ollama pull gemma2:9b"
    assert rows["llama3:latest"].usable  # pulled, though not a preset


def test_describe_reports_parameters_quantisation_and_size(scripted_server: Start) -> None:
    server = scripted_server(
        {
            ("POST", "/api/show"): Reply(recorded("ollama_show.json")),
            ("GET", "/api/tags"): Reply(recorded("ollama_tags.json")),
        }
    )
    info = OllamaBackend("llama3.1", host=server.url).describe()
    assert info.parameters == 8030261248
    assert info.quantisation == "Q4_0"
    assert info.size_bytes == 4920753328
    assert info.context_length == 8192


def test_no_server_means_unavailable_with_the_serve_command() -> None:
    host = f"http://127.0.0.1:{free_port()}"
    with pytest.raises(BackendUnavailable) as caught:
        OllamaBackend("llama3.1", host=host).chat(AGE_PROMPT)
    assert caught.value.fix is not None and caught.value.fix.startswith("ollama serve")
    rows = OllamaBackend.statuses(host=host)
    assert rows and all(not r.usable and r.fix and "ollama serve" in r.fix for r in rows)


def test_a_server_slower_than_the_timeout_raises_backend_timeout(scripted_server: Start) -> None:
    server = chat_server(scripted_server, Reply(recorded("ollama_chat_structured.json"), delay_s=1.0))
    with pytest.raises(BackendTimeout) as caught:
        OllamaBackend("llama3.1", host=server.url).chat(AGE_PROMPT, timeout_s=0.2)
    assert caught.value.timeout_s == 0.2


def test_a_reply_that_is_not_json_raises_invalid_output(scripted_server: Start) -> None:
    page = "<html><body>Welcome to nginx!</body></html>"
    server = chat_server(scripted_server, Reply(page, content_type="text/html"))
    with pytest.raises(InvalidOutput) as caught:
        OllamaBackend("llama3.1", host=server.url).chat(AGE_PROMPT)
    assert caught.value.reason == "not_json"
    assert "nginx" in caught.value.raw


def test_a_cut_off_reply_raises_invalid_output(scripted_server: Start) -> None:
    server = chat_server(scripted_server, Reply(recorded("ollama_chat_structured.json"), truncate=True))
    with pytest.raises(InvalidOutput) as caught:
        OllamaBackend("llama3.1", host=server.url).chat(AGE_PROMPT, schema=AGE_SCHEMA)
    assert caught.value.reason == "truncated"


def test_an_answer_stopped_by_num_predict_is_reported_as_truncated(scripted_server: Start) -> None:
    body = recorded("ollama_chat_structured.json")
    body["message"]["content"] = '{"age": 2'
    body["done_reason"] = "length"
    server = chat_server(scripted_server, Reply(body))
    with pytest.raises(InvalidOutput) as caught:
        OllamaBackend("llama3.1", host=server.url).chat(AGE_PROMPT, schema=AGE_SCHEMA)
    assert caught.value.reason == "truncated"
    assert caught.value.raw == '{"age": 2'


def test_an_answer_that_breaks_the_schema_raises_invalid_output(scripted_server: Start) -> None:
    body = recorded("ollama_chat_structured.json")
    body["message"]["content"] = '{"age": "twenty-two", "available": false}'
    server = chat_server(scripted_server, Reply(body))
    with pytest.raises(InvalidOutput) as caught:
        OllamaBackend("llama3.1", host=server.url).chat(AGE_PROMPT, schema=AGE_SCHEMA)
    assert caught.value.reason == "schema_mismatch"
    assert "$.age" in str(caught.value)
