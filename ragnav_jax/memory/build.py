"""Building the memory bank of a scene set from its exploration streams.

Stages (timed; host work between batched phases only):
  keyposes    host, per scene: key-pose selection and node observations        (keyposes.py)
  captioning  host, per scene: spatial fingerprints                             (captioner.py)
  embedding   one batched encoder call over every caption of the set            (encoder.py)
  edges       jit, over scenes: D_ij, free-segment edges                        (topomap.py)
  apsp        jit + vmap over scenes: Floyd-Warshall costs and predecessors     (paths.py)
  forest      jit + vmap over scenes: hybrid distance, dendrogram, levels       (forest.py)
  summaries   host: components, parent labels and summaries                     (summarise.py)
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Sequence

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.config import Config, MemoryConfig, to_dict
from ragnav_jax.memory import captioner as cap
from ragnav_jax.memory.forest import build_forest_batched
from ragnav_jax.memory.keyposes import KeyframeRule, NodeObservation, node_sensors, observe, select_key_poses
from ragnav_jax.memory.paths import batched_shortest_paths, connected_components, edge_weights
from ragnav_jax.memory.summarise import Summariser, leaf_label, llm_summary
from ragnav_jax.memory.topomap import batched_edges, obstacles_from_arrays, obstacles_numpy
from ragnav_jax.memory.types import DualBasisMemory, MemoryBank, MemoryMeta, scene_fingerprint
from ragnav_jax.sim.stream import ExplorationStream
from ragnav_jax.world.arrays import pad_sizes, stack_scenes
from ragnav_jax.world.scene import Scene

STAGES = ("keyposes", "captioning", "embedding", "edges", "apsp", "forest", "summaries")


def keyframe_rule(m: MemoryConfig) -> KeyframeRule:
    return KeyframeRule(m.keyframe_rule, m.keyframe_spacing, m.keyframe_min_spacing, m.novelty_threshold,
                        m.delta_spatial, m.edge_clearance, m.observation_window)


def caption_noise(m: MemoryConfig) -> cap.CaptionNoise:
    return cap.CaptionNoise(m.caption_detect_near, m.caption_detect_falloff, 0.8, m.caption_confusion,
                            m.caption_synonym, m.caption_attribute_keep, m.caption_sensor_text, m.caption_max_objects)


@dataclasses.dataclass
class BuildStats:
    stage_seconds: dict[str, float]  # totals over the set (batched stages: one call for all scenes)
    scene_seconds: dict[str, dict[str, float]]  # scene -> host stage -> seconds
    texts_embedded: int  # distinct texts the encoder actually ran on (cache misses)
    embed_seconds: float
    captions_rejected: tuple[str, ...] = ()  # memory.captioner=llm: "scene node N: why" per reply replaced by a template caption


def _check_stream(scene: Scene, stream: ExplorationStream) -> None:
    from ragnav_jax.errors import UserError

    ids = tuple(o.id for o in scene.objects)
    if stream.object_ids != ids:
        raise UserError(f"stream of scene '{scene.name}' lists objects {stream.object_ids[:3]}..., "
                        f"the scene file {ids[:3]}...: they must follow scene.objects order")
    if stream.pose.shape[0] == 0:
        raise UserError(f"stream of scene '{scene.name}' has no records")


def _pad(n: int, multiple: int) -> int:
    return max(multiple, int(math.ceil(max(n, 1) / multiple)) * multiple)


def build_bank(scenes: Sequence[Scene], streams: Sequence[ExplorationStream], cfg: Config, embedder=None,
               progress: bool = False) -> tuple[MemoryBank, BuildStats]:
    """Memories of every scene (streams in the same order) as one MemoryBank."""
    from tqdm.auto import tqdm

    from ragnav_jax.memory.encoder import make_embedder

    m = cfg.memory
    B = len(scenes)
    timings = {k: 0.0 for k in STAGES}
    per_scene: dict[str, dict[str, float]] = {}
    bar = tqdm(total=B + 5, desc="memory", unit="step", disable=not progress)
    if embedder is None:
        embedder = make_embedder(m.embedder, dim=m.hashing_dim, batch_size=m.embed_batch, buckets=m.token_buckets)

    # Host stages per scene.
    rule, noise = keyframe_rule(m), caption_noise(m)
    sensor_names = tuple(sorted({k for s in scenes for o in s.objects for k, _ in o.sensors}))
    observations: list[list[NodeObservation]] = []
    captions: list[list[cap.Caption]] = []
    rejected: list[str] = []  # LLM replies that were not captions (memory.captioner=llm)
    asked = 0
    for scene, stream in zip(scenes, streams):
        bar.set_description(f"memory: key poses + captions {scene.name}")
        _check_stream(scene, stream)
        t0 = time.perf_counter()
        records = select_key_poses(stream, obstacles_numpy(scene), rule)
        obs = observe(stream, records, rule.window)
        t1 = time.perf_counter()
        caps = [cap.template_caption(scene, o, i, cfg.seed, noise) for i, o in enumerate(obs)]
        if m.captioner == "llm":
            answers = [cap.llm_caption(scene, o, cfg.llm, fallback) for o, fallback in zip(obs, caps)]
            caps = [c for c, _ in answers]
            rejected += [f"{scene.name} node {i}: {why}" for i, (_, why) in enumerate(answers) if why]
            asked += len(answers)
        t2 = time.perf_counter()
        per_scene[scene.name] = {"keyposes": t1 - t0, "captioning": t2 - t1}
        timings["keyposes"] += t1 - t0
        timings["captioning"] += t2 - t1
        observations.append(obs)
        captions.append(caps)
        bar.update(1)
    if asked and len(rejected) == asked:
        from ragnav_jax.errors import UserError

        raise UserError(f"memory.captioner=llm: none of the {asked} replies of {cfg.llm.base_url} reads as a caption "
                        f"({rejected[0]}); check llm.model, or use memory.captioner=template")

    # Embedding: one call for the whole set.
    bar.set_description("memory: embedding")
    t0 = time.perf_counter()
    before = embedder.stats["encoded"]
    flat = [c.text for caps in captions for c in caps]
    vecs = embedder.embed(flat)
    timings["embedding"] = time.perf_counter() - t0
    bar.update(1)

    # Pad and stack.
    counts = [len(o) for o in observations]
    N = _pad(max(counts), m.node_pad_multiple)
    K, S, D = m.max_objects_per_node, max(len(sensor_names), 1), embedder.dim
    pos = np.zeros((B, N, 3), np.float32)
    yaw = np.zeros((B, N), np.float32)
    rec = np.full((B, N), -1, np.int32)
    mask = np.zeros((B, N), bool)
    emb = np.zeros((B, N, D), np.float32)
    sens = np.zeros((B, N, S), np.float32)
    smask = np.zeros((B, N, S), bool)
    oobj = np.full((B, N, K), -1, np.int32)
    odist = np.full((B, N, K), np.inf, np.float32)
    off = 0
    for b, (scene, obs) in enumerate(zip(scenes, observations)):
        n = len(obs)
        mask[b, :n] = True
        emb[b, :n] = vecs[off : off + n]
        off += n
        for i, o in enumerate(obs):
            pos[b, i], yaw[b, i], rec[b, i] = o.position, o.yaw, o.record
            if sensor_names:
                sens[b, i], smask[b, i] = node_sensors(scene, o, sensor_names)
            k = min(K, len(o.objects))
            oobj[b, i, :k] = o.objects[:k]
            odist[b, i, :k] = o.distances[:k]

    # Batched kernels.
    bar.set_description("memory: edges")
    arrays, _ = stack_scenes(list(scenes), pad_sizes(scenes))
    obs_arrays = obstacles_from_arrays(arrays, jnp)
    t0 = time.perf_counter()
    dist, adj = batched_edges(jnp.asarray(pos), jnp.asarray(mask), obs_arrays, jnp.float32(m.delta_spatial),
                              jnp.float32(m.edge_clearance))
    jax.block_until_ready(adj)
    timings["edges"] = time.perf_counter() - t0
    bar.update(1)

    bar.set_description("memory: shortest paths")
    t0 = time.perf_counter()
    cost, pred = batched_shortest_paths(jax.vmap(edge_weights)(adj, dist), jnp.asarray(mask))
    jax.block_until_ready(pred)
    timings["apsp"] = time.perf_counter() - t0
    bar.update(1)

    bar.set_description("memory: semantic forest")
    t0 = time.perf_counter()
    dendro, forest = build_forest_batched(
        jnp.asarray(pos), jnp.asarray(emb), jnp.asarray(mask), cost, jnp.float32(m.omega), jnp.float32(m.alpha),
        jnp.float32(m.spatial_scale), metric=m.forest_metric, spatial=m.spatial_distance, linkage=m.linkage,
        level_sizes=tuple(m.level_sizes),
    )
    jax.block_until_ready(forest)
    timings["forest"] = time.perf_counter() - t0
    bar.update(1)

    # Host: components, labels, summaries.
    bar.set_description("memory: summaries")
    t0 = time.perf_counter()
    adj_np = np.asarray(adj)
    comps = np.stack([connected_components(adj_np[b], mask[b]) for b in range(B)])
    summariser = Summariser()
    fr = jax.tree.map(np.asarray, forest)
    metas = []
    L = 1 + len(m.level_sizes)
    for b, scene in enumerate(scenes):
        n = counts[b]
        labels_of = [c.labels for c in captions[b]]
        tree_labels = [""] * (L * N)
        tree_summaries = [""] * (L * N)
        for i in range(n):
            tree_labels[i] = leaf_label(labels_of[i])
            tree_summaries[i] = captions[b][i].text
        for lvl in range(1, L):
            for k in range(N):
                slot = lvl * N + k
                if not fr.mask[b, slot]:
                    continue
                leaves = np.flatnonzero(fr.members[b, slot])
                kids = [int(c) for c in fr.children[b, slot] if c >= 0]
                sensors = {}
                for si, name in enumerate(sensor_names):
                    have = smask[b, leaves, si]
                    if have.any():
                        sensors[name] = float(sens[b, leaves, si][have].max() if name != "ndvi" else sens[b, leaves, si][have].mean())
                label, summary = summariser.summarise(lvl, [labels_of[i] for i in leaves], fr.position[b, slot], sensors,
                                                      [tree_labels[c] for c in kids] if lvl > 1 else [])
                if m.summariser == "llm":
                    label, summary = llm_summary(cfg.llm, lvl, [captions[b][i].text for i in leaves], (label, summary))
                tree_labels[slot], tree_summaries[slot] = label, summary
        metas.append(MemoryMeta(
            scene=scene.name, num_nodes=n, captions=tuple(c.text for c in captions[b]),
            caption_labels=tuple(labels_of), observed_ids=tuple(tuple(scene.objects[j].id for j in o.objects) for o in observations[b]),
            tree_labels=tuple(tree_labels), tree_summaries=tuple(tree_summaries),
            object_ids=tuple(o.id for o in scene.objects), sensor_names=sensor_names,
            num_components=int(comps[b].max() + 1) if n else 0, embedder=embedder.name, config=to_dict(m),
            caption_objects=tuple(c.objects for c in captions[b]), caption_phrases=tuple(c.phrases for c in captions[b]),
            fingerprint=scene_fingerprint(scene, to_dict(m)),
            object_seen=tuple(zip(*(map(int, v) for v in streams[b].view_times()))),
        ))
    timings["summaries"] = time.perf_counter() - t0
    bar.update(1)
    bar.close()

    memory = DualBasisMemory(
        node_mask=jnp.asarray(mask), position=jnp.asarray(pos), yaw=jnp.asarray(yaw), record=jnp.asarray(rec),
        embedding=jnp.asarray(emb), sensors=jnp.asarray(sens), sensor_mask=jnp.asarray(smask),
        obs_object=jnp.asarray(oobj), obs_distance=jnp.asarray(odist), distance=dist, adjacency=adj,
        path_cost=cost, path_pred=pred, component=jnp.asarray(comps),
        merges=dendro.merges, merge_height=dendro.heights, merge_size=dendro.sizes,
        tree_parent=forest.parent, tree_children=forest.children, tree_level=forest.level, tree_mask=forest.mask,
        tree_members=forest.members, tree_size=forest.size, tree_embedding=forest.embedding,
        tree_position=forest.position,
    )
    stats = BuildStats(timings, per_scene, embedder.stats["encoded"] - before, timings["embedding"], tuple(rejected))
    return MemoryBank(memory, tuple(metas)), stats


def memory_summary(bank: MemoryBank) -> dict:
    """The numbers of `RUN/memory/summary.json`."""
    mem = bank.memory
    rows = []
    adj = np.asarray(mem.adjacency)
    tm = np.asarray(mem.tree_mask)
    lv = np.asarray(mem.tree_level)
    for b, meta in enumerate(bank.metas):
        n = meta.num_nodes
        levels = [int((tm[b] & (lv[b] == lvl)).sum()) for lvl in range(int(lv[b].max()) + 1)]
        rows.append({
            "scene": meta.scene, "nodes": n, "edges": int(adj[b].sum() // 2), "components": meta.num_components,
            "mean_degree": round(float(adj[b].sum() / max(n, 1)), 2), "clusters_per_level": levels,
            "top_labels": [meta.tree_labels[(len(levels) - 1) * adj.shape[1] + k].split(":")[0] for k in range(levels[-1])],
        })
    nodes = [r["nodes"] for r in rows]
    return {
        "num_scenes": len(rows),
        "mean_nodes": float(np.mean(nodes)) if nodes else 0.0,
        "min_nodes": int(min(nodes, default=0)),
        "max_nodes": int(max(nodes, default=0)),
        "padded_nodes": int(adj.shape[1]),
        "all_connected": all(r["components"] == 1 for r in rows),
        "scenes": rows,
    }
