"""Scenes that change after exploration: change lists in the open `ragnav-changes/1` format (issue 22).

A change list says what happened in one scene between the robot's exploration and its task, in order:

    {"format": "ragnav-changes/1", "scene": "seen_000", "seed": 7, "changes": [
      {"kind": "move", "object": "lamp_2", "from": [1.2, 3.4, 0.6], "to": [5.0, 1.1, 0.6], "room": "study_1"},
      {"kind": "remove", "object": "kettle_1"},
      {"kind": "add", "object": {"id": "fern_3", "category": "fern", "position": [2.0, 2.0, 0.4], ...}},
      {"kind": "close_door", "rooms": ["hall_1", "study_1"], "wall": {"a": [4.0, 1.0], "b": [4.0, 2.0]}}]}

The schema is `world/schemas/changes.schema.json` (an added object and a closing wall are written as in the
scene format). `apply_changes` gives the scene after them, checked like any scene file; `generate_changes` draws
a list for a generated house (objects moved within or across rooms, removed or added, doors closed) that keeps
every room and object reachable. Lists live beside the scenes: RUN/changes/<scene>.changes.json.

    cl = generate_changes(scene, cfg.changes, seed); after = apply_changes(scene, cl)
    save_changes(cl, path); cl = load_changes(path)
"""

from __future__ import annotations

import dataclasses
import json
import math
from collections import Counter
from functools import cache
from pathlib import Path
from typing import Any

import jsonschema
import numpy as np

from ragnav_jax.config import ChangesConfig
from ragnav_jax.errors import SceneError
from ragnav_jax.world import geometry
from ragnav_jax.world.scene import (
    Scene,
    SceneObject,
    Wall,
    json_path,
    load_schema,
    object_from_dict,
    object_to_dict,
    room_of,
    scene_from_dict,
    scene_to_dict,
)

FORMAT = "ragnav-changes/1"
KINDS = ("move", "remove", "add", "close_door")


@dataclasses.dataclass(frozen=True)
class Change:
    """One change; the fields its kind uses are set, the others keep their defaults."""

    kind: str  # one of KINDS
    object: str = ""  # move, remove, add: the object's id
    to: tuple[float, float, float] | None = None  # move: its box centre now
    origin: tuple[float, float, float] | None = None  # move: where it stood ("from" in the file)
    room: str = ""  # move: its room now ("" derives it from `to`)
    added: SceneObject | None = None  # add: the new object
    wall: Wall | None = None  # close_door: the wall across the doorway
    rooms: tuple[str, ...] = ()  # close_door: the two rooms the doorway joined


@dataclasses.dataclass(frozen=True)
class ChangeList:
    scene: str  # the name of the scene it applies to
    changes: tuple[Change, ...]
    seed: int | None = None  # the seed generate_changes drew it with (None: written by hand)

    def counts(self) -> dict[str, int]:
        """Changes per kind, every kind listed."""
        c = Counter(ch.kind for ch in self.changes)
        return {k: c[k] for k in KINDS}


# ----------------------------------------------------------------------------------------------------
# The file format


@cache
def _validator() -> jsonschema.Draft202012Validator:
    from referencing import Registry, Resource

    scene = load_schema("scene")
    registry = Registry().with_resource(scene["$id"], Resource.from_contents(scene))
    return jsonschema.Draft202012Validator(load_schema("changes"), registry=registry)


def _schema_check(data: Any, source: str) -> None:
    errors = list(_validator().iter_errors(data))
    if errors:
        err = jsonschema.exceptions.best_match(errors)
        raise SceneError(source, json_path(err.absolute_path), err.message[:300])


def _xyz(v) -> tuple[float, float, float]:
    return tuple(float(x) for x in v)


def changes_from_dict(data: Any, source: str = "<changes>") -> ChangeList:
    """Validates plain data (as parsed from JSON) against the schema; raises SceneError naming the field. Whether
    the changes fit their scene is checked by `apply_changes`."""
    _schema_check(data, source)
    out = []
    for i, c in enumerate(data["changes"]):
        kind = c["kind"]
        if kind == "move":
            out.append(Change(kind, c["object"], to=_xyz(c["to"]), origin=_xyz(c["from"]) if "from" in c else None,
                              room=c.get("room", "")))
        elif kind == "remove":
            out.append(Change(kind, c["object"]))
        elif kind == "add":
            obj = object_from_dict(c["object"], f"{source}: $.changes[{i}].object")
            out.append(Change(kind, obj.id, added=obj))
        else:
            w = c["wall"]
            wall = Wall(tuple(map(float, w["a"])), tuple(map(float, w["b"])), float(w.get("thickness", 0.1)),
                        float(w.get("height", 2.5)))
            out.append(Change(kind, wall=wall, rooms=tuple(c.get("rooms", ()))))
    return ChangeList(data["scene"], tuple(out), data.get("seed"))


def changes_to_dict(cl: ChangeList) -> dict:
    """Plain data in the `ragnav-changes/1` format."""
    out = []
    for c in cl.changes:
        if c.kind == "move":
            d = {"kind": "move", "object": c.object}
            if c.origin is not None:
                d["from"] = [_num(v) for v in c.origin]
            d["to"] = [_num(v) for v in c.to]
            if c.room:
                d["room"] = c.room
        elif c.kind == "remove":
            d = {"kind": "remove", "object": c.object}
        elif c.kind == "add":
            d = {"kind": "add", "object": object_to_dict(c.added)}
        else:
            w = c.wall
            d = {"kind": "close_door", "rooms": list(c.rooms),
                 "wall": {"a": [_num(v) for v in w.a], "b": [_num(v) for v in w.b], "thickness": _num(w.thickness),
                          "height": _num(w.height)}}
            if not c.rooms:
                del d["rooms"]
        out.append(d)
    head = {"format": FORMAT, "scene": cl.scene}
    return {**head, **({"seed": cl.seed} if cl.seed is not None else {}), "changes": out}


def _num(v: float) -> float | int:
    v = round(float(v), 4)
    return int(v) if v == int(v) else v


def load_changes(path: str | Path) -> ChangeList:
    """Reads and validates one change list file; raises SceneError naming the file and field."""
    path = Path(path)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except json.JSONDecodeError as e:
        raise SceneError(str(path), f"line {e.lineno} column {e.colno}", f"not valid JSON ({e.msg})") from None
    except (OSError, UnicodeDecodeError) as e:
        raise SceneError(str(path), "$", f"cannot read file ({getattr(e, 'strerror', None) or e})") from None
    return changes_from_dict(data, str(path))


def save_changes(cl: ChangeList, path: str | Path) -> Path:
    from ragnav_jax.io import write_text

    return write_text(path, json.dumps(changes_to_dict(cl), indent=1) + "\n")


def changes_path(run: str | Path, scene_name: str) -> Path:
    """Where a run keeps a scene's change list: RUN/changes/<scene>.changes.json (beside RUN/scenes)."""
    return Path(run) / "changes" / f"{scene_name}.changes.json"


# ----------------------------------------------------------------------------------------------------
# Applying a list


def apply_changes(scene: Scene, cl: ChangeList, source: str = "<changes>") -> Scene:
    """The scene after every change of `cl`, in order; raises SceneError naming the change that does not fit
    (an unknown or already removed object, a duplicate id, a wall of zero length) or the scene the changes leave
    invalid (an object outside every room, the start inside a wall)."""
    if cl.scene != scene.name:
        raise SceneError(source, "$.scene", f"the list is for scene '{cl.scene}', not '{scene.name}'")
    objects = {o.id: o for o in scene.objects}
    walls = list(scene.walls)
    for i, c in enumerate(cl.changes):
        where = f"$.changes[{i}]"
        if c.kind in ("move", "remove") and c.object not in objects:
            raise SceneError(source, f"{where}.object", f"no object '{c.object}' in scene '{scene.name}' at this point")
        if c.kind == "move":
            o = objects[c.object]
            if c.origin is not None and math.dist(c.origin, o.position) > 1e-3:
                raise SceneError(source, f"{where}.from",
                                 f"object '{c.object}' stands at {list(o.position)}, not there")
            room = c.room or room_of(scene.rooms, c.to[0], c.to[1])
            if c.room and c.room not in {r.id for r in scene.rooms}:
                raise SceneError(source, f"{where}.room", f"unknown room id '{c.room}'")
            if not room:
                raise SceneError(source, f"{where}.to", f"({c.to[0]}, {c.to[1]}) is outside every room")
            objects[c.object] = dataclasses.replace(o, position=c.to, room=room)
        elif c.kind == "remove":
            del objects[c.object]
        elif c.kind == "add":
            if c.added.id in objects:
                raise SceneError(source, f"{where}.object.id", f"object id '{c.added.id}' is already in the scene")
            room = c.added.room or room_of(scene.rooms, c.added.position[0], c.added.position[1])
            objects[c.added.id] = dataclasses.replace(c.added, room=room)
        else:
            if c.wall.length <= 1e-6:
                raise SceneError(source, f"{where}.wall", "wall has zero length (a == b)")
            walls.append(c.wall)
    after = dataclasses.replace(scene, objects=tuple(objects.values()), walls=tuple(walls))
    # the scene file's own checks, on the scene the changes leave
    return scene_from_dict(scene_to_dict(after), source=f"{source} (scene '{scene.name}' after the changes)")


def world_after(scene: Scene, cl: ChangeList, source: str = "<changes>") -> Scene:
    """The world a task runs in after `cl`, indexed like the memory built before it: the explored scene's objects
    in their order (moved ones where they stand now, removed ones kept in the list but `absent`), then the added
    ones. A memory's object indices (`obs_object`) are therefore valid in it; checked like `apply_changes`."""
    after = apply_changes(scene, cl, source)
    now = {o.id: o for o in after.objects}
    before = {o.id for o in scene.objects}
    objects = [now.get(o.id, o) for o in scene.objects] + [o for o in after.objects if o.id not in before]
    return dataclasses.replace(after, objects=tuple(objects), absent=frozenset(before - set(now)))



# ----------------------------------------------------------------------------------------------------
# Drawing a list for a generated house


def generate_changes(scene: Scene, cfg: ChangesConfig, seed: int, split: str = "seen") -> ChangeList:
    """A seeded change list for one house: round(cfg.fraction * objects) object changes (moves, removals and
    additions in the proportions of cfg.weights; a move goes to another room with probability
    cfg.other_room) and cfg.doors doors closed. Only objects on the floor that nothing stands on move or go;
    every change keeps every room and object reachable from the start for the generator's robot, or is drawn
    again (a change that cannot be placed is skipped). Deterministic in (scene, cfg, seed, split)."""
    from ragnav_jax.world.blockers import doorways, find_blocked
    from ragnav_jax.world.generator import ROBOT_RADIUS

    rng = np.random.default_rng(np.random.SeedSequence([int(seed), *map(ord, scene.name)]))
    cur = scene
    changes: list[Change] = []
    kinds = [k for k, w in cfg.weights if w > 0]
    p = np.array([w for _, w in cfg.weights if w > 0], float)
    n = int(round(cfg.fraction * len(scene.objects)))
    touched: set[str] = set()
    for _ in range(n):
        for _ in range(10):  # a change that fails to place or blocks the way is drawn again
            kind = kinds[int(rng.choice(len(kinds), p=p / p.sum()))]
            ch = _draw(rng, cur, kind, cfg, split, touched)
            if ch is None:
                continue
            nxt = apply_changes(cur, ChangeList(cur.name, (ch,)))
            if find_blocked(nxt, ROBOT_RADIUS):
                continue
            cur = nxt
            changes.append(ch)
            touched.add(ch.object)
            break
    doors = doorways(cur)
    order = rng.permutation(len(doors))
    closed = 0
    for k in order:
        if closed >= cfg.doors:
            break
        d = doors[int(k)]
        ch = Change("close_door", wall=Wall(d.a, d.b, max(d.wall_thickness, 0.1)), rooms=d.rooms)
        nxt = apply_changes(cur, ChangeList(cur.name, (ch,)))
        if not find_blocked(nxt, ROBOT_RADIUS):
            cur, closed = nxt, closed + 1
            changes.append(ch)
    return ChangeList(scene.name, tuple(changes), int(seed))


def _movable(scene: Scene, touched: set[str]) -> list[SceneObject]:
    """Objects standing on the floor with nothing on them, not changed yet."""
    floor = [o for o in scene.objects if o.position[2] - o.size[2] / 2 <= 0.05 and o.id not in touched]

    def carries(o):
        top = o.position[2] + o.size[2] / 2
        return any(abs(q.position[2] - q.size[2] / 2 - top) < 0.02 and all(
            abs(q.position[k] - o.position[k]) < o.size[k] / 2 for k in (0, 1)) for q in scene.objects if q is not o)

    return [o for o in floor if not carries(o)]


def _furnisher(rng, scene: Scene, split: str, without: str = ""):
    """The generator's furnisher over the scene's objects (less `without`), its doorways as doors."""
    from ragnav_jax.world.blockers import doorways
    from ragnav_jax.world.generator import ROBOT_RADIUS, Door, _Furnisher
    from ragnav_jax.world.vocabulary import catalog_for, plants_for

    doors = [Door((0, 0), d.center, abs(d.a[0] - d.b[0]) < 1e-6) for d in doorways(scene)]
    f = _Furnisher(rng, dataclasses.replace(scene, objects=()), doors, catalog_for(split), plants_for(split))
    f.objects = [o for o in scene.objects if o.id != without]
    f.counts = Counter({o.category: 0 for o in scene.objects})
    for o in scene.objects:  # new ids continue each category's numbering
        tail = o.id.rsplit("_", 1)[-1]
        if tail.isdigit():
            f.counts[o.category] = max(f.counts[o.category], int(tail))
    standing = [o for o in f.objects if o.size[2] > geometry.FLAT_HEIGHT]
    f.free = geometry.free_mask(scene, f.grid, ROBOT_RADIUS, objects=standing)
    return f


def _draw(rng, scene: Scene, kind: str, cfg: ChangesConfig, split: str, touched: set[str]) -> Change | None:
    from ragnav_jax.world.generator import _groups_for

    if kind == "add":
        room = scene.rooms[int(rng.integers(len(scene.rooms)))]
        f = _furnisher(rng, scene, split)
        cats = [g.anchor for g in _groups_for(room.type, split) if g.anchor in f.catalog]
        if not cats:
            return None
        obj = f.place(str(rng.choice(sorted(set(cats)))), room)
        return None if obj is None else Change("add", obj.id, added=obj)
    movable = _movable(scene, touched)
    if not movable:
        return None
    o = movable[int(rng.integers(len(movable)))]
    if kind == "remove":
        return Change("remove", o.id)
    others = [r for r in scene.rooms if r.id != o.room]
    room = (others[int(rng.integers(len(others)))] if others and rng.uniform() < cfg.other_room
            else next(r for r in scene.rooms if r.id == o.room))
    f = _furnisher(rng, scene, split, without=o.id)
    w, d, h = o.size
    flat = o.size[2] <= geometry.FLAT_HEIGHT
    lo = (room.min[0] + w / 2 + 0.1, room.min[1] + d / 2 + 0.1)
    hi = (max(lo[0], room.max[0] - w / 2 - 0.1), max(lo[1], room.max[1] - d / 2 - 0.1))
    for _ in range(25):
        x, y = (round(float(rng.uniform(a, b)), 2) for a, b in zip(lo, hi))
        if math.hypot(x - o.position[0], y - o.position[1]) < 0.5 or not f._footprint_clear(x, y, w, d, flat, room):
            continue
        return Change("move", o.id, to=(x, y, o.position[2]), origin=o.position, room=room.id)
    return None
