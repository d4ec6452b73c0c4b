"""RAG baselines on the same embedder and node texts as RAGNav.

These are reimplementations of the *retrieval mechanisms* of the paper's baselines, documented as such
(not the original systems, which need LLM calls at index time):
- NaiveRAG (Lewis et al.): every node caption is a text chunk; flat top-1 by cosine to the query text.
- GraphRAG-style (Edge et al., local search): an entity graph whose vertices are the object phrases of
  the captions and whose edges join phrases seen at the same node; Louvain communities (networkx) with
  summaries (their most frequent phrases); local search ranks chunks by their best entity match to the
  query plus the similarity of their community summary.
- LightRAG-style (Guo et al.): dual-level keys, low-level entity keys (object phrases) and high-level
  theme keys (the community/area summaries); hybrid retrieval averages the best low-level and the
  best high-level match of each chunk.
All baselines see the query as one flat text (the subgoal's words, hints and readings included), as the
paper describes ("segmenting multimodal embodied data into text").
"""

from __future__ import annotations

import dataclasses
from collections import Counter
from collections.abc import Sequence

import networkx as nx
import numpy as np


@dataclasses.dataclass(frozen=True)
class TextMemory:
    """Host-side text view of one scene's memory."""

    captions: tuple[str, ...]  # (N,) node fingerprints
    phrases: tuple[tuple[str, ...], ...]  # (N, *) object phrases mentioned by each caption


def _unit(x: np.ndarray) -> np.ndarray:
    return x / np.maximum(np.linalg.norm(x, axis=-1, keepdims=True), 1e-12)


class NaiveRAG:
    name = "naive_rag"

    def __init__(self, mem: TextMemory, embedder):
        self.chunks = _unit(embedder.embed(list(mem.captions)))
        self.embedder = embedder

    def scores(self, queries: Sequence[str]) -> np.ndarray:
        """(Q, N) chunk scores."""
        return _unit(self.embedder.embed(list(queries))) @ self.chunks.T


class _EntityGraph:
    """Entities (distinct phrases), their co-occurrence graph and Louvain communities."""

    def __init__(self, mem: TextMemory, embedder, seed: int = 0):
        self.entities = sorted({p for ps in mem.phrases for p in ps})
        self.ent_index = {e: k for k, e in enumerate(self.entities)}
        g = nx.Graph()
        g.add_nodes_from(range(len(self.entities)))
        for ps in mem.phrases:
            ids = sorted({self.ent_index[p] for p in ps})
            for a in range(len(ids)):
                for b in range(a + 1, len(ids)):
                    w = g.get_edge_data(ids[a], ids[b], {"weight": 0})["weight"]
                    g.add_edge(ids[a], ids[b], weight=w + 1)
        comms = nx.community.louvain_communities(g, weight="weight", seed=seed) if len(g) else []
        self.community_of = np.zeros(len(self.entities), int)
        self.summaries = []
        counts = Counter(p for ps in mem.phrases for p in ps)
        for c, members in enumerate(sorted(comms, key=lambda s: min(s))):
            for e in members:
                self.community_of[e] = c
            top = sorted(members, key=lambda e: (-counts[self.entities[e]], self.entities[e]))[:6]
            self.summaries.append("area with " + ", ".join(self.entities[e] for e in top))
        self.ent_emb = _unit(embedder.embed(self.entities)) if self.entities else np.zeros((0, embedder.dim))
        self.sum_emb = _unit(embedder.embed(self.summaries)) if self.summaries else np.zeros((0, embedder.dim))
        # chunk -> entities (N, E) incidence and chunk -> community (its most frequent community)
        self.incidence = np.zeros((len(mem.phrases), len(self.entities)), bool)
        self.chunk_comm = np.zeros(len(mem.phrases), int)
        for i, ps in enumerate(mem.phrases):
            ids = [self.ent_index[p] for p in ps]
            self.incidence[i, ids] = True
            if ids:
                self.chunk_comm[i] = Counter(self.community_of[ids]).most_common(1)[0][0]


class GraphRAGLocal:
    name = "graphrag"

    def __init__(self, mem: TextMemory, embedder, seed: int = 0):
        self.g = _EntityGraph(mem, embedder, seed)
        self.embedder = embedder
        self.chunks = _unit(embedder.embed(list(mem.captions)))

    def scores(self, queries: Sequence[str]) -> np.ndarray:
        q = _unit(self.embedder.embed(list(queries)))  # (Q, D)
        if not self.g.entities:
            return q @ self.chunks.T
        ent = q @ self.g.ent_emb.T  # (Q, E)
        # Local search: the query's entry entities are its top matches; chunks holding them are candidates.
        best_ent = np.where(self.g.incidence[None], ent[:, None, :], -1.0).max(-1)  # (Q, N)
        comm = (q @ self.g.sum_emb.T)[:, self.g.chunk_comm] if len(self.g.summaries) else 0.0
        return 0.6 * best_ent + 0.2 * comm + 0.2 * (q @ self.chunks.T)


class LightRAGHybrid:
    name = "lightrag"

    def __init__(self, mem: TextMemory, embedder, seed: int = 0):
        self.g = _EntityGraph(mem, embedder, seed)
        self.embedder = embedder

    def scores(self, queries: Sequence[str]) -> np.ndarray:
        q = _unit(self.embedder.embed(list(queries)))
        if not self.g.entities:
            return np.zeros((len(queries), len(self.g.incidence)))
        low = np.where(self.g.incidence[None], (q @ self.g.ent_emb.T)[:, None, :], -1.0).max(-1)  # (Q, N)
        high = (q @ self.g.sum_emb.T)[:, self.g.chunk_comm]
        return 0.5 * low + 0.5 * high


BASELINES = {"naive_rag": NaiveRAG, "graphrag": GraphRAGLocal, "lightrag": LightRAGHybrid}
