"""The `openai` backend: against a real `python -m llama_cpp.server`, and against faults."""

from __future__ import annotations

from collections.abc import Callable

import jsonschema
import pytest
from backend_servers import WEATHER_PROMPT, WEATHER_SCHEMA, Reply, ScriptedServer, free_port
from drivetwin.orchestrator.backends import (
    BackendError,
    BackendTimeout,
    BackendUnavailable,
    InvalidOutput,
    load_backend,
)
from drivetwin.orchestrator.backends.openai_backend import OpenAIBackend

Start = Callable[[dict[tuple[str, str], Reply]], ScriptedServer]
COMPLETION = {
    "id": "chatcmpl-1",
    "object": "chat.completion",
    "model": "served-model",
    "choices": [
        {
            "index": 0,
            "message": {
                "role": "assistant",
                "content": '{"weather": "rain", "intensity": "heavy"}',
            },
            "finish_reason": "stop",
        }
    ],
    "usage": {"prompt_tokens": 30, "completion_tokens": 12, "total_tokens": 42},
}
MODELS = {"object": "list", "data": [{"id": "served-model", "object": "model"}]}


@pytest.mark.llm
def test_llama_cpp_server_answers_json_that_matches_the_schema(llama_server: str) -> None:
    backend = load_backend("openai", base_url=llama_server, timeout_s=60)
    result = backend.chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA, max_tokens=64)
    jsonschema.validate(result.data, WEATHER_SCHEMA)
    assert result.model == "smollm2-135m"  # the server's only model, found via /v1/models
    assert result.prompt_tokens > 0 and result.completion_tokens > 0


@pytest.mark.llm
def test_llama_cpp_server_plain_chat_returns_text(llama_server: str) -> None:
    result = load_backend("openai", "smollm2-135m", base_url=llama_server).chat(
        [{"role": "user", "content": "Say hello."}], max_tokens=8
    )
    assert result.text.strip()
    assert result.completion_tokens <= 8


@pytest.mark.llm
def test_statuses_list_the_served_model_as_usable(llama_server: str) -> None:
    rows = OpenAIBackend.statuses(base_url=llama_server)
    assert [(r.model, r.usable) for r in rows] == [("smollm2-135m", True)]


def test_the_schema_goes_out_as_an_openai_json_schema_response_format(
    scripted_server: Start,
) -> None:
    server = scripted_server(
        {("POST", "/v1/chat/completions"): Reply(COMPLETION), ("GET", "/v1/models"): Reply(MODELS)}
    )
    result = OpenAIBackend(base_url=f"{server.url}/v1").chat(
        WEATHER_PROMPT, schema=WEATHER_SCHEMA, seed=3, max_tokens=50
    )
    sent = server.requests[-1]["json"]
    assert sent["response_format"]["type"] == "json_schema"
    assert sent["response_format"]["json_schema"]["schema"] == WEATHER_SCHEMA
    assert (sent["model"], sent["seed"], sent["max_tokens"]) == ("served-model", 3, 50)
    assert result.data == {"weather": "rain", "intensity": "heavy"}
    assert (result.prompt_tokens, result.completion_tokens) == (30, 12)


def test_connection_refused_is_unavailable_and_names_a_server_command() -> None:
    backend = OpenAIBackend("m", base_url=f"http://127.0.0.1:{free_port()}/v1")
    with pytest.raises(BackendUnavailable) as caught:
        backend.chat(WEATHER_PROMPT)
    assert caught.value.fix is not None and "llama_cpp.server" in caught.value.fix


def test_a_server_slower_than_the_timeout_raises_backend_timeout(scripted_server: Start) -> None:
    server = scripted_server({("POST", "/v1/chat/completions"): Reply(COMPLETION, delay_s=1.0)})
    with pytest.raises(BackendTimeout):
        OpenAIBackend("m", base_url=f"{server.url}/v1").chat(WEATHER_PROMPT, timeout_s=0.2)


def test_a_reply_that_is_not_json_raises_invalid_output(scripted_server: Start) -> None:
    server = scripted_server(
        {("POST", "/v1/chat/completions"): Reply("<html>Welcome</html>", content_type="text/html")}
    )
    with pytest.raises(InvalidOutput) as caught:
        OpenAIBackend("m", base_url=f"{server.url}/v1").chat(WEATHER_PROMPT)
    assert caught.value.reason == "not_json" and caught.value.raw == "<html>Welcome</html>"


def test_a_cut_off_reply_raises_invalid_output(scripted_server: Start) -> None:
    server = scripted_server({("POST", "/v1/chat/completions"): Reply(COMPLETION, truncate=True)})
    with pytest.raises(InvalidOutput) as caught:
        OpenAIBackend("m", base_url=f"{server.url}/v1").chat(WEATHER_PROMPT)
    assert caught.value.reason == "truncated"


def test_a_model_answer_that_is_not_json_raises_invalid_output_with_the_raw_text(
    scripted_server: Start,
) -> None:
    reply = {**COMPLETION, "choices": [{"message": {"content": "It is raining."}}]}
    server = scripted_server({("POST", "/v1/chat/completions"): Reply(reply)})
    with pytest.raises(InvalidOutput) as caught:
        OpenAIBackend("m", base_url=f"{server.url}/v1").chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA)
    assert caught.value.reason == "not_json" and caught.value.raw == "It is raining."


def test_a_rejected_api_key_names_the_setting_that_fixes_it(scripted_server: Start) -> None:
    server = scripted_server({("POST", "/v1/chat/completions"): Reply({"error": "invalid key"}, status=401)})
    with pytest.raises(BackendUnavailable) as caught:
        OpenAIBackend("m", base_url=f"{server.url}/v1", api_key="x").chat(WEATHER_PROMPT)
    assert caught.value.fix is not None and "DRIVETWIN_OPENAI_API_KEY" in caught.value.fix


def test_a_server_error_is_a_backend_error_with_its_status(scripted_server: Start) -> None:
    server = scripted_server({("POST", "/v1/chat/completions"): Reply({"error": "out of memory"}, status=503)})
    with pytest.raises(BackendError, match="HTTP 503"):
        OpenAIBackend("m", base_url=f"{server.url}/v1").chat(WEATHER_PROMPT)


def test_a_server_that_refuses_json_schema_is_asked_again_with_json_object(scripted_server: Start) -> None:
    refusal = Reply({"error": {"message": "response_format.type: Input should be 'text' or 'json_object'"}}, status=422)
    server = scripted_server({("POST", "/v1/chat/completions"): refusal})
    backend = OpenAIBackend("m", base_url=f"{server.url}/v1")
    with pytest.raises(BackendError, match="HTTP 422"):  # the retry is refused too: reported, not looped
        backend.chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA)
    formats = [r["json"]["response_format"] for r in server.requests]
    assert [f["type"] for f in formats] == ["json_schema", "json_object"]
    assert formats[1]["schema"] == WEATHER_SCHEMA

    server.routes[("POST", "/v1/chat/completions")] = Reply(COMPLETION)
    assert backend.chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA).data == {"weather": "rain", "intensity": "heavy"}
    assert server.requests[-1]["json"]["response_format"]["type"] == "json_object"  # remembered
