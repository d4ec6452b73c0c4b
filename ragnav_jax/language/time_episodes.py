"""Time-indexed episodes ("go to the mug you saw first"), generated after exploration from the recorded stream.

The truth is the exploration stream's: an object's first and latest views are the first and the last records in
which the forward camera saw it. A query names a kind of object (its category name), optionally a room, and an
(order, rank); the target is the object of that kind (in that room) seen rank-th earliest ("first") or rank-th
latest ("last"), among the objects of the kind the robot saw. A query is generated only where the stream makes the
answer clear: two or more objects of the kind were seen, and the target's view is at least `gap` records from the
views of its neighbours in that order (a person who saw two mugs in one glance could not say which came first).

The memory cannot read the stream: retrieval ranks by the records of the key poses whose captions described each
instance (`RetrievalIndex.inst_first` / `inst_last`), so key-pose spacing and captions that leave an object out
are what it gets wrong.

Phrasings: "seen" are this module's own templates (the time reader, `time_words.py`, was written beside them);
"heldout" (`time_text_heldout.py`, set 1) to "heldout4" (set 4) were each written by an author who never read the
reader. Set k was measured fresh once with the reader frozen at round k, then round k + 1 was developed on its
failures (and those of the sets before it); set k + 1 was written before round k + 1 was.
"""

from __future__ import annotations

import dataclasses
import zlib
from collections.abc import Mapping, Sequence

import numpy as np

from ragnav_jax.errors import UserError
from ragnav_jax.language.episodes import POLITE, VERBS, Episode, GeneratedEpisode, SceneFacts, _room_ok, _sentence
from ragnav_jax.language.types import Subgoal, Target, TaskChain, TimeConstraint, derive_dependencies
from ragnav_jax.sim.stream import ExplorationStream
from ragnav_jax.world.scene import Scene

MODALITY = "text+time"
PHRASINGS = ("seen", "heldout", "heldout2", "heldout3", "heldout4")
MAX_RANK = 3


@dataclasses.dataclass(frozen=True)
class TimeQuery:
    """One generated query: the kind, room (or None), order and rank, and the object that answers it."""

    phrase: str
    room: str | None
    order: str
    rank: int
    object_id: str


def scene_queries(scene: Scene, stream: ExplorationStream, facts: SceneFacts, gap: int) -> list[TimeQuery]:
    """Every clear time-indexed query of one explored scene (see the module docstring), in a fixed order."""
    if tuple(stream.object_ids) != tuple(o.id for o in scene.objects):
        raise UserError(f"stream of scene '{scene.name}' lists other objects than the scene file (explore it again)")
    first, last = stream.view_times()
    col = {o.id: k for k, o in enumerate(scene.objects)}
    room_types = [r.type for r in scene.rooms]
    room_of = {r.id: r.type for r in scene.rooms}
    out = []
    for kind in sorted({o.category for o in scene.objects}):
        named = [o for o in facts.by_head.get(kind, ()) if first[col[o.id]] >= 0 and o.id not in scene.absent]
        if not named or any(o.category != kind for o in named):  # the name must pick out its own kind only
            continue
        pools = [(None, named)] + [(rt, [o for o in named if room_of.get(o.room) == rt])
                                   for rt in sorted({room_of.get(o.room) for o in named} - {None})
                                   if room_types.count(rt) == 1 and _room_ok(rt)]
        for room, pool in pools:
            if len(pool) < 2:
                continue
            for order, times in (("first", first), ("last", -last)):
                ranked = sorted(pool, key=lambda o: times[col[o.id]])
                keys = [int(times[col[o.id]]) for o in ranked]
                for rank in range(1, min(MAX_RANK, len(pool)) + 1):
                    k = rank - 1
                    gaps = [abs(keys[k] - keys[j]) for j in (k - 1, k + 1) if 0 <= j < len(keys)]
                    if min(gaps) >= gap:
                        out.append(TimeQuery(kind, room, order, rank, ranked[k].id))
    return out


# The generator's own phrasings (split "seen"): ordinal adjectives, adverbs after the verb, participles.
_ADJ = {("first", 1): ("first", "earliest"), ("first", 2): ("second",), ("first", 3): ("third",),
        ("last", 1): ("last", "latest", "most recent"), ("last", 2): ("second-to-last", "second most recent"),
        ("last", 3): ("third-to-last", "third most recent")}
_ADV = {("first", 1): ("first",), ("first", 2): ("second",), ("first", 3): ("third",),
        ("last", 1): ("last", "most recently"), ("last", 2): ("second to last",), ("last", 3): ("third to last",)}
_SAW = ("saw", "spotted", "noticed", "passed", "came across")
_SEEN = ("seen", "spotted", "noticed")


def time_goal(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    """One instruction for a time-indexed goal in the generator's own words ("Go to the mug you saw first.")."""
    pick = lambda xs: xs[int(rng.integers(len(xs)))]  # noqa: E731
    where = f" in the {room}" if room else ""
    adj, adv, saw = pick(_ADJ[order, rank]), pick(_ADV[order, rank]), pick(_SAW)
    shapes = [f"the {adj} {phrase}{where} you {saw}", f"the {phrase}{where} you {saw} {adv}",
              f"the {phrase}{where} {pick(_SEEN)} {adv}"]
    if rank == 1:
        shapes += [f"the {phrase}{where} that you {'first' if order == 'first' else pick(('last', 'most recently'))} "
                   f"{saw}", f"the {'first' if order == 'first' else pick(('last', 'most recently'))} "
                   f"{pick(_SEEN)} {phrase}{where}"]
    return _sentence(f"{pick(POLITE)}{pick(VERBS)} {pick(shapes)}")


def _phrasing(name: str):
    if name == "seen":
        return time_goal
    import importlib

    return getattr(importlib.import_module(f"ragnav_jax.language.time_text_{name}"), f"time_goal_{name}")


def generate_time_episodes(scenes: Sequence[Scene], streams: Mapping[str, ExplorationStream], facts_of,
                           per_scene: int, gap: int, phrasing: str, seed: int) -> list[GeneratedEpisode]:
    """Up to `per_scene` time-indexed single-goal episodes per scene, drawn without replacement from its clear
    queries; `facts_of(scene)` gives the scene's SceneFacts. Same inputs and seed, same episodes."""
    if phrasing not in PHRASINGS:
        raise UserError(f"time phrasing '{phrasing}' is not one of {', '.join(PHRASINGS)}")
    say = _phrasing(phrasing)
    out = []
    for scene in scenes:
        if scene.name not in streams:
            raise UserError(f"no exploration stream for scene '{scene.name}' (run ragnav explore first)")
        queries = scene_queries(scene, streams[scene.name], facts_of(scene), gap)
        rng = np.random.default_rng(np.random.SeedSequence([int(seed), zlib.crc32(scene.name.encode()), 7]))
        for k, i in enumerate(sorted(rng.permutation(len(queries))[:per_scene])):
            q = queries[i]
            text = say(rng, q.phrase, q.order, q.rank, q.room)
            sg = Subgoal(0, Target(q.phrase, q.phrase), room=q.room, text=text, time=TimeConstraint(q.order, q.rank))
            truth = TaskChain(instruction=text, subgoals=(sg,), order="strict",
                              dependencies=derive_dependencies((sg,), "strict"), parser="truth")
            ep = Episode(f"{scene.name}-time-{k:03d}", scene.name, text, (q.object_id,), MODALITY, "strict")
            out.append(GeneratedEpisode(ep, truth))
    return out
