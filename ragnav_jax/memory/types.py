"""DualBasisMemory M = {G_t, T_s}: padded arrays (a flax struct pytree) plus host metadata; the memory bank.

Shapes for one scene: N padded nodes, K observed objects per node, S sensor channels, D embedding size,
L forest levels, M = L * N forest slots (slot l * N + k is cluster k of level l; level 0 are the nodes).
A bank stacks the scenes of a set with a leading axis B (same N, K, S, D, L for all).
"""

from __future__ import annotations

import dataclasses
import hashlib
import json

import jax.numpy as jnp
import numpy as np
from flax import struct

from ragnav_jax.pytrees import stack, take

FORMAT_VERSION = 1


@struct.dataclass
class DualBasisMemory:
    # topological map G_t
    node_mask: jnp.ndarray  # (N,) bool real nodes
    position: jnp.ndarray  # (N, 3) float32 x, y, z of the key pose
    yaw: jnp.ndarray  # (N,) float32 heading of the key pose
    record: jnp.ndarray  # (N,) int32 index of the key pose's record in the exploration stream, -1 padding
    embedding: jnp.ndarray  # (N, D) float32 unit fingerprint embeddings psi(d_i)
    sensors: jnp.ndarray  # (N, S) float32 mean reading of the seen objects per channel, 0 where none
    sensor_mask: jnp.ndarray  # (N, S) bool some seen object reports the channel
    obs_object: jnp.ndarray  # (N, K) int32 seen objects (index into scene.objects), nearest first, -1 padded
    obs_distance: jnp.ndarray  # (N, K) float32 metres to them, inf padded
    distance: jnp.ndarray  # (N, N) float32 Euclidean D_ij
    adjacency: jnp.ndarray  # (N, N) bool edges: D_ij < delta_spatial and the segment is free
    path_cost: jnp.ndarray  # (N, N) float32 shortest-path length over G_t, inf where unreachable
    path_pred: jnp.ndarray  # (N, N) int32 predecessor of j on a shortest i -> j path, -1 none (see paths.py)
    component: jnp.ndarray  # (N,) int32 connected component, -1 padding
    # semantic forest T_s
    merges: jnp.ndarray  # (N-1, 2) int32 dendrogram, scipy-style ids; -1 unused
    merge_height: jnp.ndarray  # (N-1,) float32 merge distances, inf unused
    merge_size: jnp.ndarray  # (N-1,) int32
    tree_parent: jnp.ndarray  # (M,) int32 parent slot, -1 roots/padding
    tree_children: jnp.ndarray  # (M, N) int32 child slots ascending, -1 padded
    tree_level: jnp.ndarray  # (M,) int32
    tree_mask: jnp.ndarray  # (M,) bool
    tree_members: jnp.ndarray  # (M, N) bool leaves (nodes) under each slot
    tree_size: jnp.ndarray  # (M,) int32 leaves under each slot
    tree_embedding: jnp.ndarray  # (M, D) float32 unit rows; parents: normalised mean of their children
    tree_position: jnp.ndarray  # (M, 3) float32 centroid of the leaves

    @property
    def num_nodes(self) -> jnp.ndarray:
        return self.node_mask.sum(-1)

    @property
    def num_levels(self) -> int:
        return self.tree_level.shape[-1] // self.node_mask.shape[-1]


@dataclasses.dataclass(frozen=True)
class MemoryMeta:
    """Host-side metadata of one scene's memory (strings and ragged lists)."""

    scene: str
    num_nodes: int
    captions: tuple[str, ...]  # (n,) spatial fingerprints d_i
    caption_labels: tuple[tuple[str, ...], ...]  # (n,) surface labels the captioner used
    observed_ids: tuple[tuple[str, ...], ...]  # (n,) object ids seen from each node, nearest first
    tree_labels: tuple[str, ...]  # (M,) label per forest slot ("" padding; leaves: node label)
    tree_summaries: tuple[str, ...]  # (M,) summary per forest slot
    object_ids: tuple[str, ...]  # scene.objects order (obs_object indexes it)
    sensor_names: tuple[str, ...]  # (S,) channel names of `sensors`
    num_components: int
    embedder: str
    config: dict  # the memory config that built it
    caption_objects: tuple[tuple[int, ...], ...] = ()  # (n,) scene object index of each described instance
    caption_phrases: tuple[tuple[str, ...], ...] = ()  # (n,) the caption's phrase for each of them
    fingerprint: str = ""  # scene_fingerprint of the scene and `config` it was built from ("" in older banks)
    # (O,) the first and the last exploration record in which the camera saw each scene object, (-1, -1) never: the
    # memory's sighting log, which time-indexed queries and recency read (() in older banks: node records instead)
    object_seen: tuple[tuple[int, int], ...] = ()

    def to_json(self) -> dict:
        return dataclasses.asdict(self)

    @staticmethod
    def from_json(d: dict) -> MemoryMeta:
        tup = lambda x: tuple(tuple(v) if isinstance(v, list) else v for v in x)  # noqa: E731
        return MemoryMeta(
            scene=d["scene"], num_nodes=int(d["num_nodes"]), captions=tuple(d["captions"]),
            caption_labels=tup(d["caption_labels"]), observed_ids=tup(d["observed_ids"]),
            tree_labels=tuple(d["tree_labels"]), tree_summaries=tuple(d["tree_summaries"]),
            object_ids=tuple(d["object_ids"]), sensor_names=tuple(d["sensor_names"]),
            num_components=int(d["num_components"]), embedder=d["embedder"], config=dict(d["config"]),
            caption_objects=tuple(tuple(int(x) for x in v) for v in d.get("caption_objects", ())),
            caption_phrases=tup(d.get("caption_phrases", ())), fingerprint=str(d.get("fingerprint", "")),
            object_seen=tuple((int(a), int(b)) for a, b in d.get("object_seen", ())),
        )


def scene_fingerprint(scene, memory_config: dict) -> str:
    """SHA-256 over the scene's canonical JSON (name, rooms, walls, objects, start pose) and the memory config
    that built its memory: a bank records it per scene, and its consumers check it against their scenes."""
    from ragnav_jax.world.scene import scene_to_dict

    text = json.dumps({"scene": scene_to_dict(scene), "memory": memory_config}, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()


@dataclasses.dataclass(frozen=True)
class MemoryBank:
    """The memories of a scene set: one DualBasisMemory with a leading scene axis (B, ...) + metadata."""

    memory: DualBasisMemory  # every field has a leading (B,) axis
    metas: tuple[MemoryMeta, ...]  # (B,)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(m.scene for m in self.metas)

    def index(self, name: str) -> int:
        try:
            return self.names.index(name)
        except ValueError:
            from ragnav_jax.errors import UserError

            raise UserError(f"no memory for scene '{name}' (have: {', '.join(self.names)})") from None

    def scene(self, name: str) -> tuple[DualBasisMemory, MemoryMeta]:
        """One scene's memory (no batch axis) and metadata."""
        b = self.index(name)
        return take(self.memory, b), self.metas[b]


def stack_memories(memories: list[DualBasisMemory]) -> DualBasisMemory:
    return stack(memories)


def memory_to_numpy(mem: DualBasisMemory) -> dict[str, np.ndarray]:
    return {f.name: np.asarray(getattr(mem, f.name)) for f in dataclasses.fields(mem)}
