"""Reachability warnings (`ragnav validate`): which rooms and objects a robot of a given radius cannot
reach from the start pose, and what blocks the way (an object in a doorway, a narrow doorway, walls).

Host-side NumPy on the generator's 0.1 m raster with the generator's rules (`generator.py`): a room is
reachable when some reachable free cell lies inside it, an object when some reachable free cell lies
within SUCCESS_RADIUS of its box. Doorways are derived from the scene as the format defines them: gaps
in the walls along the boundary two rooms share.

Blockers are found by removing objects, never by guessing from positions. Only objects whose inflated
footprint borders the reachable region can open anything when removed, so each of those is removed
alone (one connected-component labelling each). When no single object explains a target, bordering
objects are removed greedily until it is reached, then the set is pruned to an irreducible one. The
doorway a blocker is named with is the one its removal lets the robot pass (reachable cells on both
sides of the gap); with no such doorway the warning gives the blocker's position instead.
"""

from __future__ import annotations

import dataclasses

import numpy as np
from scipy import ndimage

from ragnav_jax.world import geometry
from ragnav_jax.world.generator import GRID_RES, SUCCESS_RADIUS
from ragnav_jax.world.scene import Room, Scene, SceneObject

_TOL = 1e-3  # metres: two room sides closer than this are one shared boundary


@dataclasses.dataclass(frozen=True)
class Doorway:
    """A gap in the walls along the boundary shared by two rooms."""

    rooms: tuple[str, str]  # ids of the two rooms it joins
    a: tuple[float, float]  # gap end points on the shared boundary
    b: tuple[float, float]
    wall_thickness: float = 0.0  # of the walls on that boundary (0 for an open plan)

    @property
    def center(self) -> tuple[float, float]:
        return ((self.a[0] + self.b[0]) / 2, (self.a[1] + self.b[1]) / 2)

    @property
    def width(self) -> float:
        return float(np.hypot(self.b[0] - self.a[0], self.b[1] - self.a[1]))

    @property
    def clear(self) -> float:
        """Width left between the wall ends (each wall reaches half its thickness past its end point)."""
        return self.width - self.wall_thickness


@dataclasses.dataclass(frozen=True)
class Blocked:
    """One room or object the robot cannot reach, and why.

    At most one explanation is filled: `blockers` (objects whose removal opens the way: any one of
    them when `together` is False, all of them when True), `narrow` (doorways too narrow for the robot,
    into a room unreachable even without objects), or neither (walled off; for objects: no floor near
    it even without objects).
    """

    kind: str  # "room", "object" or "start"
    id: str  # room or object id ("" for the start)
    label: str  # room type or object category
    room: str  # holding room of an object ("" otherwise)
    blockers: tuple[str, ...] = ()  # object ids
    doors: tuple[Doorway | None, ...] = ()  # per blocker: the doorway its removal opens (None: none)
    together: bool = False
    narrow: tuple[Doorway, ...] = ()
    hidden_objects: int = 0  # rooms: objects inside that are unreachable too (not warned one by one)


# ----------------------------------------------------------------------------------------------------
# Doorways


def _subtract(lo: float, hi: float, covered: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Parts of [lo, hi] outside the union of the `covered` intervals, longer than _TOL."""
    out, cur = [], lo
    for c0, c1 in sorted(covered):
        if c0 > cur + _TOL:
            out.append((cur, min(c0, hi)))
        cur = max(cur, c1)
        if cur >= hi:
            break
    if hi > cur + _TOL:
        out.append((cur, hi))
    return [(a, b) for a, b in out if b - a > _TOL]


def _shared_sides(r1: Room, r2: Room):
    """(axis, coord, lo, hi) of the boundary stretches two rooms share; axis 0: the line x = coord."""
    for axis in (0, 1):
        o = 1 - axis
        for c1, c2 in ((r1.max[axis], r2.min[axis]), (r1.min[axis], r2.max[axis])):
            lo, hi = max(r1.min[o], r2.min[o]), min(r1.max[o], r2.max[o])
            if abs(c1 - c2) <= _TOL and hi - lo > _TOL:
                yield axis, (c1 + c2) / 2, lo, hi


def doorways(scene: Scene) -> list[Doorway]:
    """Every wall gap on a boundary two rooms share (open plans, with no wall there, give one wide gap).

    A wall lies on the boundary line when both its end points are within half its thickness of it.
    """
    out = []
    for i, r1 in enumerate(scene.rooms):
        for r2 in scene.rooms[i + 1 :]:
            for axis, c, lo, hi in _shared_sides(r1, r2):
                o = 1 - axis
                on_line = [
                    w
                    for w in scene.walls
                    if abs(w.a[axis] - c) <= w.thickness / 2 + _TOL and abs(w.b[axis] - c) <= w.thickness / 2 + _TOL
                ]
                covered = [(min(w.a[o], w.b[o]), max(w.a[o], w.b[o])) for w in on_line]
                thick = max((w.thickness for w in on_line), default=0.0)
                for g0, g1 in _subtract(lo, hi, covered):
                    a, b = ((c, g0), (c, g1)) if axis == 0 else ((g0, c), (g1, c))
                    out.append(Doorway((r1.id, r2.id), a, b, thick))
    return out


def gap_distance(o: SceneObject, d: Doorway) -> float:
    """Planar distance from the object's footprint to the doorway's gap (0 when they touch)."""
    t = np.linspace(0.0, 1.0, max(2, int(np.ceil(d.width / 0.05)) + 1))
    px, py = d.a[0] + t * (d.b[0] - d.a[0]), d.a[1] + t * (d.b[1] - d.a[1])
    return float(geometry.object_box_distance(o, px, py).min())


# ----------------------------------------------------------------------------------------------------
# Rasters


def object_boxes(grid: geometry.Grid, objects, inflate: float) -> np.ndarray:
    """(K, rows, cols) bool: cells whose centre lies in object k's footprint grown by `inflate`
    (the same rule as `geometry.free_mask`)."""
    xs, ys = grid.centers()
    out = np.zeros((len(objects), *grid.shape), bool)
    for k, o in enumerate(objects):
        hx, hy = o.size[0] / 2 + inflate, o.size[1] / 2 + inflate
        out[k] = (np.abs(xs - o.position[0]) <= hx) & (np.abs(ys - o.position[1]) <= hy)
    return out


def room_reached(room: Room, xs: np.ndarray, ys: np.ndarray, reach: np.ndarray) -> bool:
    """Some reachable cell (reach, xs, ys: (rows, cols)) lies strictly inside the room."""
    inside = (xs > room.min[0]) & (xs < room.max[0]) & (ys > room.min[1]) & (ys < room.max[1])
    return bool((reach & inside).any())


def object_reached(o: SceneObject, grid: geometry.Grid, reach: np.ndarray, radius: float = SUCCESS_RADIUS) -> bool:
    """Some reachable cell (reach: (rows, cols)) lies within `radius` of the object's box; looks only
    at the window around the object."""
    pad = radius + grid.resolution
    i0, j0 = grid.cell_of(o.position[0] - o.size[0] / 2 - pad, o.position[1] - o.size[1] / 2 - pad)
    i1, j1 = grid.cell_of(o.position[0] + o.size[0] / 2 + pad, o.position[1] + o.size[1] / 2 + pad)
    sl = (slice(max(i0, 0), max(i1 + 1, 0)), slice(max(j0, 0), max(j1 + 1, 0)))
    sub = reach[sl]
    if not sub.any():
        return False
    xs, ys = grid.centers()
    return bool((geometry.object_box_distance(o, xs[sl][sub], ys[sl][sub]) <= radius).any())


def _span(lo: float, hi: float, origin: float, res: float, n: int) -> slice:
    """Indices of the cells (of n) whose centres lie in [lo, hi]."""
    i0 = int(np.ceil((lo - origin) / res - 0.5 - 1e-9))
    i1 = int(np.floor((hi - origin) / res - 0.5 + 1e-9))
    return slice(min(max(i0, 0), n), min(max(i1 + 1, 0), n))


def door_sides(grid: geometry.Grid, doors: list[Doorway], margin: float) -> list[tuple[tuple[slice, slice], ...]]:
    """Per doorway, two (row, col) slice pairs: the cells along its gap on either side of the wall
    line, up to half the wall thickness plus `margin` metres from it (the line itself excluded).
    The robot passes the doorway when it reaches both sides."""
    (x0, y0), res, (rows, cols) = grid.origin, grid.resolution, grid.shape
    out = []
    for d in doors:
        depth = d.wall_thickness / 2 + margin
        vertical = d.a[0] == d.b[0]  # the wall line is x = const
        c = d.a[0] if vertical else d.a[1]
        lo, hi = sorted((d.a[1], d.b[1]) if vertical else (d.a[0], d.b[0]))
        sides = []
        for a, b in ((c - depth, c - 1e-6), (c + 1e-6, c + depth)):
            if vertical:
                sides.append((_span(lo, hi, y0, res, rows), _span(a, b, x0, res, cols)))
            else:
                sides.append((_span(a, b, y0, res, rows), _span(lo, hi, x0, res, cols)))
        out.append(tuple(sides))
    return out


def doors_open(reach: np.ndarray, sides) -> np.ndarray:
    """(D,) bool: both sides of doorway d hold reachable cells (reach: (rows, cols))."""
    return np.array([all(reach[sl].any() for sl in pair) for pair in sides], bool)


@dataclasses.dataclass(frozen=True)
class _Raster:
    """The scene on the raster, objects kept apart so any subset can be removed."""

    scene: Scene
    grid: geometry.Grid
    walls_free: np.ndarray  # (rows, cols) bool free of walls (robot centre)
    boxes: np.ndarray  # (K, rows, cols) bool inflated footprints of the blocking objects
    count: np.ndarray  # (rows, cols) int32 how many inflated footprints cover each cell

    def reach_without(self, removed=()) -> np.ndarray:
        """(rows, cols) bool cells reachable from the start once the objects `removed` (indices) go."""
        removed = list(removed)
        occupied = self.count - self.boxes[removed].sum(0, dtype=np.int32) if removed else self.count
        return geometry.reachable_mask(self.scene, self.grid, free=self.walls_free & (occupied == 0))

    def border(self, reach: np.ndarray) -> np.ndarray:
        """(K,) bool: objects whose footprint touches the region's edge (only these can open it)."""
        edge = ndimage.binary_dilation(reach) & ~reach & self.walls_free
        return self.boxes[:, edge].any(1)


def _raster(scene: Scene, robot_radius: float, resolution: float) -> tuple[_Raster, list[SceneObject]]:
    grid = geometry.make_grid(scene, resolution)
    objects = geometry.blocking_objects(scene)
    boxes = object_boxes(grid, objects, robot_radius)
    walls_free = geometry.free_mask(scene, grid, robot_radius, objects=[])
    return _Raster(scene, grid, walls_free, boxes, boxes.sum(0, dtype=np.int32)), objects


# ----------------------------------------------------------------------------------------------------
# Blocked rooms and objects


def _targets_reached(grid, reach, targets) -> list[bool]:
    """Per target (a Room or a SceneObject): reached by the (rows, cols) mask `reach`."""
    xs, ys = grid.centers()
    return [room_reached(t, xs, ys, reach) if isinstance(t, Room) else object_reached(t, grid, reach) for t in targets]


def _joint_blockers(ras: _Raster, target, exclude: int | None) -> tuple[int, ...]:
    """Indices of an irreducible set of objects whose joint removal reaches `target` (() if none):
    remove every object bordering the reachable region until it is reached, then put back each one
    that is not needed."""
    removed: set[int] = set()
    while not _targets_reached(ras.grid, reach := ras.reach_without(removed), [target])[0]:
        new = set(np.flatnonzero(ras.border(reach)).tolist()) - removed - {exclude}
        if not new:
            return ()
        removed |= new
    for k in sorted(removed):
        if _targets_reached(ras.grid, ras.reach_without(removed - {k}), [target])[0]:
            removed.discard(k)
    return tuple(sorted(removed))


def _opened_door(ras: _Raster, removed, closed: np.ndarray, doors, sides, objects) -> Doorway | None:
    """Of the doorways the robot could not pass (closed: (D,) bool), the one that removing the objects
    `removed` (indices) opens; the nearest to them when several open, None when none does."""
    opened = doors_open(ras.reach_without(removed), sides) & closed
    cands = [d for d, o in zip(doors, opened) if o]
    if len(cands) <= 1:
        return cands[0] if cands else None
    return min(cands, key=lambda d: min(gap_distance(objects[k], d) for k in removed))


def find_blocked(scene: Scene, robot_radius: float, resolution: float = GRID_RES) -> list[Blocked]:
    """Rooms and objects (scene order) a robot of `robot_radius` cannot reach from the start, and why.

    Objects in an unreachable room are counted in the room's `hidden_objects`, not listed.
    """
    ras, objects = _raster(scene, robot_radius, resolution)
    i, j = ras.grid.cell_of(*scene.start.position)
    if not ras.walls_free[i, j] or ras.count[i, j]:
        return [Blocked("start", "", "", "", blockers=tuple(o.id for o, b in zip(objects, ras.boxes) if b[i, j]))]
    reach = ras.reach_without()
    rooms_ok = dict(zip([r.id for r in scene.rooms], _targets_reached(ras.grid, reach, scene.rooms)))
    lost_rooms = [r for r in scene.rooms if not rooms_ok[r.id]]
    lost_objects = [o for o, ok in zip(scene.objects, _targets_reached(ras.grid, reach, scene.objects)) if not ok]
    if not lost_rooms and not lost_objects:
        return []
    hidden = {r.id: sum(o.room == r.id for o in lost_objects) for r in lost_rooms}
    targets = lost_rooms + [o for o in lost_objects if rooms_ok.get(o.room, True)]
    reach0 = ras.reach_without(range(len(objects)))
    open0 = _targets_reached(ras.grid, reach0, targets)
    index = {o.id: k for k, o in enumerate(objects)}
    doors = doorways(scene)
    sides = door_sides(ras.grid, doors, robot_radius + 2 * resolution)
    closed = ~doors_open(reach, sides)

    # Single blockers: every object bordering the reachable region, removed alone.
    singles: dict[int, list[int]] = {t: [] for t in range(len(targets))}
    pending = [t for t in range(len(targets)) if open0[t]]
    for k in np.flatnonzero(ras.border(reach)).tolist():
        hits = _targets_reached(ras.grid, ras.reach_without([k]), [targets[t] for t in pending])
        for t, hit in zip(pending, hits):
            if hit and not (isinstance(targets[t], SceneObject) and targets[t].id == objects[k].id):
                singles[t].append(k)

    rooms0 = dict(zip([r.id for r in scene.rooms], _targets_reached(ras.grid, reach0, scene.rooms)))
    out = []
    for t, target in enumerate(targets):
        is_room = isinstance(target, Room)
        base = Blocked(
            "room" if is_room else "object",
            target.id,
            target.type if is_room else target.category,
            "" if is_room else target.room,
            hidden_objects=hidden.get(target.id, 0) if is_room else 0,
        )
        if singles[t]:
            ks = singles[t]
            door = tuple(_opened_door(ras, [k], closed, doors, sides, objects) for k in ks)
            out.append(dataclasses.replace(base, blockers=tuple(objects[k].id for k in ks), doors=door))
        elif open0[t]:
            ks = _joint_blockers(ras, target, None if is_room else index.get(target.id))
            door = (_opened_door(ras, ks, closed, doors, sides, objects),) * len(ks)
            out.append(
                dataclasses.replace(base, blockers=tuple(objects[k].id for k in ks), doors=door, together=len(ks) > 1)
            )
        elif is_room:
            narrow = tuple(
                d
                for d in doors
                if target.id in d.rooms
                and rooms0[d.rooms[0] if d.rooms[1] == target.id else d.rooms[1]]
                and d.clear < 2 * robot_radius + 2 * resolution  # wider ones are closed by something else
            )
            out.append(dataclasses.replace(base, narrow=narrow))
        else:
            out.append(base)
    return out


# ----------------------------------------------------------------------------------------------------
# Warning lines


def _num(v: float) -> str:
    s = f"{v:.2f}".rstrip("0")
    return s + "0" if s.endswith(".") else s


def _at(p) -> str:
    return f"({_num(p[0])}, {_num(p[1])})"


def _door_name(d: Doorway, room: str) -> str:
    if room in d.rooms:
        other = d.rooms[1] if d.rooms[0] == room else d.rooms[0]
        return f"doorway to '{other}' at {_at(d.center)}"
    return f"doorway between '{d.rooms[0]}' and '{d.rooms[1]}' at {_at(d.center)}"


def _obj(o: SceneObject) -> str:
    return f"'{o.id}' ({o.category})"


def _reason(scene: Scene, b: Blocked, robot_radius: float) -> str:
    """Why `b` is unreachable, as a clause."""
    room = b.id if b.kind == "room" else b.room
    if b.blockers:
        objs = [scene.object_by_id(k) for k in b.blockers]
        near = 2 * robot_radius + 0.5  # farther from the gap, an object blocks the way to the doorway

        def where(d: Doorway | None, group) -> str:
            if d is None:
                return "the way"
            at_gap = min(gap_distance(o, d) for o in group) <= near
            return _door_name(d, room) if at_gap else f"the way to the {_door_name(d, room)}"

        if b.together:
            names = ", ".join(_obj(o) for o in objs[:-1]) + f" and {_obj(objs[-1])}"
            return f"{where(b.doors[0], objs)} is blocked by objects {names} together"
        groups: dict[tuple, list[SceneObject]] = {}
        for o, d in zip(objs, b.doors):
            groups.setdefault((d, where(d, [o])), []).append(o)
        parts = []
        for (d, place), group in groups.items():
            names = ", ".join(_obj(o) + ("" if d else f" at {_at(o.position)}") for o in group)
            parts.append(f"{place} is blocked by {'objects' if len(group) > 1 else 'object'} {names}")
        return "; ".join(parts) + (" (removing any one of them opens it)" if len(objs) > 1 else "")
    if b.narrow:
        return "; ".join(
            f"{_door_name(d, room)} is too narrow for a robot of radius {_num(robot_radius)} m "
            f"({_num(max(d.clear, 0.0))} m clear between the wall ends)"
            for d in b.narrow
        )
    if b.kind == "room":
        return "it is walled off (no doorway leads to it from a reachable room)"
    return f"no floor within {_num(SUCCESS_RADIUS)} m of it is reachable even without furniture (walls)"


def format_blocked(scene: Scene, b: Blocked, robot_radius: float) -> str:
    """One warning line (without a file prefix), e.g. "room 'kitchen_1' (kitchen) is not reachable from
    the start: doorway to 'hallway_1' at (3.0, 4.5) is blocked by object 'sofa_2' (sofa)"."""
    if b.kind == "start":
        p = _at(scene.start.position)
        if b.blockers:
            names = ", ".join(_obj(scene.object_by_id(k)) for k in b.blockers)
            return f"start {p} is not free for a robot of radius {_num(robot_radius)} m: it overlaps {names}; nothing is reachable"
        return f"start {p} is not free for a robot of radius {_num(robot_radius)} m: a wall is too close; nothing is reachable"
    what = f"room '{b.id}' ({b.label})" if b.kind == "room" else f"object '{b.id}' ({b.label}) in room '{b.room}'"
    line = f"{what} is not reachable from the start: {_reason(scene, b, robot_radius)}"
    if b.hidden_objects:
        line += f"; {b.hidden_objects} object{'s' if b.hidden_objects > 1 else ''} in it unreachable too"
    return line


def lidar_blind(scene: Scene, lidar_height: float, robot_bottom: float) -> list[str]:
    """Warning lines for objects that stop the robot (their top is above its lowest point, `robot_bottom`)
    but stand below the lidar's plane: exploration maps free floor there, plans through them and gets stuck."""
    out = []
    for o in geometry.blocking_objects(scene):
        top = o.position[2] + o.size[2] / 2
        if robot_bottom < top < lidar_height:
            out.append(f"object '{o.id}' ({o.category}) at {_at(o.position[:2])} is {_num(top)} m tall, under the "
                       f"lidar ({_num(lidar_height)} m) but high enough to stop the robot: exploration cannot see it "
                       f"and may not get past it")
    return out


def reach_warnings(scene: Scene, robot_radius: float) -> list[str]:
    """Warning lines for every room and object of the scene the robot cannot reach (empty when all can)."""
    return [format_blocked(scene, b, robot_radius) for b in find_blocked(scene, robot_radius)]
