"""Builds RetrievalIndex arrays from a memory bank (host side, once per scene set).

Slots are the object instances each key pose *described* in its caption (the captioner's phrases,
with its perception noise), so retrieval never reads ground-truth categories. A slot's position and
readings are those of the instance the robot saw (detections are localised from pose + range +
bearing; with noiseless odometry that is the object's position, as the paper's simulator assumes).
"""

from __future__ import annotations

import dataclasses
import re
from typing import Sequence

import jax.numpy as jnp
import numpy as np

from ragnav_jax.memory.types import DualBasisMemory, MemoryBank, MemoryMeta
from ragnav_jax.retrieval.score import RetrievalIndex
from ragnav_jax.world.scene import Scene

_ARTICLE = re.compile(r"^(a|an|the)\s+", re.I)


@dataclasses.dataclass(frozen=True)
class IndexMeta:
    scene: str
    num_nodes: int
    slot_objects: tuple[tuple[int, ...], ...]  # (n, *) scene object index of each slot
    slot_phrases: tuple[tuple[str, ...], ...]  # (n, *) caption phrase of each slot
    observed: tuple[frozenset[int], ...]  # (n,) every object visible from the node (accuracy rule)
    sensor_names: tuple[str, ...]


def node_slots(meta: MemoryMeta, scene: Scene) -> tuple[list[list[int]], list[list[str]]]:
    """(object indices, phrases) each node's caption describes."""
    objs, phrases = meta.caption_objects, meta.caption_phrases
    if len(objs) != meta.num_nodes:  # memories built before captions recorded their instances
        ids = {o.id: k for k, o in enumerate(scene.objects)}
        objs = [[ids[i] for i in obs[: len(lab)]] for obs, lab in zip(meta.observed_ids, meta.caption_labels)]
        phrases = [list(lab) for lab in meta.caption_labels]
    return [list(map(int, o)) for o in objs], [[_ARTICLE.sub("", p) for p in ps] for ps in phrases]


def _ancestors(mem: DualBasisMemory, n_pad: int, levels: int) -> np.ndarray:
    """(N, L-1) cluster index within each level >= 1 of every leaf (-1 for padding)."""
    members = np.asarray(mem.tree_members)  # (M, N)
    mask = np.asarray(mem.tree_mask)
    out = np.full((n_pad, max(levels - 1, 1)), -1, np.int32)
    for lvl in range(1, levels):
        block = members[lvl * n_pad : (lvl + 1) * n_pad] & mask[lvl * n_pad : (lvl + 1) * n_pad, None]  # (C, N)
        has = block.any(0)
        out[has, lvl - 1] = np.argmax(block, axis=0)[has]
    return out


def build_scene_index(
    mem: DualBasisMemory, meta: MemoryMeta, scene: Scene, embedder, max_slots: int, max_degree: int,
) -> tuple[RetrievalIndex, IndexMeta]:
    """One scene's RetrievalIndex (padded to the memory's N, max_slots, max_degree)."""
    n_pad = int(mem.node_mask.shape[0])
    n = meta.num_nodes
    L = n_pad and int(mem.tree_level.shape[0]) // n_pad
    sensor_names = tuple(meta.sensor_names)
    S = max(len(sensor_names), 1)
    objs, phrases = node_slots(meta, scene)
    flat = sorted({p for ps in phrases for p in ps})
    vec = dict(zip(flat, embedder.embed(flat))) if flat else {}
    D = int(mem.embedding.shape[-1])
    slot_emb = np.zeros((n_pad, max_slots, D), np.float32)
    slot_pos = np.zeros((n_pad, max_slots, 3), np.float32)
    slot_sens = np.zeros((n_pad, max_slots, S), np.float32)
    slot_smask = np.zeros((n_pad, max_slots, S), bool)
    slot_mask = np.zeros((n_pad, max_slots), bool)
    for i in range(n):
        for j, (oi, ph) in enumerate(list(zip(objs[i], phrases[i]))[:max_slots]):
            o = scene.objects[oi]
            slot_emb[i, j], slot_pos[i, j], slot_mask[i, j] = vec[ph], o.position, True
            for k, v in o.sensors:
                if k in sensor_names:
                    slot_sens[i, j, sensor_names.index(k)] = v
                    slot_smask[i, j, sensor_names.index(k)] = True
    adj = np.asarray(mem.adjacency)
    nbr = np.full((n_pad, max_degree), -1, np.int32)
    for i in range(n_pad):
        nb = np.flatnonzero(adj[i])[:max_degree]
        nbr[i, : len(nb)] = nb
    # Forest levels above the leaves; cluster embeddings blend the mean fingerprint with the summary label.
    tree_emb = np.asarray(mem.tree_embedding)
    labels = list(meta.tree_labels)
    lab_texts = sorted({labels[s] for s in range(n_pad, L * n_pad) if labels[s]})
    lab_vec = dict(zip(lab_texts, embedder.embed(lab_texts))) if lab_texts else {}
    Lc = max(L - 1, 1)
    cluster_emb = np.zeros((Lc, n_pad, D), np.float32)
    cluster_mask = np.zeros((Lc, n_pad), bool)
    cluster_parent = np.full((Lc, n_pad), -1, np.int32)
    tmask, tparent = np.asarray(mem.tree_mask), np.asarray(mem.tree_parent)
    for lvl in range(1, L):
        for k in range(n_pad):
            s = lvl * n_pad + k
            if not tmask[s]:
                continue
            e = tree_emb[s] + (lab_vec[labels[s]] if labels[s] in lab_vec else 0.0)
            cluster_emb[lvl - 1, k] = e / max(np.linalg.norm(e), 1e-12)
            cluster_mask[lvl - 1, k] = True
            if tparent[s] >= 0 and lvl + 1 < L:
                cluster_parent[lvl - 1, k] = tparent[s] - (lvl + 1) * n_pad
    if L <= 1:  # no forest levels: one cluster holding everything
        cluster_emb[0, 0], cluster_mask[0, 0] = 1.0, True
    leaf_cluster = _ancestors(mem, n_pad, L) if L > 1 else np.where(np.asarray(mem.node_mask), 0, -1)[:, None].astype(np.int32)
    index = RetrievalIndex(
        node_emb=mem.embedding, node_pos=mem.position, node_mask=mem.node_mask & jnp.asarray(slot_mask.any(1)),
        nbr=jnp.asarray(nbr), nbr_mask=jnp.asarray(nbr >= 0), slot_emb=jnp.asarray(slot_emb),
        slot_pos=jnp.asarray(slot_pos), slot_sensors=jnp.asarray(slot_sens), slot_sensor_mask=jnp.asarray(slot_smask),
        slot_mask=jnp.asarray(slot_mask), cluster_emb=jnp.asarray(cluster_emb), cluster_mask=jnp.asarray(cluster_mask),
        cluster_parent=jnp.asarray(cluster_parent), leaf_cluster=jnp.asarray(leaf_cluster),
    )
    obs = np.asarray(mem.obs_object)
    observed = tuple(frozenset(int(x) for x in obs[i] if x >= 0) for i in range(n))
    meta_out = IndexMeta(scene.name, n, tuple(tuple(o[:max_slots]) for o in objs),
                         tuple(tuple(p[:max_slots]) for p in phrases), observed, sensor_names)
    return index, meta_out


def build_bank_index(bank: MemoryBank, scenes: Sequence[Scene], embedder, max_slots: int | None = None):
    """RetrievalIndex for every scene of a bank, stacked with a leading scene axis (B, ...)."""
    import jax

    by_name = {s.name: s for s in scenes}
    missing = [m.scene for m in bank.metas if m.scene not in by_name]
    if missing:
        from ragnav_jax.errors import UserError

        raise UserError(f"memory holds scenes with no scene file: {', '.join(missing)}")
    adj = np.asarray(bank.memory.adjacency)
    max_degree = max(int(adj.sum(-1).max()), 1)
    if max_slots is None:
        max_slots = max(max((len(o) for o in node_slots(m, by_name[m.scene])[0]), default=1) for m in bank.metas)
        max_slots = max(max_slots, 1)
    out, metas = [], []
    for b, meta in enumerate(bank.metas):
        mem = jax.tree.map(lambda x: x[b], bank.memory)
        idx, im = build_scene_index(mem, meta, by_name[meta.scene], embedder, max_slots, max_degree)
        out.append(idx)
        metas.append(im)
    return jax.tree.map(lambda *xs: jnp.stack(xs), *out), tuple(metas)
