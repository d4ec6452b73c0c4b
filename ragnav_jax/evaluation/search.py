"""Where to look for a goal the memory has no confirmed candidate for: the search table.

    table = search_table(verifier, views, bank, episodes, subgoals, nodes=4)  # [e][g] -> node ids (views: memory_views)

The captioner misses things (a small lamp on a shelf, a console a sofa hides from the exploration's
camera), so a memory never holds every object. When a goal's candidates are all rejected, or it has none,
the reflection searches where the instruction says the object is, if it says so:
- a coordinate hint: the key poses within the hint's radius (`episodes.location_radius`) of it or in
  the room it lies in, nearest the hint first (the one nearest it when there are none);
- a room: the key poses inside the rooms the room phrase may mean (`Verifier.rooms_match`, so room names
  no prototype knows work), spread over them by farthest-point sampling from the one nearest a room's
  centre; when no room the memory named fits, the rooms it recorded nothing in.
A goal with neither is not searched. At most `nodes` key poses per goal; the loop visits them nearest
first, looks around at each and checks what it sees against the verdict table, as at a candidate.
Host NumPy, computed before the loop like the verdict table.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.evaluation.verify import SceneView, Verifier
from ragnav_jax.language.types import Subgoal
from ragnav_jax.world.scene import room_of


def spread(pos: np.ndarray, first: int, k: int) -> list[int]:
    """k indices of pos (n, 2) by farthest-point sampling from index `first` (all of them when n <= k)."""
    chosen = [first]
    d = np.linalg.norm(pos - pos[first], axis=1)
    while len(chosen) < min(k, len(pos)):
        nxt = int(np.argmax(d))
        chosen.append(nxt)
        d = np.minimum(d, np.linalg.norm(pos - pos[nxt], axis=1))
    return chosen


def search_nodes(verifier: Verifier, view: SceneView, sg: Subgoal, node_pos: np.ndarray, node_live: np.ndarray,
                 k: int) -> tuple[int, ...]:
    """Key poses (indices of node_pos (N, 2), live ones) to search for subgoal sg, at most k."""
    live = np.flatnonzero(node_live)
    if k <= 0 or not len(live):
        return ()
    rooms = view.scene.rooms
    if sg.location is not None:
        hint = (sg.location.x, sg.location.y)
        d = np.linalg.norm(node_pos[live] - hint, axis=1)
        order = np.argsort(d, kind="stable")
        room = room_of(rooms, *hint)
        near = [int(live[i]) for i in order if d[i] <= verifier.radius or (room and room_of(rooms, *node_pos[live[i]]) == room)]
        return tuple(near[:k] or [int(live[order[0]])])
    if sg.room is None:
        return ()
    unknown = {r for r, ns in view.room_names.items() if not ns}
    fit = verifier.rooms_match(sg.room, view) - unknown or unknown
    out: list[int] = []
    for r in (r for r in rooms if r.id in fit):
        inside = [int(n) for n in live if room_of(rooms, *node_pos[n]) == r.id]
        if inside:
            p = node_pos[inside]
            first = int(np.argmin(np.linalg.norm(p - r.center, axis=1)))
            out += [inside[i] for i in spread(p, first, k)]
    return tuple(out[:k])


def search_table(verifier: Verifier, views: dict[str, SceneView], bank, episodes, subgoals, nodes: int) -> list[list[tuple]]:
    """[e][g] -> key poses to search for goal g of episode e when its candidates run out (`search_nodes`);
    an empty list for an episode that did not parse. views: `memory_views` of the episodes' scenes."""
    pos = np.asarray(bank.memory.position)[..., :2]
    live = np.asarray(bank.memory.node_mask)
    names = list(bank.names)
    out = []
    for ep, sgs in zip(episodes, subgoals):
        b = names.index(ep.scene)
        out.append([search_nodes(verifier, views[ep.scene], sg, pos[b], live[b], nodes) for sg in sgs or ()])
    return out

