"""The scene model (`ragnav-scene/1`): load, validate, save.

A scene is a planar indoor environment: axis-aligned rooms, wall segments (doorways are gaps between
walls), open-vocabulary objects with attributes and sensor readings, and the robot's start pose.
Validation has two layers: the JSON schema (shipped in `world/schemas/`), then geometric checks the
schema cannot express (finite numbers, overlapping rooms, objects outside every room, duplicate ids,
a start pose inside a wall). Every problem raises SceneError naming the file and the JSON path.
"""

from __future__ import annotations

import dataclasses
import json
import math
from functools import cache
from importlib import resources
from pathlib import Path
from typing import Any

import jsonschema

from ragnav_jax.errors import SceneError
from ragnav_jax.filenames import name_problem

FORMAT = "ragnav-scene/1"
DEFAULT_OBJECT_SIZE = (0.5, 0.5, 0.5)
DEFAULT_WALL_THICKNESS = 0.1
DEFAULT_WALL_HEIGHT = 2.5
_EPS = 1e-6


@dataclasses.dataclass(frozen=True)
class Room:
    id: str
    type: str
    min: tuple[float, float]
    max: tuple[float, float]

    @property
    def center(self) -> tuple[float, float]:
        return ((self.min[0] + self.max[0]) / 2, (self.min[1] + self.max[1]) / 2)

    @property
    def area(self) -> float:
        return (self.max[0] - self.min[0]) * (self.max[1] - self.min[1])

    def contains(self, x: float, y: float, tol: float = 1e-6) -> bool:
        return self.min[0] - tol <= x <= self.max[0] + tol and self.min[1] - tol <= y <= self.max[1] + tol


@dataclasses.dataclass(frozen=True)
class Wall:
    a: tuple[float, float]
    b: tuple[float, float]
    thickness: float = DEFAULT_WALL_THICKNESS
    height: float = DEFAULT_WALL_HEIGHT

    @property
    def length(self) -> float:
        return math.dist(self.a, self.b)


@dataclasses.dataclass(frozen=True)
class SceneObject:
    id: str
    category: str
    position: tuple[float, float, float]
    size: tuple[float, float, float] = DEFAULT_OBJECT_SIZE
    room: str = ""  # id of the holding room (derived from position when absent in the file)
    attributes: tuple[tuple[str, str], ...] = ()  # sorted-as-written (key, value) pairs
    description: str = ""
    sensors: tuple[tuple[str, float], ...] = ()

    @property
    def attrs(self) -> dict[str, str]:
        return dict(self.attributes)

    @property
    def readings(self) -> dict[str, float]:
        return dict(self.sensors)


@dataclasses.dataclass(frozen=True)
class Start:
    position: tuple[float, float]
    yaw: float = 0.0


@dataclasses.dataclass(frozen=True)
class Scene:
    name: str
    rooms: tuple[Room, ...]
    walls: tuple[Wall, ...]
    objects: tuple[SceneObject, ...]
    start: Start
    # ids of objects listed only so that a memory built before a change keeps its indices: they left the
    # world (`world.changes.world_after`), so nothing collides with, sees or declares them; never in a file
    absent: frozenset[str] = frozenset()

    def room_by_id(self, room_id: str) -> Room:
        return next(r for r in self.rooms if r.id == room_id)

    def object_by_id(self, object_id: str) -> SceneObject:
        return next(o for o in self.objects if o.id == object_id)

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """(xmin, ymin, xmax, ymax) over rooms and walls."""
        xs = [r.min[0] for r in self.rooms] + [r.max[0] for r in self.rooms]
        ys = [r.min[1] for r in self.rooms] + [r.max[1] for r in self.rooms]
        for w in self.walls:
            xs += [w.a[0], w.b[0]]
            ys += [w.a[1], w.b[1]]
        return (min(xs), min(ys), max(xs), max(ys))


# ----------------------------------------------------------------------------------------------------
# Schema validation


@cache
def load_schema(name: str = "scene") -> dict:
    """The JSON schema shipped with the package: 'scene' or 'episode'."""
    text = resources.files("ragnav_jax.world").joinpath("schemas").joinpath(f"{name}.schema.json").read_text()
    return json.loads(text)


def json_path(parts) -> str:
    """JSONPath-like string for a sequence of keys/indices: ('objects', 3, 'position') -> $.objects[3].position."""
    out = "$"
    for p in parts:
        out += f"[{p}]" if isinstance(p, int) else f".{p}"
    return out


def _schema_check(data: Any, source: str, schema_name: str = "scene") -> None:
    validator = jsonschema.Draft202012Validator(load_schema(schema_name))
    errors = sorted(validator.iter_errors(data), key=lambda e: (len(e.absolute_path), list(map(str, e.absolute_path))))
    if errors:
        err = jsonschema.exceptions.best_match(errors)
        msg = err.message
        if len(msg) > 300:
            msg = msg[:300] + "..."
        raise SceneError(source, json_path(err.absolute_path), msg)


def _finite_check(data: Any, source: str, parts=()) -> None:
    """Python's json accepts NaN and Infinity; scenes must not."""
    if isinstance(data, float) and not math.isfinite(data):
        raise SceneError(source, json_path(parts), f"number must be finite, got {data}")
    if isinstance(data, dict):
        for k, v in data.items():
            _finite_check(v, source, (*parts, k))
    elif isinstance(data, list):
        for i, v in enumerate(data):
            _finite_check(v, source, (*parts, i))


# ----------------------------------------------------------------------------------------------------
# Geometry checks


def point_segment_distance(p, a, b) -> float:
    ax, ay = a
    bx, by = b
    px, py = p
    dx, dy = bx - ax, by - ay
    denom = dx * dx + dy * dy
    t = 0.0 if denom == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / denom))
    return math.hypot(px - (ax + t * dx), py - (ay + t * dy))


def _overlap(r1: Room, r2: Room) -> float:
    w = min(r1.max[0], r2.max[0]) - max(r1.min[0], r2.min[0])
    h = min(r1.max[1], r2.max[1]) - max(r1.min[1], r2.min[1])
    return w * h if (w > _EPS and h > _EPS) else 0.0


def _semantic_check(scene: Scene, source: str) -> None:
    seen: dict[str, int] = {}
    for i, r in enumerate(scene.rooms):
        if r.id in seen:
            raise SceneError(source, f"$.rooms[{i}].id", f"duplicate room id '{r.id}' (also $.rooms[{seen[r.id]}])")
        seen[r.id] = i
        if not (r.max[0] > r.min[0] and r.max[1] > r.min[1]):
            raise SceneError(source, f"$.rooms[{i}]", f"room '{r.id}' needs min < max on both axes")
    if not scene.rooms:
        raise SceneError(source, "$.rooms", "a scene needs at least one room")
    for i, r1 in enumerate(scene.rooms):
        for j in range(i + 1, len(scene.rooms)):
            if _overlap(r1, scene.rooms[j]) > 0:
                raise SceneError(
                    source, f"$.rooms[{j}]", f"room '{scene.rooms[j].id}' overlaps room '{r1.id}' ($.rooms[{i}])"
                )
    for i, w in enumerate(scene.walls):
        if w.length <= _EPS:
            raise SceneError(source, f"$.walls[{i}]", "wall has zero length (a == b)")
    obj_seen: dict[str, int] = {}
    for i, o in enumerate(scene.objects):
        if o.id in obj_seen:
            raise SceneError(
                source, f"$.objects[{i}].id", f"duplicate object id '{o.id}' (also $.objects[{obj_seen[o.id]}])"
            )
        obj_seen[o.id] = i
        if any(s <= 0 for s in o.size):
            raise SceneError(source, f"$.objects[{i}].size", "object sizes must be positive")
        if not any(r.contains(o.position[0], o.position[1]) for r in scene.rooms):
            raise SceneError(
                source,
                f"$.objects[{i}].position",
                f"object '{o.id}' at ({o.position[0]}, {o.position[1]}) is outside every room",
            )
        if o.room and o.room not in seen:
            raise SceneError(source, f"$.objects[{i}].room", f"unknown room id '{o.room}'")
    sx, sy = scene.start.position
    if not any(r.contains(sx, sy) for r in scene.rooms):
        raise SceneError(source, "$.start.position", f"start ({sx}, {sy}) is outside every room")
    for i, w in enumerate(scene.walls):
        if point_segment_distance((sx, sy), w.a, w.b) <= w.thickness / 2 + _EPS:
            raise SceneError(source, "$.start.position", f"start ({sx}, {sy}) is inside wall $.walls[{i}]")


def room_of(rooms, x: float, y: float) -> str:
    """Id of the first room containing (x, y), or '' when none does."""
    for r in rooms:
        if r.contains(x, y):
            return r.id
    return ""


# ----------------------------------------------------------------------------------------------------
# Dict <-> Scene


def scene_from_dict(data: Any, source: str = "<scene>") -> Scene:
    """Validates plain data (as parsed from JSON) and builds a Scene; raises SceneError."""
    _finite_check(data, source)
    _schema_check(data, source)
    if problem := name_problem(data["name"]):  # RUN/scenes/<name>.json, streams, maps and plots are named after it
        raise SceneError(source, "$.name", f"scene name {problem}")
    rooms = tuple(Room(r["id"], r["type"], tuple(r["min"]), tuple(r["max"])) for r in data["rooms"])
    walls = tuple(
        Wall(
            tuple(w["a"]),
            tuple(w["b"]),
            float(w.get("thickness", DEFAULT_WALL_THICKNESS)),
            float(w.get("height", DEFAULT_WALL_HEIGHT)),
        )
        for w in data["walls"]
    )
    objects = [object_from_dict(o, source, i) for i, o in enumerate(data["objects"])]
    start = Start(tuple(float(v) for v in data["start"]["position"]), float(data["start"].get("yaw", 0.0)))
    scene = Scene(data["name"], rooms, walls, tuple(objects), start)
    _semantic_check(scene, source)
    # Derive missing rooms from positions (after the check, which guarantees one exists).
    objs = tuple(
        o if o.room else dataclasses.replace(o, room=room_of(rooms, o.position[0], o.position[1]))
        for o in scene.objects
    )
    return dataclasses.replace(scene, objects=objs)


def object_from_dict(o: dict, source: str = "<scene>", i: int = 0) -> SceneObject:
    """One object as the scene format writes it (already schema-checked; `i`: its place, for error paths)."""
    return SceneObject(
        id=o["id"],
        category=o["category"],
        position=tuple(float(v) for v in o["position"]),
        size=tuple(float(v) for v in o.get("size", DEFAULT_OBJECT_SIZE)),
        room=o.get("room", ""),
        attributes=tuple((str(k), str(v)) for k, v in o.get("attributes", {}).items()),
        description=o.get("description", ""),
        sensors=_sensors(o.get("sensors", {}), source, i),
    )


def _sensors(raw: dict, source: str, i: int) -> tuple[tuple[str, float], ...]:
    """An object's readings under their canonical keys and units (`language/readings.py`: "humidity" is
    humidity_pct, "temp_f" is temperature_c in Celsius); two keys for one reading are an error."""
    from ragnav_jax.language.readings import canonical_sensor

    out: dict[str, tuple[str, float]] = {}
    for k, v in raw.items():
        key, val = canonical_sensor(str(k), float(v))
        if key in out:
            raise SceneError(source, f"$.objects[{i}].sensors",
                             f"'{out[key][0]}' and '{k}' are the same reading ({key}); keep one")
        out[key] = (str(k), val)
    return tuple((key, val) for key, (_, val) in out.items())


def _num(v: float) -> float | int:
    v = round(float(v), 4)
    return int(v) if v == int(v) and abs(v) < 1e9 else v


def scene_to_dict(scene: Scene) -> dict:
    """Plain data in the `ragnav-scene/1` format (numbers rounded to 0.1 mm for stable files)."""
    return {
        "format": FORMAT,
        "name": scene.name,
        "rooms": [
            {"id": r.id, "type": r.type, "min": [_num(v) for v in r.min], "max": [_num(v) for v in r.max]}
            for r in scene.rooms
        ],
        "walls": [
            {
                "a": [_num(v) for v in w.a],
                "b": [_num(v) for v in w.b],
                "thickness": _num(w.thickness),
                "height": _num(w.height),
            }
            for w in scene.walls
        ],
        "objects": [object_to_dict(o) for o in scene.objects],
        "start": {"position": [_num(v) for v in scene.start.position], "yaw": _num(scene.start.yaw)},
    }


def object_to_dict(o: SceneObject) -> dict:
    """One object in the `ragnav-scene/1` format."""
    d: dict[str, Any] = {
        "id": o.id,
        "category": o.category,
        "position": [_num(v) for v in o.position],
        "size": [_num(v) for v in o.size],
    }
    if o.room:
        d["room"] = o.room
    if o.attributes:
        d["attributes"] = dict(o.attributes)
    if o.description:
        d["description"] = o.description
    if o.sensors:
        d["sensors"] = {k: _num(v) for k, v in o.sensors}
    return d


def scene_to_json(scene: Scene) -> str:
    return json.dumps(scene_to_dict(scene), indent=1) + "\n"


def parse_scene_text(text: str, source: str = "<scene>") -> Scene:
    try:
        data = json.loads(text)
    except json.JSONDecodeError as e:
        raise SceneError(source, f"line {e.lineno} column {e.colno}", f"not valid JSON ({e.msg})") from None
    return scene_from_dict(data, source)


def load_scene(path: str | Path) -> Scene:
    """Reads and validates one scene file; raises SceneError naming the file."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise SceneError(str(path), "$", "file is not UTF-8 text") from None
    except OSError as e:
        raise SceneError(str(path), "$", f"cannot read file ({e.strerror})") from None
    return parse_scene_text(text, str(path))


def save_scene(scene: Scene, path: str | Path) -> Path:
    """Writes the scene's JSON atomically (a full disk never leaves a truncated scene file)."""
    from ragnav_jax.io import write_text

    return write_text(path, scene_to_json(scene))


def scene_files(source: str | Path) -> list[Path]:
    """The scene files of a scene set: a folder (its *.json, sorted) or a single file."""
    source = Path(source)
    if source.is_dir():
        files = sorted(source.glob("*.json"))
        if not files:
            raise SceneError(str(source), "$", "folder holds no *.json scene files")
        return files
    if source.is_file():
        return [source]
    raise SceneError(str(source), "$", "no such file or folder")


def load_scene_set(source: str | Path) -> list[Scene]:
    """Loads every scene of a scene set; scene names must be unique."""
    scenes, names = [], {}
    for f in scene_files(source):
        s = load_scene(f)
        if s.name in names:
            raise SceneError(str(f), "$.name", f"duplicate scene name '{s.name}' (also in {names[s.name]})")
        names[s.name] = f
        scenes.append(s)
    return scenes


def example_scene_path() -> Path:
    """The embedded example scene (a copy of shared/examples/scenes/apartment.json)."""
    return Path(str(resources.files("ragnav_jax").joinpath("data").joinpath("apartment.json")))
