"""Builds RetrievalIndex arrays from a memory bank (host side, once per scene set).

Slots are the object instances each key pose *described* in its caption (the captioner's phrases,
with its perception noise), so retrieval never reads ground-truth categories. A slot's position and
readings are those of the instance the robot saw (detections are localised from pose + range +
bearing; with noiseless odometry that is the object's position, as the paper's simulator assumes).
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Sequence

import jax.numpy as jnp
import numpy as np

from ragnav_jax.memory.names import name_classes
from ragnav_jax.memory.types import DualBasisMemory, MemoryBank, MemoryMeta
from ragnav_jax.pytrees import stack, take
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
    instance_phrases: tuple[tuple[str, ...], ...] = ()  # (I,) every distinct phrase the captions used for each instance


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


ASSOCIATION_RADIUS = 0.15  # metres (3-D): detections closer than this are the same instance


def associate(positions: np.ndarray) -> np.ndarray:
    """Greedy data association of detections by estimated 3-D position: (K, 3) -> (K,) instance ids."""
    centres: list[np.ndarray] = []
    out = np.zeros(len(positions), np.int32)
    for k, p in enumerate(positions):
        for c, q in enumerate(centres):
            if np.linalg.norm(p - q) < ASSOCIATION_RADIUS:
                out[k] = c
                break
        else:
            out[k] = len(centres)
            centres.append(p)
    return out


def build_scene_index(
    mem: DualBasisMemory, meta: MemoryMeta, scene: Scene, embedder, max_slots: int, max_degree: int,
    max_instances: int | None = None, max_phrases: int = 8,
) -> tuple[RetrievalIndex, IndexMeta]:
    """One scene's RetrievalIndex (padded to the memory's N, max_slots, max_degree, max_instances)."""
    n_pad = int(mem.node_mask.shape[0])
    n = meta.num_nodes
    L = n_pad and int(mem.tree_level.shape[0]) // n_pad
    sensor_names = tuple(meta.sensor_names)
    S = max(len(sensor_names), 1)
    objs, phrases = node_slots(meta, scene)
    D = int(mem.embedding.shape[-1])
    # Detections (node, slot) -> instances by estimated position (exact here: noiseless odometry).
    dets = [(i, j, oi, ph) for i in range(n) for j, (oi, ph) in enumerate(list(zip(objs[i], phrases[i]))[:max_slots])]
    det_pos = np.array([scene.objects[oi].position for _, _, oi, _ in dets], np.float32).reshape(-1, 3)
    inst_of = associate(det_pos)
    n_inst = int(inst_of.max()) + 1 if len(dets) else 0
    I = max(max_instances or n_inst, n_inst, 1)
    said: list[list[str]] = [[] for _ in range(n_inst)]  # every distinct phrase; the first max_phrases are embedded
    called: dict[int, list[str]] = {c: [] for c in range(n_inst)}  # the captioner's name of the instance, per view
    inst_obj = [-1] * n_inst
    slot_inst = np.full((n_pad, max_slots), -1, np.int32)
    for (i, j, oi, ph), c in zip(dets, inst_of):
        slot_inst[i, j] = c
        inst_obj[c] = oi
        if ph not in said[c]:
            said[c].append(ph)
        if j < len(meta.caption_labels[i]):
            called[c].append(meta.caption_labels[i][j])
    inst_phr = [ps[:max_phrases] for ps in said]
    # What the memory mostly calls each instance, with the aliases it learnt for those names (memory/names.py, as the
    # verifier reads them; a name said once in confusion is left out): time-indexed queries rank among the instances
    # that go by the head noun.
    classes, frequent = name_classes(called)
    inst_names = [sorted({y for x in frequent[c] for y in classes[x]})[:max_phrases] for c in range(n_inst)]
    flat = sorted({p for ps in inst_phr + inst_names for p in ps})
    vec = dict(zip(flat, embedder.embed(flat))) if flat else {}
    inst_emb = np.zeros((I, max_phrases, D), np.float32)
    inst_pmask = np.zeros((I, max_phrases), bool)
    inst_pos = np.zeros((I, 3), np.float32)
    inst_sens = np.zeros((I, S), np.float32)
    inst_smask = np.zeros((I, S), bool)
    inst_mask = np.zeros((I,), bool)
    name_emb = np.zeros((I, max_phrases, D), np.float32)
    name_mask = np.zeros((I, max_phrases), bool)
    for c, names in enumerate(inst_names):
        for k, x in enumerate(names):
            name_emb[c, k], name_mask[c, k] = vec[x], True
    # When each instance was seen: the records of the first and the latest node that described it, widened by the
    # memory's sighting log (MemoryMeta.object_seen) where it has the object (every view, not only key poses).
    det_rec = np.asarray(mem.record).astype(np.float32)[[i for i, _, _, _ in dets]]
    inst_first, inst_last = np.full((I,), np.inf, np.float32), np.full((I,), -np.inf, np.float32)
    np.minimum.at(inst_first, inst_of[: len(dets)], det_rec)
    np.maximum.at(inst_last, inst_of[: len(dets)], det_rec)
    inst_first[n_inst:], inst_last[n_inst:] = 0.0, 0.0
    for c in range(n_inst):
        if inst_obj[c] < len(meta.object_seen) and meta.object_seen[inst_obj[c]][0] >= 0:
            first, last = meta.object_seen[inst_obj[c]]
            inst_first[c], inst_last[c] = min(inst_first[c], first), max(inst_last[c], last)
    for c in range(n_inst):
        for k, ph in enumerate(inst_phr[c]):
            inst_emb[c, k], inst_pmask[c, k] = vec[ph], True
        o = scene.objects[inst_obj[c]]
        inst_pos[c], inst_mask[c] = det_pos[np.flatnonzero(inst_of == c)].mean(0), True
        for key, v in o.sensors:
            if key in sensor_names:
                inst_sens[c, sensor_names.index(key)], inst_smask[c, sensor_names.index(key)] = v, True
    adj = np.asarray(mem.adjacency)
    nbr = np.full((n_pad, max_degree), -1, np.int32)
    for i in range(n_pad):
        nb = np.flatnonzero(adj[i])[:max_degree]
        nbr[i, : len(nb)] = nb
    # Forest levels above the leaves; cluster embeddings blend the mean fingerprint with the summary label;
    # label embeddings alone (the inferred area type before ':') drive the soft room term.
    tree_emb = np.asarray(mem.tree_embedding)
    labels = list(meta.tree_labels)
    area = [lab.split(":", 1)[0].strip() for lab in labels]
    texts = sorted({t for s_ in range(n_pad, L * n_pad) for t in (labels[s_], area[s_]) if t})
    tvec = dict(zip(texts, embedder.embed(texts))) if texts else {}
    Lc = max(L - 1, 1)
    cluster_emb = np.zeros((Lc, n_pad, D), np.float32)
    cluster_label = np.zeros((Lc, n_pad, D), np.float32)
    cluster_mask = np.zeros((Lc, n_pad), bool)
    cluster_parent = np.full((Lc, n_pad), -1, np.int32)
    tmask, tparent = np.asarray(mem.tree_mask), np.asarray(mem.tree_parent)
    for lvl in range(1, L):
        for k in range(n_pad):
            s_ = lvl * n_pad + k
            if not tmask[s_]:
                continue
            e = tree_emb[s_] + (tvec[labels[s_]] if labels[s_] in tvec else 0.0)
            cluster_emb[lvl - 1, k] = e / max(np.linalg.norm(e), 1e-12)
            if area[s_] in tvec:
                cluster_label[lvl - 1, k] = tvec[area[s_]]
            cluster_mask[lvl - 1, k] = True
            if tparent[s_] >= 0 and lvl + 1 < L:
                cluster_parent[lvl - 1, k] = tparent[s_] - (lvl + 1) * n_pad
    if L <= 1:  # no forest levels: one cluster holding everything
        cluster_emb[0, 0], cluster_mask[0, 0] = 1.0, True
    leaf_cluster = _ancestors(mem, n_pad, L) if L > 1 else np.where(np.asarray(mem.node_mask), 0, -1)[:, None].astype(np.int32)
    slot_mask = slot_inst >= 0
    index = RetrievalIndex(
        node_emb=mem.embedding, node_pos=mem.position, node_mask=mem.node_mask & jnp.asarray(slot_mask.any(1)),
        nbr=jnp.asarray(nbr), nbr_mask=jnp.asarray(nbr >= 0), inst_emb=jnp.asarray(inst_emb),
        inst_phrase_mask=jnp.asarray(inst_pmask), inst_name_emb=jnp.asarray(name_emb),
        inst_name_mask=jnp.asarray(name_mask), inst_pos=jnp.asarray(inst_pos), inst_sensors=jnp.asarray(inst_sens),
        inst_sensor_mask=jnp.asarray(inst_smask), inst_mask=jnp.asarray(inst_mask), inst_first=jnp.asarray(inst_first),
        inst_last=jnp.asarray(inst_last), slot_inst=jnp.asarray(slot_inst),
        slot_mask=jnp.asarray(slot_mask), cluster_emb=jnp.asarray(cluster_emb),
        cluster_label_emb=jnp.asarray(cluster_label), cluster_mask=jnp.asarray(cluster_mask),
        cluster_parent=jnp.asarray(cluster_parent), leaf_cluster=jnp.asarray(leaf_cluster),
    )
    obs = np.asarray(mem.obs_object)
    observed = tuple(frozenset(int(x) for x in obs[i] if x >= 0) for i in range(n))
    meta_out = IndexMeta(scene.name, n, tuple(tuple(o[:max_slots]) for o in objs),
                         tuple(tuple(p[:max_slots]) for p in phrases), observed, sensor_names,
                         tuple(tuple(ps) for ps in said))
    return index, meta_out


def count_instances(meta: MemoryMeta, scene: Scene, max_slots: int) -> int:
    objs, _ = node_slots(meta, scene)
    pos = np.array([scene.objects[oi].position for o in objs for oi in o[:max_slots]], np.float32).reshape(-1, 3)
    return int(associate(pos).max()) + 1 if len(pos) else 1


def build_bank_index(bank: MemoryBank, scenes: Sequence[Scene], embedder, max_slots: int | None = None):
    """RetrievalIndex for every scene of a bank, stacked with a leading scene axis (B, ...)."""

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
    max_inst = max(count_instances(m, by_name[m.scene], max_slots) for m in bank.metas)
    out, metas = [], []
    for b, meta in enumerate(bank.metas):
        mem = take(bank.memory, b)
        idx, im = build_scene_index(mem, meta, by_name[meta.scene], embedder, max_slots, max_degree, max_inst)
        out.append(idx)
        metas.append(im)
    return stack(out), tuple(metas)
