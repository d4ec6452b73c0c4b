"""Seeded procedural house generator writing `ragnav-scene/1` scenes.

Layout: a rectangle is split binary-space-partition style into 4-9 rooms; rooms that share enough wall
get doors along a random spanning tree (every room reachable) plus extra loops; walls are the union
of room sides minus door gaps. Furnishing: per-room-type groups with co-occurrence (see
`vocabulary.py`), placed by rejection sampling that keeps doors clear and, checked on a 0.1 m raster
after every placement, every room and every object reachable from the start pose. Same-category
distractors are guaranteed (instances differ in attributes, room, neighbours or sensor values).
`world.split` picks the vocabulary: "seen" (the default; the original catalogue, unchanged) or "unseen"
(other room types, categories and attribute kinds, including on/off, open/closed and empty/full states).

The same (config, seed) gives byte-identical scene files: every random draw comes from a NumPy
generator seeded by (seed, scene index), and numbers are rounded before writing.
"""

from __future__ import annotations

import dataclasses
import math
from collections import Counter

import numpy as np
from scipy import ndimage

from ragnav_jax.config import WorldConfig
from ragnav_jax.world import geometry
from ragnav_jax.world.scene import Room, Scene, SceneObject, Start, Wall, scene_from_dict, scene_to_dict
from ragnav_jax.world.vocabulary import (
    CATALOG,
    PLANTS,
    Entry,
    Group,
    catalog_for,
    generic_groups_for,
    plants_for,
    room_groups_for,
)

WALL_THICKNESS = 0.1
WALL_HEIGHT = 2.5
ROBOT_RADIUS = 0.2  # reachability is checked for a robot of this radius
SUCCESS_RADIUS = 1.0  # every object must have reachable floor within this distance of its box
GRID_RES = 0.1
SPACE_TOLERANCE = 0.01  # metres: boxes may touch or overlap this little on an axis (positions are rounded to 0.01)

Rect = tuple[float, float, float, float]  # (x0, y0, x1, y1)


@dataclasses.dataclass(frozen=True)
class Door:
    rooms: tuple[int, int]
    center: tuple[float, float]
    vertical: bool  # the wall line is vertical (x = const)


def _r(v: float, q: float = 0.1) -> float:
    return round(round(v / q) * q, 4)


# ----------------------------------------------------------------------------------------------------
# Layout


def split_rooms(rng: np.random.Generator, n: int, side: tuple[float, float]) -> list[Rect] | None:
    """Binary space partition of a house rectangle into n rooms (None when it cannot be split)."""
    mean = (side[0] + side[1]) / 2
    area = n * mean * mean * rng.uniform(0.85, 1.15)
    aspect = rng.uniform(1.0, 1.7)
    w = _r(math.sqrt(area * aspect))
    h = _r(area / w)
    min_side = 0.8 * side[0]
    rects: list[Rect] = [(0.0, 0.0, w, h)]
    while len(rects) < n:
        order = sorted(range(len(rects)), key=lambda k: -(rects[k][2] - rects[k][0]) * (rects[k][3] - rects[k][1]))
        for k in order:
            x0, y0, x1, y1 = rects[k]
            rw, rh = x1 - x0, y1 - y0
            axes = [0, 1] if rw > rh * rng.uniform(0.8, 1.25) else [1, 0]
            done = False
            for axis in axes:
                length = rw if axis == 0 else rh
                lo, hi = max(min_side, 0.35 * length), min(length - min_side, 0.65 * length)
                if hi < lo:
                    continue
                cut = _r(rng.uniform(lo, hi))
                if cut < min_side - 1e-9 or length - cut < min_side - 1e-9:
                    continue
                if axis == 0:
                    new = [(x0, y0, _r(x0 + cut), y1), (_r(x0 + cut), y0, x1, y1)]
                else:
                    new = [(x0, y0, x1, _r(y0 + cut)), (x0, _r(y0 + cut), x1, y1)]
                rects[k : k + 1] = new
                done = True
                break
            if done:
                break
        else:
            return None
    return rects


def shared_walls(rects: list[Rect], min_len: float) -> list[tuple[int, int, bool, float, float, float]]:
    """Pairs of rooms sharing a wall stretch of at least min_len: (i, j, vertical, coord, lo, hi)."""
    out = []
    for i, a in enumerate(rects):
        for j in range(i + 1, len(rects)):
            b = rects[j]
            for vertical, ca, cb in ((True, (a[2], a[0]), (b[0], b[2])), (False, (a[3], a[1]), (b[1], b[3]))):
                for c1, c2 in ((ca[0], cb[0]), (ca[1], cb[1])):
                    if abs(c1 - c2) < 1e-6:
                        lo = max(a[1], b[1]) if vertical else max(a[0], b[0])
                        hi = min(a[3], b[3]) if vertical else min(a[2], b[2])
                        if hi - lo >= min_len:
                            out.append((i, j, vertical, c1, lo, hi))
    return out


def place_doors(rng, rects: list[Rect], door_width: float, extra_prob: float) -> list[Door] | None:
    """Doors on a random spanning tree of the room adjacency graph plus random extra loops."""
    margin = 0.25
    edges = shared_walls(rects, door_width + 2 * margin)
    perm = rng.permutation(len(edges))
    parent = list(range(len(rects)))

    def find(k):
        while parent[k] != k:
            parent[k] = parent[parent[k]]
            k = parent[k]
        return k

    chosen = []
    for e in perm:
        i, j = edges[e][:2]
        ri, rj = find(i), find(j)
        if ri != rj:
            parent[ri] = rj
            chosen.append(e)
        elif rng.uniform() < extra_prob and not any(edges[c][:2] == (i, j) for c in chosen):
            chosen.append(e)
    if len({find(k) for k in range(len(rects))}) != 1:
        return None
    doors = []
    for e in sorted(chosen):
        i, j, vertical, coord, lo, hi = edges[e]
        c = round(rng.uniform(lo + margin + door_width / 2, hi - margin - door_width / 2) / 0.05) * 0.05
        c = round(c, 4)
        doors.append(Door((i, j), (coord, c) if vertical else (c, coord), vertical))
    return doors


def build_walls(rects: list[Rect], doors: list[Door], door_width: float) -> list[Wall]:
    """Union of room sides per wall line, minus door gaps."""
    lines: dict[tuple[bool, float], list[tuple[float, float]]] = {}
    for x0, y0, x1, y1 in rects:
        for key, iv in (((False, y0), (x0, x1)), ((False, y1), (x0, x1)), ((True, x0), (y0, y1)), ((True, x1), (y0, y1))):
            lines.setdefault((key[0], round(key[1], 4)), []).append(iv)
    walls = []
    for (vertical, coord), ivs in sorted(lines.items()):
        ivs.sort()
        merged = [list(ivs[0])]
        for lo, hi in ivs[1:]:
            if lo <= merged[-1][1] + 1e-9:
                merged[-1][1] = max(merged[-1][1], hi)
            else:
                merged.append([lo, hi])
        gaps = sorted(
            (d.center[1] if vertical else d.center[0]) for d in doors
            if d.vertical == vertical and abs((d.center[0] if vertical else d.center[1]) - coord) < 1e-6
        )
        for lo, hi in merged:
            pieces, cur = [], lo
            for g in gaps:
                if lo < g < hi:
                    pieces.append((cur, g - door_width / 2))
                    cur = g + door_width / 2
            pieces.append((cur, hi))
            for a, b in pieces:
                if b - a > 0.05:
                    a, b = round(a, 4), round(b, 4)
                    pa, pb = ((coord, a), (coord, b)) if vertical else ((a, coord), (b, coord))
                    walls.append(Wall(pa, pb, WALL_THICKNESS, WALL_HEIGHT))
    return walls


def assign_types(rng, rects: list[Rect], room_types: tuple[str, ...]) -> list[str]:
    """Room types: the essential ones first (living room, kitchen, bedroom, bathroom), then others;
    the living room takes the largest room, the bathroom the smallest, a hallway the most elongated."""
    n = len(rects)
    essentials = [t for t in ("living room", "kitchen", "bedroom", "bathroom") if t in room_types]
    others = [t for t in room_types if t not in essentials]
    chosen = essentials[:n]
    pool = list(rng.permutation(others)) if others else []
    while len(chosen) < n:
        chosen.append(pool.pop(0) if pool else str(rng.choice(room_types)))
    area = [(r[2] - r[0]) * (r[3] - r[1]) for r in rects]
    elong = [max(r[2] - r[0], r[3] - r[1]) / min(r[2] - r[0], r[3] - r[1]) for r in rects]
    types: list[str | None] = [None] * n
    free = list(range(n))

    def take(t, idx):
        types[idx] = t
        free.remove(idx)
        chosen.remove(t)

    if "living room" in chosen:
        take("living room", max(free, key=lambda k: area[k]))
    if "bathroom" in chosen:
        take("bathroom", min(free, key=lambda k: area[k]))
    if "hallway" in chosen:
        take("hallway", max(free, key=lambda k: elong[k]))
    for t, idx in zip(rng.permutation(chosen), rng.permutation(free)):
        types[int(idx)] = str(t)
    return [str(t) for t in types]


# ----------------------------------------------------------------------------------------------------
# Furnishing


@dataclasses.dataclass
class _Furnisher:
    rng: np.random.Generator
    scene: Scene  # rooms/walls/start filled, no objects yet
    doors: list[Door]
    catalog: dict[str, Entry] = dataclasses.field(default_factory=lambda: CATALOG)  # of the world split
    plants: tuple[str, ...] = PLANTS
    objects: list[SceneObject] = dataclasses.field(default_factory=list)
    counts: Counter = dataclasses.field(default_factory=Counter)

    def __post_init__(self):
        self.grid = geometry.make_grid(self.scene, GRID_RES)
        self.free = geometry.free_mask(self.scene, self.grid, ROBOT_RADIUS, objects=[])
        self.xs, self.ys = self.grid.centers()

    # -- checks
    def _footprint_clear(self, x, y, w, d, flat: bool, room: Room) -> bool:
        m = WALL_THICKNESS / 2 + 0.02
        if not (room.min[0] + m + w / 2 <= x <= room.max[0] - m - w / 2):
            return False
        if not (room.min[1] + m + d / 2 <= y <= room.max[1] - m - d / 2):
            return False
        if flat:
            return True
        for o in self.objects:
            if o.size[2] <= geometry.FLAT_HEIGHT or o.position[2] - o.size[2] / 2 > 0.05:
                continue
            if abs(o.position[0] - x) < (o.size[0] + w) / 2 + 0.08 and abs(o.position[1] - y) < (o.size[1] + d) / 2 + 0.08:
                return False
        for door in self.doors:
            dx = max(abs(door.center[0] - x) - w / 2, 0.0)
            dy = max(abs(door.center[1] - y) - d / 2, 0.0)
            if math.hypot(dx, dy) < 0.9:
                return False
        sx, sy = self.scene.start.position
        if math.hypot(max(abs(sx - x) - w / 2, 0), max(abs(sy - y) - d / 2, 0)) < 0.6:
            return False
        return True

    def _space_free(self, x, y, z, w, d, h, support: SceneObject) -> bool:
        """A box standing on `support` meets no other object but flat ones (two things on one shelf stand side
        by side: neither is hidden inside the other)."""
        for o in self.objects:
            if o is support or o.size[2] <= geometry.FLAT_HEIGHT:
                continue
            gaps = [abs(p - q) - (a + b) / 2 for p, q, a, b in zip(o.position, (x, y, z), o.size, (w, d, h))]
            if max(gaps) < -SPACE_TOLERANCE:
                return False
        return True

    def _still_reachable(self, free: np.ndarray, extra: SceneObject | None) -> bool:
        labels, _ = ndimage.label(free)
        i, j = self.grid.cell_of(*self.scene.start.position)
        lab = labels[i, j]
        if lab == 0:
            return False
        reach = labels == lab
        for r in self.scene.rooms:
            inside = (self.xs > r.min[0]) & (self.xs < r.max[0]) & (self.ys > r.min[1]) & (self.ys < r.max[1])
            if not (reach & inside).any():
                return False
        objs = self.objects + ([extra] if extra is not None else [])
        for o in objs:
            if not self._object_reachable(reach, o):
                return False
        return True

    def _object_reachable(self, reach, o) -> bool:
        pad = SUCCESS_RADIUS + GRID_RES
        i0, j0 = self.grid.cell_of(o.position[0] - o.size[0] / 2 - pad, o.position[1] - o.size[1] / 2 - pad)
        i1, j1 = self.grid.cell_of(o.position[0] + o.size[0] / 2 + pad, o.position[1] + o.size[1] / 2 + pad)
        i0, j0 = max(i0, 0), max(j0, 0)
        sl = (slice(i0, i1 + 1), slice(j0, j1 + 1))
        sub = reach[sl]
        if not sub.any():
            return False
        dist = geometry.object_box_distance(o, self.xs[sl][sub], self.ys[sl][sub])
        return bool((dist <= SUCCESS_RADIUS).any())

    # -- sampling
    def _attributes(self, category: str, entry: Entry) -> dict[str, str]:
        """Attributes, differing from earlier instances of the category where the options allow."""
        used = {tuple(sorted(o.attributes)) for o in self.objects if o.category == category}
        for _ in range(8):
            attrs = {k: str(self.rng.choice(opts)) for k, opts in entry.attrs if self.rng.uniform() < 0.85}
            if tuple(sorted(attrs.items())) not in used:
                return attrs
        return attrs

    def _sensors(self, category: str, entry: Entry) -> dict[str, float]:
        out = {}
        for name, lo, hi in entry.sensors:
            v = self.rng.uniform(lo, hi)
            out[name] = round(v, 2) if name == "ndvi" else round(v, 1)
        return out

    def _pose(self, entry: Entry, room: Room, relation: str | None, anchor: SceneObject | None):
        w, d, h = (s * self.rng.uniform(0.9, 1.1) if s > 0.05 else s for s in entry.size)
        if relation == "on" and anchor is not None:
            if w > anchor.size[0] or d > anchor.size[1]:
                w, d = d, w
            if w > anchor.size[0] or d > anchor.size[1]:
                return None
            x = anchor.position[0] + self.rng.uniform(-1, 1) * (anchor.size[0] - w) / 2
            y = anchor.position[1] + self.rng.uniform(-1, 1) * (anchor.size[1] - d) / 2
            z = anchor.position[2] + anchor.size[2] / 2 + h / 2
            return x, y, z, w, d, h
        if relation == "near" and anchor is not None:
            side = self.rng.integers(4)
            gap = self.rng.uniform(0.15, 0.6)
            ax, ay = anchor.position[0], anchor.position[1]
            aw, ad = anchor.size[0] / 2, anchor.size[1] / 2
            if side < 2:
                x = ax + (1 if side == 0 else -1) * (aw + gap + w / 2)
                y = ay + self.rng.uniform(-ad, ad)
            else:
                y = ay + (1 if side == 2 else -1) * (ad + gap + d / 2)
                x = ax + self.rng.uniform(-aw, aw)
            return x, y, h / 2, w, d, h
        if entry.wall:
            side = self.rng.integers(4)
            off = WALL_THICKNESS / 2 + 0.03
            if side >= 2:  # against a vertical wall: the long side runs along y
                w, d = min(w, d), max(w, d)
                x = room.min[0] + off + w / 2 if side == 2 else room.max[0] - off - w / 2
                y = self.rng.uniform(room.min[1] + d / 2 + off, room.max[1] - d / 2 - off)
            else:
                w, d = max(w, d), min(w, d)
                y = room.min[1] + off + d / 2 if side == 0 else room.max[1] - off - d / 2
                x = self.rng.uniform(room.min[0] + w / 2 + off, room.max[0] - w / 2 - off)
            return x, y, h / 2, w, d, h
        if self.rng.uniform() < 0.5:
            w, d = d, w
        x = self.rng.uniform(room.min[0] + 0.5 + w / 2, max(room.min[0] + 0.5 + w / 2, room.max[0] - 0.5 - w / 2))
        y = self.rng.uniform(room.min[1] + 0.5 + d / 2, max(room.min[1] + 0.5 + d / 2, room.max[1] - 0.5 - d / 2))
        return x, y, h / 2, w, d, h

    def place(self, category: str, room: Room, relation: str | None = None, anchor=None, tries: int = 25):
        entry = self.catalog[category]
        for _ in range(tries):
            pose = self._pose(entry, room, relation, anchor)
            if pose is None:
                return None
            x, y, z, w, d, h = (round(v, 2) for v in pose)
            on_top = relation == "on"
            if not on_top and not self._footprint_clear(x, y, w, d, entry.flat, room):
                continue
            if on_top and not self._space_free(x, y, z, w, d, h, anchor):
                continue
            attrs = self._attributes(category, entry)
            sensors = self._sensors(category, entry)
            if category in self.plants and "ndvi" in sensors:
                attrs["condition"] = "healthy" if sensors["ndvi"] >= 0.6 else ("wilting" if sensors["ndvi"] < 0.3 else "fair")
            if attrs.get("state") == "switched off" and "temperature_c" in sensors:
                sensors["temperature_c"] = round(self.rng.uniform(18.0, 23.0), 1)  # off: room temperature
            self.counts[category] += 1
            obj = SceneObject(
                id=f"{category.replace(' ', '_')}_{self.counts[category]}",
                category=category,
                position=(x, y, round(z, 3)),
                size=(w, d, h),
                room=room.id,
                attributes=tuple(sorted(attrs.items())),
                sensors=tuple(sorted(sensors.items())),
            )
            free = self.free
            if not entry.flat and not on_top:
                hx, hy = w / 2 + ROBOT_RADIUS, d / 2 + ROBOT_RADIUS
                free = free & ~((np.abs(self.xs - x) <= hx) & (np.abs(self.ys - y) <= hy))
            if not self._still_reachable(free, obj):
                self.counts[category] -= 1
                continue
            self.free = free
            self.objects.append(obj)
            return obj
        return None

    def place_group(self, group: Group, room: Room, budget: int) -> int:
        anchor = self.place(group.anchor, room)
        if anchor is None:
            return 0
        n = 1
        for cat, rel, p in group.companions:
            if n >= budget:
                break
            if self.rng.uniform() < p and self.place(cat, room, rel, anchor) is not None:
                n += 1
        return n


def _groups_for(room_type: str, split: str = "seen") -> tuple[Group, ...]:
    return room_groups_for(split).get(room_type, generic_groups_for(split))


def furnish(rng, scene: Scene, doors: list[Door], cfg: WorldConfig) -> list[SceneObject]:
    f = _Furnisher(rng, scene, doors, catalog_for(cfg.split), plants_for(cfg.split))
    total_area = sum(r.area for r in scene.rooms)
    target = int(np.clip(round(total_area * rng.uniform(0.35, 0.6)), cfg.min_objects, cfg.max_objects))
    quotas = {r.id: max(2, round(target * r.area / total_area)) for r in scene.rooms}
    # Round-robin over rooms so each gets its characteristic anchors first.
    failures = Counter()
    rooms = list(scene.rooms)
    while len(f.objects) < target and any(failures[r.id] < 6 for r in rooms):
        for room in rooms:
            have = sum(o.room == room.id for o in f.objects)
            if len(f.objects) >= target or failures[room.id] >= 6:
                continue
            if have >= quotas[room.id] and any(failures[r.id] < 6 for r in rooms if r.id != room.id):
                failures[room.id] += 0.5  # over quota: let other rooms catch up first
                continue
            groups = _groups_for(room.type, cfg.split)
            placed_cats = Counter(o.category for o in f.objects if o.room == room.id)
            # Prefer anchors the room does not have yet.
            weights = np.array([g.weight / (1 + 2 * placed_cats[g.anchor]) for g in groups])
            g = groups[int(rng.choice(len(groups), p=weights / weights.sum()))]
            if f.place_group(g, room, target - len(f.objects)) == 0:
                failures[room.id] += 1
    # Distractors: make sure enough categories appear at least twice.
    tries = 0
    while tries < 40:
        multi = [c for c, k in Counter(o.category for o in f.objects).items() if k >= 2]
        if len(multi) >= cfg.min_distractor_categories:
            break
        tries += 1
        singles = sorted(c for c, k in Counter(o.category for o in f.objects).items() if k == 1)
        if not singles:
            break
        cat = str(rng.choice(singles))
        rooms_ok = [r for r in rooms if any(g.anchor == cat for g in _groups_for(r.type, cfg.split))] or rooms
        room = rooms_ok[int(rng.integers(len(rooms_ok)))]
        if len(f.objects) >= cfg.max_objects:
            # Replace-free strategy: drop the newest object that is not the only instance of its kind.
            counts = Counter(o.category for o in f.objects)
            for k in range(len(f.objects) - 1, -1, -1):
                if counts[f.objects[k].category] == 1 and f.objects[k].category != cat:
                    if not any(abs(o.position[2] - o.size[2] / 2 - (f.objects[k].position[2] + f.objects[k].size[2] / 2)) < 1e-6 for o in f.objects):
                        f.objects.pop(k)
                        break
        f.place(cat, room)
    return f.objects


def choose_start(rng, scene: Scene) -> Start:
    """Start in the living room (or the largest room), near its centre, facing a random direction."""
    rooms = [r for r in scene.rooms if r.type == "living room"] or sorted(scene.rooms, key=lambda r: -r.area)
    r = rooms[0]
    cx, cy = r.center
    x = _r(cx + rng.uniform(-0.25, 0.25) * (r.max[0] - r.min[0]), 0.05)
    y = _r(cy + rng.uniform(-0.25, 0.25) * (r.max[1] - r.min[1]), 0.05)
    yaw = round(float(rng.uniform(-math.pi, math.pi)), 3)
    return Start((x, y), yaw)


# ----------------------------------------------------------------------------------------------------


def generate_scene(cfg: WorldConfig, seed: int, index: int) -> Scene:
    """One house; deterministic in (cfg, seed, index)."""
    rng = np.random.default_rng(np.random.SeedSequence([int(seed), int(index)]))
    name = f"{cfg.name_prefix}_{index:03d}"
    for _ in range(200):
        n = int(rng.integers(cfg.min_rooms, cfg.max_rooms + 1))
        rects = split_rooms(rng, n, cfg.room_side)
        if rects is None:
            continue
        doors = place_doors(rng, rects, cfg.door_width, cfg.extra_door_prob) if n > 1 else []
        if doors is None:
            continue
        types = assign_types(rng, rects, cfg.room_types)
        seen = Counter()
        rooms = []
        for t, (x0, y0, x1, y1) in zip(types, rects):
            seen[t] += 1
            rooms.append(Room(f"{t.replace(' ', '_')}_{seen[t]}", t, (x0, y0), (x1, y1)))
        walls = build_walls(rects, doors, cfg.door_width)
        skeleton = Scene(name, tuple(rooms), tuple(walls), (), Start((0.0, 0.0)))
        skeleton = dataclasses.replace(skeleton, start=choose_start(rng, skeleton))
        objects = furnish(rng, skeleton, doors, cfg)
        if len(objects) < cfg.min_objects:
            continue
        scene = dataclasses.replace(skeleton, objects=tuple(objects))
        # Round-trip through the schema and geometric validation: the generator never writes bad scenes.
        return scene_from_dict(scene_to_dict(scene), source=name)
    raise RuntimeError(f"could not generate scene {name} with this config after 200 layouts")


def generate_scenes(cfg: WorldConfig, seed: int, progress: bool = False) -> list[Scene]:
    from tqdm.auto import tqdm

    it = range(cfg.num_scenes)
    if progress:
        it = tqdm(it, desc="generate", unit="scene")
    return [generate_scene(cfg, seed, i) for i in it]
