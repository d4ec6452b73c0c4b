"""Tasks in worlds that changed after exploration (issue 22): the memory is the explored scenes', the world is
the scenes after their change lists.

    worlds = load_worlds(scenes, "RUN/changes")                 # scene name -> the world after its changes
    world_scenes = [worlds.get(s.name, s) for s in scenes]
    rows, summary = evaluate_navigation(bank, world_scenes, episodes, ..., memory_scenes=scenes)
    # rows hold "changed_goals" ("move", "add" or "" per goal) and "changed"; the summary a static / changed split

A world keeps the memory's object indices (`world.changes.world_after`): the explored scene's objects in their
order, moved ones where they stand now, removed ones `absent`, added ones last. Retrieval, grounding and what
the memory knows read the explored scenes; driving, seeing, the check's perception and the Oracle read the
world. The ETPNav-style baseline replays the exploration's route; in a changed world what it sees along it is
seen again in the world (`world_stream`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.errors import UserError
from ragnav_jax.world.changes import changes_path, load_changes, world_after
from ragnav_jax.world.scene import Scene

STREAM_CHUNK = 256  # exploration records seen again per jitted call


def load_worlds(scenes: Sequence[Scene], folder: str | Path, needed: Sequence[str] = ()) -> dict[str, Scene]:
    """Scene name -> the world after its change list (`world_after`), from the change lists in `folder` (`<scene>.changes.json`, as `ragnav changes` writes
    them). Every scene named in `needed` must have a list (UserError naming the file otherwise); a list that
    does not fit its scene raises SceneError naming the change."""
    folder = Path(folder)
    if not folder.is_dir():
        raise UserError(f"{folder}: no such folder of change lists (write one with `ragnav changes`)")
    by_name = {s.name: s for s in scenes}
    missing = [n for n in needed if not (folder / changes_path("", n).name).is_file()]
    if missing:
        raise UserError(f"{folder / changes_path('', missing[0]).name}: no change list for scene '{missing[0]}'"
                        + (f" (and {len(missing) - 1} more)" if len(missing) > 1 else ""))
    out = {}
    for name, s in by_name.items():
        f = folder / changes_path("", name).name
        if f.is_file():
            out[name] = world_after(s, load_changes(f), str(f))
    return out


def goal_changes(goals: Sequence[str], world: Scene, memory: Scene) -> list[str]:
    """Per goal object id: "add" (not in the scene the memory was built from), "move" (it stands elsewhere now)
    or "" (where the memory saw it)."""
    before = {o.id: o for o in memory.objects}
    now = {o.id: o for o in world.objects}
    return ["add" if g not in before else "move" if now[g].position != before[g].position else "" for g in goals]


def world_stream(stream, world: Scene, executor, sim_cfg):
    """The exploration stream as `world` shows it now: the same records (poses, lidar), with what the forward
    camera sees from each pose (`visible`, `distance`, `bearing`) cast again in the world's MJX model (objects
    moved, removed or added; doors closed) of `executor`. Columns follow the world's objects."""
    from ragnav_jax.sim.model import GEOMETRY_FIELDS, initial_data
    from ragnav_jax.sim.sensors import camera_visibility

    ex = executor
    s = ex.names.index(world.name)
    lay = ex.model.layout
    obj_geom = jnp.arange(lay.obj_geom0, lay.obj_geom0 + lay.objects, dtype=jnp.int32)
    m = ex.model.mx.tree_replace({k: getattr(ex.tables.geometry, k)[s] for k in GEOMETRY_FIELDS})
    pos, size, mask = ex.tables.obj_pos[s], ex.tables.obj_size[s], ex.tables.obj_mask[s]

    @jax.jit
    def see(poses):  # (C, 3) x, y, yaw -> what the camera sees of every object from each
        def one(p):
            v = camera_visibility(m, initial_data(m, p), pos, size, mask, obj_geom, sim_cfg, lay.robot_body)
            return v.visible, v.distance, v.bearing

        return jax.vmap(one)(poses)

    xyyaw = np.asarray(stream.pose)[:, [0, 1, 3]].astype(np.float32)
    out = []
    for c0 in range(0, len(xyyaw), STREAM_CHUNK):
        chunk = xyyaw[c0 : c0 + STREAM_CHUNK]
        pad = np.concatenate([chunk, np.repeat(chunk[-1:], STREAM_CHUNK - len(chunk), 0)])
        out.append([np.asarray(x)[: len(chunk)] for x in see(jnp.asarray(pad))])
    k = len(world.objects)
    vis, dist, bear = (np.concatenate([o[i] for o in out])[:, :k] for i in range(3))
    return dataclasses.replace(stream, visible=vis, distance=dist.astype(np.float32), bearing=bear.astype(np.float32),
                               object_ids=tuple(o.id for o in world.objects))
