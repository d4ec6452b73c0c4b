"""Tasks in worlds that changed after exploration (issue 22): the memory is the explored scenes', the world is
the scenes after their change lists.

    worlds = load_worlds(scenes, "RUN/changes")                 # scene name -> the world after its changes
    world_scenes = [worlds.get(s.name, s) for s in scenes]
    rows, summary = evaluate_navigation(bank, world_scenes, episodes, ..., memory_scenes=scenes)
    # rows hold "changed_goals" ("move", "add" or "" per goal) and "changed"; the summary a static / changed split

A world keeps the memory's object indices (`world.changes.world_after`): the explored scene's objects in their
order, moved ones where they stand now, removed ones `absent`, added ones last. Retrieval, grounding and what
the memory knows read the explored scenes; driving, seeing, the check's perception and the Oracle read the
world. The ETPNav-style baseline, which explores for itself, explores the world as it is now (`explore_worlds`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from ragnav_jax.errors import UserError
from ragnav_jax.world.changes import changes_path, load_changes, world_after
from ragnav_jax.world.scene import Scene


def load_worlds(scenes: Sequence[Scene], folder: str | Path, needed: Sequence[str] = ()) -> dict[str, Scene]:
    """Scene name -> the world after its change list (`world_after`), from the lists in `folder`
    (`<scene>.changes.json`, as `ragnav changes` writes them). Every scene named in `needed` must have a list
    (UserError naming the file otherwise); a list that does not fit its scene raises SceneError naming the
    change."""
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


def explore_worlds(worlds: Sequence[Scene], cfg, progress: bool = False) -> dict:
    """Scene name -> the robot's own frontier exploration of each world as it is now (`sim.explore`, the
    configured budget and seed), its object columns in the world's order (what left it: never seen). The
    ETPNav-style baseline explores for itself instead of remembering: in a changed world it explores that world,
    closed doors and all, rather than replaying a route through the house as it was."""
    from ragnav_jax.sim.explore import explore_scenes

    present = [dataclasses.replace(w, objects=tuple(o for o in w.objects if o.id not in w.absent), absent=frozenset())
               for w in worlds]
    out = {}
    for w, r in zip(worlds, explore_scenes(present, cfg, progress=progress)):
        st = r.stream
        col = {i: k for k, i in enumerate(st.object_ids)}
        take = np.array([col.get(o.id, -1) for o in w.objects])
        out[w.name] = dataclasses.replace(st, visible=_columns(st.visible, take, False),
                                          distance=_columns(st.distance, take, np.inf),
                                          bearing=_columns(st.bearing, take, 0.0), object_ids=tuple(o.id for o in w.objects))
    return out


def _columns(a: np.ndarray, take: np.ndarray, fill) -> np.ndarray:
    """(T, len(take)) columns of a (T, K) at take (K index, -1: fill)."""
    out = np.full((a.shape[0], len(take)), fill, a.dtype)
    out[:, take >= 0] = a[:, take[take >= 0]]
    return out
