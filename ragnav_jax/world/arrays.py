"""Scenes as padded array pytrees, so later stages can jit and vmap over many scenes at once.

Every scene in a batch is padded to the same static counts (rooms, walls, objects, sensor channels)
with boolean masks; strings (ids, categories, sensor names) live in a host-side `SceneIndex`.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from typing import NamedTuple

import jax.numpy as jnp
import numpy as np
from flax import struct

from ragnav_jax.world.scene import Scene


class PadSizes(NamedTuple):
    """Static maximum counts of one batch."""

    rooms: int
    walls: int
    objects: int
    sensors: int  # number of distinct sensor channels


@struct.dataclass
class SceneArrays:
    """One scene (or, with a leading batch axis B, many) as padded arrays."""

    room_min: jnp.ndarray  # (R, 2) float32
    room_max: jnp.ndarray  # (R, 2) float32
    room_mask: jnp.ndarray  # (R,) bool
    wall_a: jnp.ndarray  # (W, 2) float32
    wall_b: jnp.ndarray  # (W, 2) float32
    wall_thickness: jnp.ndarray  # (W,) float32
    wall_height: jnp.ndarray  # (W,) float32
    wall_mask: jnp.ndarray  # (W,) bool
    obj_pos: jnp.ndarray  # (O, 3) float32, box centre
    obj_size: jnp.ndarray  # (O, 3) float32, full extents
    obj_room: jnp.ndarray  # (O,) int32 index into rooms, -1 for padding
    obj_category: jnp.ndarray  # (O,) int32 index into SceneIndex.categories, -1 for padding
    obj_mask: jnp.ndarray  # (O,) bool
    obj_sensors: jnp.ndarray  # (O, S) float32 readings, 0 where absent
    obj_sensor_mask: jnp.ndarray  # (O, S) bool, reading present
    start: jnp.ndarray  # (3,) float32: x, y, yaw


@dataclasses.dataclass(frozen=True)
class SceneIndex:
    """Host-side names that go with a batch of SceneArrays."""

    names: tuple[str, ...]  # (B,) scene names
    room_ids: tuple[tuple[str, ...], ...]  # per scene, unpadded
    room_types: tuple[tuple[str, ...], ...]
    object_ids: tuple[tuple[str, ...], ...]
    categories: tuple[str, ...]  # vocabulary of object categories over the batch, sorted
    sensor_names: tuple[str, ...]  # sensor channels over the batch, sorted
    sizes: PadSizes


def pad_sizes(scenes: Sequence[Scene]) -> PadSizes:
    """The smallest PadSizes that fits every scene (at least 1 of each, so shapes are never empty)."""
    sensors = {k for s in scenes for o in s.objects for k, _ in o.sensors}
    return PadSizes(
        rooms=max([len(s.rooms) for s in scenes] + [1]),
        walls=max([len(s.walls) for s in scenes] + [1]),
        objects=max([len(s.objects) for s in scenes] + [1]),
        sensors=max(len(sensors), 1),
    )


def scene_to_numpy(scene: Scene, sizes: PadSizes, categories: Sequence[str], sensor_names: Sequence[str]) -> dict:
    """One scene as a dict of padded NumPy arrays (the fields of SceneArrays)."""
    R, W, O, S = sizes
    if len(scene.rooms) > R or len(scene.walls) > W or len(scene.objects) > O:
        raise ValueError(
            f"scene '{scene.name}' ({len(scene.rooms)} rooms, {len(scene.walls)} walls, {len(scene.objects)} objects) "
            f"does not fit pad sizes {sizes}"
        )
    cat_idx = {c: i for i, c in enumerate(categories)}
    sen_idx = {c: i for i, c in enumerate(sensor_names)}
    room_idx = {r.id: i for i, r in enumerate(scene.rooms)}
    f32 = np.float32
    out = dict(
        room_min=np.zeros((R, 2), f32),
        room_max=np.zeros((R, 2), f32),
        room_mask=np.zeros((R,), bool),
        wall_a=np.zeros((W, 2), f32),
        wall_b=np.zeros((W, 2), f32),
        wall_thickness=np.zeros((W,), f32),
        wall_height=np.zeros((W,), f32),
        wall_mask=np.zeros((W,), bool),
        obj_pos=np.zeros((O, 3), f32),
        obj_size=np.zeros((O, 3), f32),
        obj_room=np.full((O,), -1, np.int32),
        obj_category=np.full((O,), -1, np.int32),
        obj_mask=np.zeros((O,), bool),
        obj_sensors=np.zeros((O, S), f32),
        obj_sensor_mask=np.zeros((O, S), bool),
        start=np.array([*scene.start.position, scene.start.yaw], f32),
    )
    for i, r in enumerate(scene.rooms):
        out["room_min"][i], out["room_max"][i], out["room_mask"][i] = r.min, r.max, True
    for i, w in enumerate(scene.walls):
        out["wall_a"][i], out["wall_b"][i] = w.a, w.b
        out["wall_thickness"][i], out["wall_height"][i], out["wall_mask"][i] = w.thickness, w.height, True
    for i, o in enumerate(scene.objects):
        out["obj_pos"][i], out["obj_size"][i], out["obj_mask"][i] = o.position, o.size, True
        out["obj_room"][i] = room_idx.get(o.room, -1)
        out["obj_category"][i] = cat_idx[o.category]
        for k, v in o.sensors:
            out["obj_sensors"][i, sen_idx[k]] = v
            out["obj_sensor_mask"][i, sen_idx[k]] = True
    return out


def stack_scenes(scenes: Sequence[Scene], sizes: PadSizes | None = None) -> tuple[SceneArrays, SceneIndex]:
    """Pads and stacks scenes into one SceneArrays with a leading batch axis (B, ...)."""
    if not scenes:
        raise ValueError("stack_scenes needs at least one scene")
    sizes = sizes or pad_sizes(scenes)
    categories = tuple(sorted({o.category for s in scenes for o in s.objects}))
    sensor_names = tuple(sorted({k for s in scenes for o in s.objects for k, _ in o.sensors}))
    per = [scene_to_numpy(s, sizes, categories, sensor_names) for s in scenes]
    arrays = SceneArrays(**{k: jnp.asarray(np.stack([p[k] for p in per])) for k in per[0]})
    index = SceneIndex(
        names=tuple(s.name for s in scenes),
        room_ids=tuple(tuple(r.id for r in s.rooms) for s in scenes),
        room_types=tuple(tuple(r.type for r in s.rooms) for s in scenes),
        object_ids=tuple(tuple(o.id for o in s.objects) for s in scenes),
        categories=categories,
        sensor_names=sensor_names,
        sizes=sizes,
    )
    return arrays, index


def scene_arrays(scene: Scene, sizes: PadSizes | None = None) -> tuple[SceneArrays, SceneIndex]:
    """One scene without a batch axis."""
    from ragnav_jax.pytrees import take

    batched, index = stack_scenes([scene], sizes)
    return take(batched, 0), index
