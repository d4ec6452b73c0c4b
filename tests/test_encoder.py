"""Text encoders: Flax MiniLM against sentence-transformers reference values, buckets, cache, hashing."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from ragnav_jax.memory.encoder import HashingEmbedder, MiniLMEmbedder, TextCache, make_embedder

REFERENCE = Path(__file__).parent / "data" / "minilm_reference.json"


@pytest.fixture(scope="module")
def minilm():
    return MiniLMEmbedder(batch_size=16, buckets=(16, 32, 64))


@pytest.fixture(scope="module")
def reference(minilm):
    ref = json.loads(REFERENCE.read_text())
    return ref, minilm.embed(ref["sentences"])  # the 12 sentences, once


def test_minilm_matches_sentence_transformers(reference):
    ref, out = reference
    want = np.asarray(ref["embeddings"], np.float32)
    assert out.shape == want.shape == (12, 384)
    assert "" in ref["sentences"]
    for i, s in enumerate(ref["sentences"]):
        cos = float(out[i] @ want[i] / np.linalg.norm(want[i]))
        diff = float(np.abs(out[i] - want[i]).max())
        assert cos >= 0.9999 and diff <= 1e-5, (s, cos, diff)
    np.testing.assert_allclose(np.linalg.norm(out, axis=1), 1.0, atol=1e-5)


def test_minilm_cache_and_buckets(minilm, reference):
    ref, out = reference
    hits = minilm.cache.hits
    again = minilm.embed(ref["sentences"][::-1])
    np.testing.assert_array_equal(again, out[::-1])
    assert minilm.cache.hits == hits + 12  # served from the cache
    # New sentences of other lengths in an already-compiled bucket do not retrace the jitted model.
    minilm.embed(["a bed", "a lamp"])  # compiles the (8, 16) shape at most once
    sizes_before = minilm._apply._cache_size()
    minilm.embed(["a green armchair", "a television", "the kettle is hot and steaming today"])  # same bucket
    assert minilm._apply._cache_size() == sizes_before
    # Semantics: synonyms are close, unrelated texts are not.
    e = minilm.embed(["a couch", "a sofa", "a stainless steel sink"])
    assert e[0] @ e[1] > e[0] @ e[2] + 0.2


def test_hashing_embedder_deterministic_unit():
    h1, h2 = HashingEmbedder(64), HashingEmbedder(64)
    texts = ["a red sofa", "", "A red sofa", "kitchen sink"]
    a, b = h1.embed(texts), h2.embed(texts)
    np.testing.assert_array_equal(a, b)
    assert a.shape == (4, 64) and a.dtype == np.float32
    np.testing.assert_allclose(np.linalg.norm(a[[0, 2, 3]], axis=1), 1.0, atol=1e-6)
    assert np.all(a[1] == 0)  # nothing to hash
    np.testing.assert_array_equal(a[0], a[2])  # case-insensitive
    assert h1.embed([]).shape == (0, 64)


def test_text_cache_counts():
    c = TextCache()
    assert c.split(["a", "b", "a"]) == ["a", "b"]
    c.put(["a", "b"], np.eye(2, dtype=np.float32))
    assert c.split(["a", "b", "c"]) == ["c"]
    assert c.hits == 3 and c.misses == 3


def test_make_embedder_unknown():
    from ragnav_jax.errors import UserError

    assert make_embedder("hashing", dim=32).dim == 32
    with pytest.raises(UserError, match="unknown embedder"):
        make_embedder("bert-huge")
