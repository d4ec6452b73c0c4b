"""Episodes: the `ragnav-episode` JSONL files, and a generator with a ground-truth TaskChain per episode.

    pairs = generate_episodes(scenes, cfg.episodes, seed=cfg.seed)    # [GeneratedEpisode]
    save_episodes([p.episode for p in pairs], "episodes.jsonl")
    episodes = load_episodes("episodes.jsonl")                          # EpisodeError names file:line

The generator describes each goal object so that the description picks out that object and no other
in the scene's ground truth (`resolve`), using, in this order of need, the category name or a
synonym, attributes, the room, a neighbouring object (nested up to two levels), a coordinate hint, or
a sensor reading / superlative. The three modalities:
- text: words only;
- text+location: at least one goal whose category has distractors is told apart by a coordinate hint;
- text+location+sensor: at least one goal is told apart by a sensor threshold, an approximate value
  or a superlative (possibly under a hypernym: "the warmest appliance in the kitchen").
Instructions come from strict and free templates with varied verbs and politeness. The generator may
use scene vocabulary (synonyms, hypernyms); the parser never does. Every draw comes from a NumPy
generator seeded by (seed, scene name, modality), so a seed gives the same file.
"""

from __future__ import annotations

import dataclasses
import functools
import importlib
import json
import math
import zlib
from collections.abc import Iterable, Sequence
from pathlib import Path

import numpy as np

from ragnav_jax.config import EpisodesConfig
from ragnav_jax.errors import UserError
from ragnav_jax.filenames import name_problem
from ragnav_jax.io import write_jsonl
from ragnav_jax.language import lexicon as L
from ragnav_jax.language.parser import split_noun_phrase
from ragnav_jax.language.readings import READINGS
from ragnav_jax.language.types import (
    Location,
    Relation,
    SensorConstraint,
    Subgoal,
    Target,
    TaskChain,
    derive_dependencies,
)
from ragnav_jax.world.scene import Scene, SceneObject

MODALITIES = ("text", "text+location", "text+location+sensor")
MODALITY_TAGS = {"text": "t", "text+location": "tl", "text+location+sensor": "tls"}

# Generator-side vocabulary (scene knowledge; the parser has none of this).
SYNONYMS: dict[str, tuple[str, ...]] = {
    "sofa": ("couch",),
    "television": ("tv",),
    "remote control": ("remote",),
    "fridge": ("refrigerator",),
    "bookshelf": ("bookcase",),
    "nightstand": ("bedside table", "night table"),
    "bedside table": ("nightstand",),
    "trash bin": ("bin", "rubbish bin", "garbage can"),
    "computer monitor": ("monitor",),
    "office chair": ("desk chair",),
    "dresser": ("chest of drawers",),
    "stove": ("cooker",),
    "washing machine": ("washer",),
    "bathtub": ("bath", "tub"),
    "potted plant": ("houseplant",),
    "coat rack": ("coat stand",),
    "exercise bike": ("stationary bike",),
    "treadmill": ("running machine",),
    "filing cabinet": ("file cabinet",),
    "water cooler": ("water dispenser",),
    "punching bag": ("boxing bag",),
    "microwave": ("microwave oven",),
    "yoga mat": ("exercise mat",),
}
HYPERNYMS: dict[str, frozenset[str]] = {
    "appliance": frozenset(
        ("fridge", "coffee machine", "stove", "kettle", "microwave", "dishwasher", "washing machine", "printer",
         "water cooler")
    ),
    "plant": frozenset(("potted plant", "fern", "cactus", "orchid", "tomato plant", "lemon tree")),
    "lamp": frozenset(("floor lamp", "table lamp", "desk lamp")),
}


@functools.cache
def names(unseen: bool = True) -> tuple[dict[str, tuple[str, ...]], dict[str, frozenset[str]]]:
    """(synonyms, hypernyms) people use: the seen ones above and, with `unseen`, the world's unseen-split
    vocabulary (world/vocabulary.py UNSEEN_SYNONYMS, UNSEEN_HYPERNYMS). The catalogues are disjoint, so a
    house's categories decide which apply (`names_for`: seen houses are described exactly as before the
    unseen ones existed, and describing them never reads the unseen tables)."""
    if not unseen:
        return dict(SYNONYMS), dict(HYPERNYMS)
    from ragnav_jax.world.vocabulary import UNSEEN_HYPERNYMS, UNSEEN_SYNONYMS

    hyp = dict(HYPERNYMS)
    for k, cats in UNSEEN_HYPERNYMS.items():
        hyp[k] = hyp.get(k, frozenset()) | cats
    return {**SYNONYMS, **UNSEEN_SYNONYMS}, hyp


def names_for(categories) -> tuple[dict[str, tuple[str, ...]], dict[str, frozenset[str]]]:
    """`names()` for objects of these categories: the unseen tables only when one is not a seen category."""
    from ragnav_jax.world.vocabulary import CATALOG

    return names(any(c not in CATALOG for c in categories))


FRAMES = {"gold": "gold-framed", "black": "black-framed", "wooden": "wooden-framed", "aluminium": "aluminium-framed",
          "frameless": "frameless"}
APPROX_TOL = {k: r.tolerance for k, r in READINGS.items()}  # "about v" matches |r - v| <= tol
READING_TEXT = {k: r.text for k, r in READINGS.items()}
NEAR_TYPES = ("near", "next_to", "beside", "by")
REL_TEXT = {
    "near": ("near", "close to"),
    "next_to": ("next to",),
    "beside": ("beside",),
    "by": ("by",),
    "on": ("on", "on top of"),
    "with": ("with",),
    "in_room_with": ("in the room with", "in the same room as"),
}


class EpisodeError(UserError):
    """An episodes file is invalid; the message names the file and line."""


# ----------------------------------------------------------------------------------------------------
# Episode records


@dataclasses.dataclass(frozen=True)
class Episode:
    """One line of an episodes file (schema: world/schemas/episode.schema.json)."""

    id: str
    scene: str
    instruction: str
    goals: tuple[str, ...]  # object ids, in instruction order
    modality: str = "text"
    order: str = "strict"
    max_steps: int | None = None

    def to_dict(self) -> dict:
        d = {"id": self.id, "scene": self.scene, "instruction": self.instruction, "modality": self.modality,
             "goals": [{"object_id": g} for g in self.goals], "order": self.order}
        if self.max_steps is not None:
            d["max_steps"] = self.max_steps
        return d

    @classmethod
    def from_dict(cls, d: dict) -> Episode:
        return cls(d["id"], d["scene"], d["instruction"], tuple(g["object_id"] for g in d["goals"]),
                   d.get("modality", "text"), d.get("order", "strict"), d.get("max_steps"))


@dataclasses.dataclass(frozen=True)
class GeneratedEpisode:
    episode: Episode
    truth: TaskChain  # what the instruction says, as the generator wrote it (parser = "truth")


def validate_episode_dict(d, source: str, line: int) -> Episode:
    import jsonschema

    from ragnav_jax.world.scene import load_schema

    validator = jsonschema.Draft202012Validator(load_schema("episode"))
    errors = list(validator.iter_errors(d))
    if errors:
        err = jsonschema.exceptions.best_match(errors)
        where = "$" + "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in err.absolute_path)
        raise EpisodeError(f"{source}: line {line}: {where}: {err.message[:200]}")
    if problem := name_problem(d["id"]):  # an id may name per-episode output files
        raise EpisodeError(f"{source}: line {line}: $.id: episode id {problem}")
    return Episode.from_dict(d)


def load_episodes(path: str | Path, scenes: Sequence[Scene] | None = None) -> list[Episode]:
    """Reads a JSONL episodes file; with scenes, also checks scene names and goal object ids."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise EpisodeError(f"{path}: file is not UTF-8 text") from None
    except OSError as e:
        raise EpisodeError(f"{path}: cannot read file ({e.strerror})") from None
    by_name = {s.name: s for s in scenes} if scenes is not None else None
    out, ids = [], {}
    for n, raw in enumerate(text.splitlines(), start=1):
        if not raw.strip():
            continue
        try:
            d = json.loads(raw)
        except json.JSONDecodeError as e:
            raise EpisodeError(f"{path}: line {n}: not valid JSON ({e.msg} at column {e.colno})") from None
        ep = validate_episode_dict(d, str(path), n)
        if ep.id in ids:
            raise EpisodeError(f"{path}: line {n}: duplicate episode id '{ep.id}' (also line {ids[ep.id]})")
        ids[ep.id] = n
        if by_name is not None:
            if ep.scene not in by_name:
                raise EpisodeError(f"{path}: line {n}: unknown scene '{ep.scene}' (scenes: {', '.join(sorted(by_name))})")
            sc = by_name[ep.scene]
            known = {o.id for o in sc.objects}
            for g in ep.goals:
                if g not in known or g in sc.absent:
                    gone = " (its change list removes it)" if g in sc.absent else ""
                    raise EpisodeError(f"{path}: line {n}: goal object '{g}' is not in scene '{ep.scene}'{gone}")
        out.append(ep)
    if not out:
        raise EpisodeError(f"{path}: no episodes in file")
    return out


def save_episodes(episodes: Iterable[Episode], path: str | Path) -> Path:
    return write_jsonl(path, (e.to_dict() for e in episodes))


def save_truth(pairs: Iterable[GeneratedEpisode], path: str | Path) -> Path:
    """Ground-truth chains as JSONL: {"id": ..., "chain": TaskChain.to_dict()}."""
    return write_jsonl(path, ({"id": p.episode.id, "chain": p.truth.to_dict()} for p in pairs))


def load_truth(path: str | Path) -> dict[str, TaskChain]:
    path = Path(path)
    out = {}
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as e:
        raise EpisodeError(f"{path}: cannot read file ({e})") from None
    for n, raw in enumerate(lines, start=1):
        if raw.strip():
            try:
                d = json.loads(raw)
                out[str(d["id"])] = TaskChain.from_dict(d["chain"])
            except (ValueError, KeyError, TypeError, UserError) as e:
                raise EpisodeError(f"{path}: line {n}: not a ground-truth chain record ({e})") from None
    return out


# ----------------------------------------------------------------------------------------------------
# Ground truth: which objects does a description pick out?


@dataclasses.dataclass(frozen=True)
class SceneFacts:
    """Host-side lookups over one scene for resolving descriptions."""

    scene: Scene
    near_distance: float
    location_radius: float
    room_type: dict  # room id -> type
    attrs: dict  # object id -> tuple of attribute phrases as the generator writes them
    by_head: dict = dataclasses.field(default_factory=dict)  # head word(s) -> objects it names
    simple: dict = dataclasses.field(default_factory=dict)  # object id -> head(+attribute) Targets fitting only it
    loose: dict = dataclasses.field(default_factory=dict)  # object id -> every head(+attribute) Target fitting it
    split: str = "seen"  # the sentence templates descriptions are written with (EpisodesConfig.split)

    @classmethod
    def build(cls, scene: Scene, cfg: EpisodesConfig) -> SceneFacts:
        syn, hyp = names_for({o.category for o in scene.objects})
        heads = {h for o in scene.objects for h in (o.category, *syn.get(o.category, ()))} | set(hyp)
        by_head = {h: tuple(o for o in scene.objects if head_matches(o, h)) for h in heads}
        facts = cls(scene, cfg.near_distance, cfg.location_radius, {r.id: r.type for r in scene.rooms},
                    {o.id: attribute_phrases(o) for o in scene.objects}, by_head, split=cfg.split)
        loose = {o.id: tuple(_simple_targets(facts, o, unique=False)) for o in scene.objects}
        simple = {
            o.id: tuple(t for t in loose[o.id] if [x.id for x in resolve_target(facts, t)] == [o.id])
            for o in scene.objects
        }
        return dataclasses.replace(facts, simple=simple, loose=loose)


def attribute_phrases(o: SceneObject) -> tuple[str, ...]:
    """The object's attributes as words a description can use ('gold-framed', 'king-size', 'oak')."""
    out = []
    for k, v in o.attributes:
        v = v.strip().lower()
        if k in ("pot", "door") or (k == "condition" and v == "fair") or not v:
            continue
        if k == "state":  # written after the noun ("the lamp that is switched on"): any words
            out.append(v)
            continue
        if k == "frame":
            v = FRAMES.get(v, f"{v}-framed")
        if k == "size" and v == "king":
            v = "king-size"
        words = v.split()
        if all(L.is_modifier(w, words[i + 1] if i + 1 < len(words) else None) for i, w in enumerate(words)):
            if v not in out:
                out.append(v)
    return tuple(out)


def category_matches(category: str, head: str, vocab: tuple[dict, dict] | None = None) -> bool:
    """A head noun names this category: the category itself, a synonym of it, or a hypernym of it
    (vocab: (synonyms, hypernyms), by default `names_for` the category)."""
    syn, hyp = vocab or names_for((category,))
    return head == category or head in syn.get(category, ()) or category in hyp.get(head, ())


def head_matches(o: SceneObject, head: str) -> bool:
    return category_matches(o.category, head)


def attrs_match(wanted: Sequence[str], has: Sequence[str]) -> bool:
    """Every word of the wanted attributes is a word of the object's attribute phrases: the parser splits
    'black metal shoe rack' into ('black', 'metal') while the generator writes the phrase 'black metal'."""
    have = {w for a in has for w in a.split()}
    return all(w in have for a in wanted for w in a.split())


def box_gap(a: SceneObject, b: SceneObject) -> float:
    """Horizontal distance between two objects' footprints (0 when they overlap)."""
    dx = max(0.0, abs(a.position[0] - b.position[0]) - (a.size[0] + b.size[0]) / 2)
    dy = max(0.0, abs(a.position[1] - b.position[1]) - (a.size[1] + b.size[1]) / 2)
    return math.hypot(dx, dy)


def is_on(o: SceneObject, a: SceneObject) -> bool:
    bottom, top = o.position[2] - o.size[2] / 2, a.position[2] + a.size[2] / 2
    return (abs(bottom - top) < 0.05 and abs(o.position[0] - a.position[0]) <= a.size[0] / 2 + 0.05
            and abs(o.position[1] - a.position[1]) <= a.size[1] / 2 + 0.05)


def relation_holds(rtype: str, o: SceneObject, a: SceneObject, near: float) -> bool:
    if o.id == a.id:
        return False
    if rtype in NEAR_TYPES:
        return o.room == a.room and box_gap(o, a) <= near
    if rtype == "on":
        return is_on(o, a)
    if rtype == "with":
        return is_on(a, o) or (o.room == a.room and box_gap(o, a) <= near)
    if rtype == "in_room_with":
        return o.room == a.room
    return False


def resolve_target(facts: SceneFacts, t: Target) -> list[SceneObject]:
    named = facts.by_head.get(t.head)
    if named is None:
        named = [o for o in facts.scene.objects if head_matches(o, t.head)]
    out = [o for o in named if attrs_match(t.attributes, facts.attrs[o.id])] if t.attributes else list(named)
    for r in t.relations:
        anchors = resolve_target(facts, r.anchor)
        out = [o for o in out if any(relation_holds(r.type, o, a, facts.near_distance) for a in anchors)]
    return out


def sensor_holds(c: SensorConstraint, value: float) -> bool:
    v = c.value
    return {"gt": value > v, "ge": value >= v, "lt": value < v, "le": value <= v,
            "approx": abs(value - v) <= APPROX_TOL[c.reading] + 1e-9}[c.comparator]


def resolve(facts: SceneFacts, sg: Subgoal) -> tuple[str, ...]:
    """Ids of every scene object the subgoal's description fits (ground truth)."""
    cands = resolve_target(facts, sg.target)
    if sg.room:
        cands = [o for o in cands if facts.room_type.get(o.room) == sg.room]
    if sg.location is not None:
        cands = [o for o in cands if math.dist(o.position[:2], (sg.location.x, sg.location.y)) <= facts.location_radius]
    for c in sg.sensors:
        if not c.is_superlative:
            cands = [o for o in cands if c.reading in o.readings and sensor_holds(c, o.readings[c.reading])]
    for c in sg.sensors:
        if c.is_superlative:
            have = [o for o in cands if c.reading in o.readings]
            if not have:
                return ()
            vals = [o.readings[c.reading] for o in have]
            best = max(vals) if c.comparator == "max" else min(vals)
            cands = [o for o, v in zip(have, vals) if v == best]
    return tuple(o.id for o in cands)


# ----------------------------------------------------------------------------------------------------
# Describing one object


def _target(head: str, attrs: tuple[str, ...] = (), relations: tuple[Relation, ...] = ()) -> Target:
    from ragnav_jax.language.phrasings import is_state

    return Target(" ".join((*(a for a in attrs if not is_state(a)), head)), head, attrs, relations)


def _expressible(head: str, attrs: tuple[str, ...]) -> bool:
    """The words read back as these attributes and this head (no head starting with an adjective); states
    are written after the noun and need no check."""
    from ragnav_jax.language.phrasings import is_state

    attrs = tuple(a for a in attrs if not is_state(a))
    words = " ".join((*attrs, head)).split()
    got_attrs, got_head = split_noun_phrase(words)
    return got_head == head and " ".join(got_attrs).split() == " ".join(attrs).split()


def _heads(o: SceneObject) -> list[str]:
    return [h for h in (o.category, *names_for((o.category,))[0].get(o.category, ())) if _expressible(h, ())]


def _attr_sets(facts: SceneFacts, o: SceneObject) -> list[tuple[str, ...]]:
    a = facts.attrs[o.id]
    return [()] + [(x,) for x in a] + [(x, y) for i, x in enumerate(a) for y in a[i + 1 :]]


def _simple_targets(facts: SceneFacts, o: SceneObject, unique: bool = True) -> list[Target]:
    """Head (+ attributes) descriptions of o, unique in the scene when `unique`."""
    out = []
    for h in _heads(o):
        for attrs in _attr_sets(facts, o):
            if not _expressible(h, attrs):
                continue
            t = _target(h, attrs)
            ids = [x.id for x in resolve_target(facts, t)]
            if not unique or ids == [o.id]:
                out.append(t)
    return out


def _room_ok(room_type: str) -> bool:
    return L.is_room_phrase(room_type.split())


def _pick(rng: np.random.Generator, items: Sequence):
    return items[int(rng.integers(len(items)))]


def _prefer_simple(rng, targets: list[Target], synonym_prob: float) -> Target:
    """Fewest attributes first; the category name unless a synonym is drawn."""
    fewest = min(len(t.attributes) for t in targets)
    pool = [t for t in targets if len(t.attributes) == fewest] if rng.uniform() < 0.75 else targets
    names = [t for t in pool if t.head == pool[0].head]
    syn = [t for t in pool if t not in names]
    if syn and rng.uniform() < synonym_prob:
        return _pick(rng, syn)
    return _pick(rng, names or pool)


def _anchor_options(facts: SceneFacts, o: SceneObject, cfg: EpisodesConfig, depth: int,
                    exclude: frozenset[str] = frozenset()) -> list[tuple[str, Target]]:
    """(relation type, anchor description) pairs that hold for o, anchors uniquely described.

    Anchors of o's own category ("the fridge near the fridge") and objects in `exclude` (the target of
    a nested description) are never used.
    """
    out = []
    for a in facts.scene.objects:
        if a.id == o.id or a.id in exclude or a.category == o.category or set(_heads(a)) & set(_heads(o)):
            continue
        types = [t for t in REL_TEXT if relation_holds(t, o, a, cfg.near_distance)]
        if not types:
            continue
        anchors = list(facts.simple[a.id])
        if not anchors and depth > 1:
            for rt2, t2 in _anchor_options(facts, a, cfg, depth - 1, exclude | {o.id}):
                if any(head_matches(o, h) for h in _heads(o) if h == t2.head):
                    continue
                if rt2 in ("with", "on", "near", "next_to"):
                    for h in _heads(a):
                        nested = _target(h, (), (Relation(rt2, t2),))
                        if [x.id for x in resolve_target(facts, nested)] == [a.id]:
                            anchors.append(nested)
        for t in types:
            if t == "in_room_with" and a.room != o.room:
                continue
            for anc in anchors[:3]:
                out.append((t, anc))
    return out


def describe_text(facts: SceneFacts, o: SceneObject, rng: np.random.Generator, cfg: EpisodesConfig) -> Subgoal | None:
    """A words-only description that fits o and nothing else in the scene, or None."""
    simple = list(facts.simple[o.id])
    room_type = facts.room_type[o.room]
    room_opts = []
    if _room_ok(room_type):
        for t in facts.loose[o.id]:
            sg = Subgoal(0, t, room=room_type)
            if resolve(facts, sg) == (o.id,):
                room_opts.append(sg)
    rel_opts = []
    want_rel = rng.uniform() < cfg.relation_prob
    if want_rel or not (simple or room_opts):
        for rtype, anc in _anchor_options(facts, o, cfg, depth=2):
            for h in _heads(o):
                for attrs in ((),) + tuple((a,) for a in facts.attrs[o.id][:1]):
                    if not _expressible(h, attrs):
                        continue
                    sg = Subgoal(0, _target(h, attrs, (Relation(rtype, anc),)))
                    if resolve(facts, sg) == (o.id,):
                        rel_opts.append(sg)
    if rel_opts and (want_rel or not (simple or room_opts)):
        nested = [s for s in rel_opts if s.target.relations[0].anchor.relations]
        return _pick(rng, nested if nested and rng.uniform() < 0.3 else rel_opts)
    if room_opts and (rng.uniform() < cfg.room_prob or not simple):
        return _pick(rng, room_opts)
    if simple:
        t = _prefer_simple(rng, simple, cfg.synonym_prob)
        if room_opts and _room_ok(room_type) and rng.uniform() < cfg.room_prob / 2:
            return Subgoal(0, t, room=room_type)  # redundant room: still unique
        return Subgoal(0, t)
    return None


def _hint_text(rng, x: str, y: str) -> str:
    return _pick(rng, (
        f"near ({x}, {y})", f"at ({x}, {y})", f"at about {x}, {y}", f"around x={x}, y={y}", f"at x = {x}, y = {y}",
        f"at coordinates ({x}, {y})", f"located at ({x}, {y})", f"close to the point ({x}, {y})", f"({x}, {y})",
    ))


def describe_location(facts: SceneFacts, o: SceneObject, rng, cfg: EpisodesConfig) -> tuple[Subgoal, str] | None:
    """The category name plus a coordinate hint, where the name alone has distractors."""
    heads = _heads(o)
    if not heads:
        return None
    head = heads[0] if len(heads) == 1 or rng.uniform() >= cfg.synonym_prob else _pick(rng, heads[1:])
    cands = resolve_target(facts, _target(head))
    if len(cands) < 2:
        return None
    for _ in range(6):
        jitter = rng.uniform(-0.3, 0.3, size=2)
        x, y = (round(float(o.position[k] + jitter[k]), 1) + 0.0 for k in range(2))
        if math.dist((x, y), o.position[:2]) > cfg.location_radius:
            continue
        if any(math.dist((x, y), c.position[:2]) <= cfg.location_margin for c in cands if c.id != o.id):
            continue
        xs, ys = (f"{v:.1f}" if rng.uniform() < 0.5 else f"{v:g}" for v in (x, y))
        sg = Subgoal(0, _target(head), location=Location(float(xs), float(ys)))
        if resolve(facts, sg) == (o.id,):
            return sg, _renderer(facts.split, "hint")(rng, xs, ys)
    return None


def _fmt_value(reading: str, v: float) -> str:
    if reading == "ndvi":
        return f"{v:.2f}".rstrip("0").rstrip(".") if v != 0 else "0"
    return f"{v:g}"


_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "hottest"),
    ("temperature_c", "min"): ("coldest", "coolest"),
    ("ndvi", "max"): ("healthiest", "greenest"),
    ("ndvi", "min"): ("least healthy",),
    ("humidity_pct", "max"): ("most humid", "dampest"),
    ("humidity_pct", "min"): ("driest", "least humid"),
}
_CMP_WORDS = {"gt": ("above", "over", "higher than", "more than", "greater than"),
              "lt": ("below", "under", "lower than", "less than"),
              "ge": ("at least",), "le": ("at most",), "approx": ("about", "around", "roughly", "approximately")}


def _unit_text(rng, reading: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        return _pick(rng, ((" degrees", "c"), (" °C", "c"), ("°C", "c"), (" degrees Celsius", "c")))
    if reading == "humidity_pct":
        return _pick(rng, (("%", "%"), (" percent", "%")))
    return "", ""


def render_sensor(rng, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix adjective or '', phrase after the noun or '', the constraint exactly as written)."""
    rd = c.reading
    if c.is_superlative:
        if rng.uniform() < 0.55:
            return _pick(rng, _SUPER_ADJ[(rd, c.comparator)]), "", c
        ext = "highest" if c.comparator == "max" else "lowest"
        name = READING_TEXT[rd]
        tail = _pick(rng, (f"with the {ext} {name}", f"with the {ext} {name} reading", f"whose {name} is {ext}"))
        return "", tail, c
    vtxt = _fmt_value(rd, c.value)
    value = float(vtxt)
    style = rng.uniform()
    cmp_word = _pick(rng, _CMP_WORDS[c.comparator])
    name = READING_TEXT[rd]
    if style < 0.45:  # reading named: "with an NDVI above 0.6", "whose temperature is about 60 degrees"
        unit, code = _unit_text(rng, rd) if rd != "temperature_c" or rng.uniform() < 0.8 else ("", "")
        art = {"NDVI": "an NDVI", "temperature": "a temperature", "humidity": "humidity"}[name]
        if c.comparator == "approx":
            lead = _pick(rng, (f"with {art} of {cmp_word}", f"whose {name} is {cmp_word}"))
        else:
            lead = _pick(rng, (f"with {art} {cmp_word}", f"whose {name} is {cmp_word}"))
        return "", f"{lead} {vtxt}{unit}", SensorConstraint(rd, c.comparator, value, code)
    if c.comparator in ("gt", "lt") and style < 0.6:  # comparative: "warmer than 50 degrees"
        adj = {("temperature_c", "gt"): ("warmer", "hotter"), ("temperature_c", "lt"): ("colder", "cooler"),
               ("ndvi", "gt"): ("healthier", "greener"), ("ndvi", "lt"): None,
               ("humidity_pct", "gt"): ("more humid",), ("humidity_pct", "lt"): ("drier", "less humid")}[(rd, c.comparator)]
        if adj:
            unit, code = _unit_text(rng, rd)
            return "", f"{_pick(rng, adj)} than {vtxt}{unit}", SensorConstraint(rd, c.comparator, value, code)
    if rd == "ndvi" and c.comparator not in ("gt", "lt"):  # a bare "about 0.7" reads badly: name it
        return "", f"with an NDVI of {cmp_word} {vtxt}", SensorConstraint(rd, c.comparator, value, "")
    # bare: "at about 60 degrees", "under 0.2"; temperatures and humidity carry a unit here
    unit, code = _unit_text(rng, rd)
    lead = _pick(rng, ("at ", "reading ", "")) if c.comparator == "approx" else _pick(rng, ("", "reading "))
    return "", f"{lead}{cmp_word} {vtxt}{unit}", SensorConstraint(rd, c.comparator, value, code)


def _nice_between(lo: float, hi: float, steps: Sequence[float]) -> float | None:
    """A round number in [lo, hi] (None if the interval is empty)."""
    if lo > hi:
        return None
    for s in steps:
        k = math.ceil(lo / s - 1e-9)
        v = k * s
        if v <= hi + 1e-9:
            mid = (lo + hi) / 2
            best = round(mid / s) * s
            v = best if lo - 1e-9 <= best <= hi + 1e-9 else v
            return round(v, 4)
    return None


_STEPS = {"temperature_c": (10.0, 5.0, 1.0), "ndvi": (0.1, 0.05), "humidity_pct": (10.0, 5.0, 1.0)}


def describe_sensor(facts: SceneFacts, o: SceneObject, rng, cfg: EpisodesConfig) -> tuple[Subgoal, str, str] | None:
    """A description told apart by a sensor reading: (subgoal, prefix adjective, phrase after the noun)."""
    readings = list(o.sensors)
    if not readings:
        return None
    options = []
    heads = _heads(o) + [h for h, cats in names_for((o.category,))[1].items() if o.category in cats]
    room_type = facts.room_type[o.room]
    for rd, val in readings:
        tol = APPROX_TOL[rd]
        for head in heads:
            for room in (None, room_type) if _room_ok(room_type) else (None,):
                base = Subgoal(0, _target(head), room=room)
                ids = resolve(facts, base)
                if len(ids) < 2 or o.id not in ids:
                    continue
                others = [facts.scene.object_by_id(i) for i in ids if i != o.id]
                if any(rd not in x.readings for x in others):
                    continue
                ov = [x.readings[rd] for x in others]
                if val - max(ov) >= tol:
                    options.append((base, SensorConstraint(rd, "max")))
                    t = _nice_between(max(ov) + tol / 2, val - tol / 2, _STEPS[rd])
                    if t is not None:
                        options.append((base, SensorConstraint(rd, _pick(rng, ("gt", "gt", "ge")), t)))
                if min(ov) - val >= tol:
                    options.append((base, SensorConstraint(rd, "min")))
                    t = _nice_between(val + tol / 2, min(ov) - tol / 2, _STEPS[rd])
                    if t is not None:
                        options.append((base, SensorConstraint(rd, _pick(rng, ("lt", "lt", "le")), t)))
                v = round(val) if rd != "ndvi" else round(val, 2)
                if all(abs(x - v) > 2 * tol for x in ov) and abs(val - v) <= tol:
                    options.append((base, SensorConstraint(rd, "approx", float(v))))
    rng.shuffle(options)
    for base, c in options:
        prefix, tail, written = _renderer(facts.split, "sensor")(rng, c)
        sg = dataclasses.replace(base, sensors=(written,))
        if resolve(facts, sg) == (o.id,):
            if prefix and not _expressible(base.target.head, ()):
                continue
            return sg, prefix, tail
    return None


# ----------------------------------------------------------------------------------------------------
# Rendering instructions


def render_goal(rng, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """'the warmest appliance in the kitchen next to the sink at (3.5, 2.0)' from a description."""

    from ragnav_jax.language.phrasings import is_state

    def state(t: Target) -> str:  # states read after the noun ("the lamp that is switched on")
        st = [a for a in t.attributes if is_state(a)]
        return (" that is " + " and ".join(st)) if st else ""

    def np_text(t: Target) -> str:
        s = "the " + t.phrase + state(t)
        for r in t.relations:
            s += f" {_pick(rng, REL_TEXT[r.type])} {np_text(r.anchor)}"
        return s

    t = sg.target
    head_np = "the " + (f"{prefix} " if prefix else "") + t.phrase + state(t)
    rel = "".join(f" {_pick(rng, REL_TEXT[r.type])} {np_text(r.anchor)}" for r in t.relations)
    room = f" in the {sg.room}" if sg.room else ""
    parts = head_np + (room + rel if rng.uniform() < 0.6 else rel + room)
    if hint:
        parts += " " + hint
    if tail:
        if tail.startswith(("about", "around", "roughly", "approximately")) and rng.uniform() < 0.4:
            parts += f", {tail},"
        else:
            parts += " " + tail
    return parts


VERBS = ("go to", "visit", "find", "check", "head over to", "walk to", "take me to", "navigate to", "head to",
         "make your way to", "go over to", "locate", "stop by", "inspect", "check on", "drive to", "get to",
         "approach", "swing by", "pay a visit to", "go and see", "bring me to")
POLITE = ("", "", "", "please ", "could you ", "i need you to ", "can you ", "i'd like you to ")


def _sentence(s: str) -> str:
    s = s.strip()
    s = s.replace(",,", ",").replace(", ,", ",").replace(",.", ".").replace(",?", "?").replace(", then", ", then")
    s = s.rstrip(",")
    question = s.lower().startswith(("could you", "can you"))
    if not s.endswith((".", "?", "!")):
        s += "?" if question else "."
    return s[0].upper() + s[1:]


def _clean(r: str) -> str:
    return r[:-1] if r.endswith(",") else r


def render_instruction(rng, res: list[str], order: str) -> str:
    v = lambda: _pick(rng, VERBS)  # noqa: E731
    p = _pick(rng, POLITE)
    n = len(res)
    if n == 1:
        return _sentence(f"{p}{v()} {_clean(res[0])}")
    if order == "free":
        last_sep = _pick(rng, (" and ", ", and "))
        lst = ", ".join(res[:-1]) + last_sep + _clean(res[-1])
        lst = lst.replace(",,", ",")
        k = int(rng.integers(10))
        if k == 7:
            s = f"{p}{v()} {lst}, whichever order is quickest"
        elif k == 8:
            s = f"{p}{v()} {lst}. I don't care about the order"
        elif k == 9:
            s = f"{p}{v()} {lst}, the order is up to you"
        elif k == 0:
            s = f"{p}{v()} {lst} in any order"
        elif k == 1:
            s = f"in any order, {v()} {lst}"
        elif k == 2:
            s = f"{p}{v()} {lst}, in whatever order is quickest"
        elif k == 3:
            s = f"{p}{v()} {lst} in the best order"
        elif k == 4:
            s = f"{v()} the following in any order: {lst}"
        elif k == 5:
            s = f"{p}{v()} {lst}; the order does not matter"
        else:
            s = f"{p}{v()} {lst} in no particular order"
        return _sentence(s)
    k = int(rng.integers(10))
    if k == 7:  # "X first, then Y"
        return _sentence(f"{p}{v()} {_clean(res[0])} first" + "".join(f", then {r}" for r in res[1:]))
    if k == 8:  # "Begin with X, then Y, and end at Z"
        mid = "".join(f", then {r}" for r in res[1:-1])
        return _sentence(f"begin with {res[0]}{mid}, and end at {res[-1]}")
    if k == 9:  # "After X, go to Y."
        parts = [_sentence(f"after {_pick(rng, ('visiting', 'checking', 'going to'))} {_clean(res[0])}, {v()} {_clean(res[1])}")]
        parts += [_sentence(f"{_pick(rng, ('then', 'after that', 'next'))} {v()} {_clean(r)}") for r in res[2:]]
        return " ".join(parts)
    then = lambda r: _pick(rng, (f"then {r}", f"then {v()} {r}", f"then {r}"))  # noqa: E731
    if k == 0:
        s = f"{p}{v()} {res[0]}" + "".join(f", {then(r)}" for r in res[1:])
    elif k == 1:
        mid = "".join(f", then {r}" for r in res[1:-1])
        s = f"first {v()} {res[0]}{mid}, {'and finally' if n > 2 else 'then'} {res[-1]}"
    elif k == 2:
        mid = "".join(f", continue to {r}" for r in res[1:-1])
        s = f"start at {res[0]}{mid}, and finish at {res[-1]}"
    elif k == 3:
        parts = [f"{p}{v()} {_clean(res[0])}"]
        for r in res[1:-1]:
            parts.append(_sentence(f"{_pick(rng, ('after that', 'next', 'then'))}, {v()} {_clean(r)}"))
        parts.append(_sentence(f"{_pick(rng, ('lastly', 'finally'))}, {v()} {_clean(res[-1])}"))
        return " ".join([_sentence(parts[0])] + parts[1:])
    elif k == 4:
        s = f"{p}{v()} {res[0]}" + "".join(f" and then {r}" for r in res[1:])
    elif k == 5:
        s = f"{p}{v()} {res[0]}" + "".join(f", followed by {r}" for r in res[1:])
    else:
        mid = "".join(f", next {v()} {r}" for r in res[1:-1])
        s = f"{p}{v()} {res[0]}{mid}, and lastly {res[-1]}"
    return _sentence(s)


# ----------------------------------------------------------------------------------------------------
# Episodes


# episodes.split -> (module of ragnav_jax.language, suffix of its four functions). The parser was developed
# against the unseen_dev sets in rounds 2 to 14 and 16, each first measured as the held-out set; unseen_dev11 (set N)
# was held out for round 13 and developed against in round 14; unseen_dev12 (set O) was written after round 14,
# measured fresh with parser rounds 14 and 15 and developed against in round 16; `unseen` (set P) was written
# before round 16 was measured, by an author who never read the parser.
UNSEEN_TEMPLATES = {"unseen_dev": ("phrasings", "unseen"), "unseen_dev2": ("phrasings_dev2", "dev2"),
                    "unseen_dev3": ("phrasings_dev3", "dev3"), "unseen_dev4": ("phrasings_dev4", "dev4"),
                    "unseen_dev5": ("phrasings_dev5", "dev5"), "unseen_dev6": ("phrasings_dev6", "dev6"),
                    "unseen_dev7": ("phrasings_dev7", "dev7"), "unseen_dev8": ("phrasings_dev8", "dev8"),
                    "unseen_dev9": ("phrasings_dev9", "dev9"), "unseen_dev10": ("phrasings_dev10", "dev10"),
                    "unseen_dev11": ("phrasings_dev11", "dev11"), "unseen_dev12": ("phrasings_dev12", "dev12"),
                    # written to teach the learned readers more authors (round 22); no rule was written on them
                    "unseen_train1": ("phrasings_train1", "train1"), "unseen_train2": ("phrasings_train2", "train2"),
                    "unseen_train3": ("phrasings_train3", "train3"), "unseen_train4": ("phrasings_train4", "train4"),
                    "unseen_q": ("phrasings_q", "q"), "unseen_r": ("phrasings_r", "r"),
                    "unseen_s": ("phrasings_s", "s"), "unseen_t": ("phrasings_t", "t"),
                    "unseen_u": ("phrasings_u", "u"), "unseen_v": ("phrasings_v", "v"),
                    "unseen_x": ("phrasings_x", "x"),
                    "unseen_y": ("phrasings_y", "y"),
                    "unseen_z": ("phrasings_z", "z"),
                    "unseen_w": ("phrasings_w", "w"),
                    "unseen_aa": ("phrasings_aa", "aa"),
                    "unseen_ab": ("phrasings_ab", "ab"),
                    "unseen_ac": ("phrasings_ac", "ac"),
                    "unseen_ad": ("phrasings_ad", "ad"),
                    "unseen_ae": ("phrasings_ae", "ae"),
                    "unseen_af": ("phrasings_af", "af"),
                    "unseen_ag": ("phrasings_ag", "ag"),
                    "unseen_ah": ("phrasings_ah", "ah"),
                    "unseen_ai": ("phrasings_ai", "ai"),
                    "unseen_aj": ("phrasings_aj", "aj"),
                    "unseen_ak": ("phrasings_ak", "ak"),
                    "unseen_al": ("phrasings_al", "al"),
                    "unseen_am": ("phrasings_am", "am"),
                    "unseen_an": ("phrasings_an", "an"),
                    "unseen_ao": ("phrasings_ao", "ao"),
                    "unseen_ap": ("phrasings_ap", "ap"),
                    "unseen_aq": ("phrasings_aq", "aq"),
                    "unseen_ar": ("phrasings_ar", "ar"),
                    "unseen_as": ("phrasings_as", "as"),
                    "unseen_at": ("phrasings_at", "at"),
                    "unseen_au": ("phrasings_au", "au"),
                    "unseen_av": ("phrasings_av", "av"),
                    "unseen": ("phrasings_heldout", "heldout")}


def _renderer(split: str, what: str):
    """The split's sentence template for a goal, sensor phrase, coordinate hint or whole instruction."""
    if split == "seen":
        return {"goal": render_goal, "sensor": render_sensor, "hint": _hint_text, "instruction": render_instruction}[what]
    module, sfx = UNSEEN_TEMPLATES[split]
    m = importlib.import_module(f"ragnav_jax.language.{module}")
    return getattr(m, {"goal": "render_goal_", "sensor": "render_sensor_", "hint": "hint_text_",
                       "instruction": "render_instruction_"}[what] + sfx)


def _rng(seed: int, scene_name: str, modality: str) -> np.random.Generator:
    return np.random.default_rng(np.random.SeedSequence([int(seed), zlib.crc32(scene_name.encode()),
                                                         MODALITIES.index(modality)]))


def _one_episode(facts: SceneFacts, modality: str, rng, cfg: EpisodesConfig):
    objs = list(facts.scene.objects)
    order_idx = rng.permutation(len(objs))
    n = int(rng.integers(cfg.min_goals, cfg.max_goals + 1))
    goals: list[tuple[SceneObject, Subgoal, str]] = []  # (object, description, rendered text)
    used: set[str] = set()
    if modality != "text":
        for k in order_idx:
            o = objs[k]
            if modality == "text+location":
                got = describe_location(facts, o, rng, cfg)
                if got:
                    sg, hint = got
                    goals.append((o, sg, _renderer(facts.split, "goal")(rng, sg, hint=hint)))
            else:
                got = describe_sensor(facts, o, rng, cfg)
                if got:
                    sg, prefix, tail = got
                    goals.append((o, sg, _renderer(facts.split, "goal")(rng, sg, prefix=prefix, tail=tail)))
            if goals:
                used.add(o.id)
                break
        if not goals:
            return None
    for k in order_idx:
        if len(goals) >= n:
            break
        o = objs[k]
        if o.id in used:
            continue
        got = None
        if modality == "text+location+sensor" and rng.uniform() < 0.25:
            loc = describe_location(facts, o, rng, cfg)
            if loc:
                got = (loc[0], _renderer(facts.split, "goal")(rng, loc[0], hint=loc[1]))
        if got is None:
            sg = describe_text(facts, o, rng, cfg)
            if sg is not None:
                got = (sg, _renderer(facts.split, "goal")(rng, sg))
        if got is not None:
            used.add(o.id)
            goals.append((o, *got))
    if not goals:
        return None
    # The disambiguating goal goes anywhere in the list.
    perm = rng.permutation(len(goals))
    goals = [goals[i] for i in perm]
    order = "strict" if len(goals) == 1 or rng.uniform() < cfg.strict_fraction else "free"
    instruction = _renderer(facts.split, "instruction")(rng, [g[2] for g in goals], order)
    subgoals = tuple(dataclasses.replace(sg, index=i, text=txt.strip(" ,")) for i, (_, sg, txt) in enumerate(goals))
    truth = TaskChain(instruction, subgoals, order, derive_dependencies(subgoals, order), parser="truth")
    return [o.id for o, _, _ in goals], modality, order, instruction, truth


def generate_scene_episodes(scene: Scene, cfg: EpisodesConfig, seed: int) -> list[GeneratedEpisode]:
    """The episodes of one scene: cfg.text / text_location / text_location_sensor of each modality."""
    facts = SceneFacts.build(scene, cfg)
    out: list[GeneratedEpisode] = []
    seen: set[str] = set()
    for modality, count in zip(MODALITIES, (cfg.text, cfg.text_location, cfg.text_location_sensor)):
        rng = _rng(seed, scene.name, modality)
        made, tries = 0, 0
        while made < count and tries < count * 8 + 10:
            tries += 1
            got = _one_episode(facts, modality, rng, cfg)
            if got is None:
                continue
            goal_ids, modality_, order, instruction, truth = got
            if instruction in seen:
                continue
            for sg, gid in zip(truth.subgoals, goal_ids):  # the generator's promise, checked every time
                if resolve(facts, sg) != (gid,):
                    raise RuntimeError(f"generator bug: '{sg.text}' does not identify {gid} in {scene.name}")
            seen.add(instruction)
            ep = Episode(f"{scene.name}-{MODALITY_TAGS[modality]}-{made:03d}", scene.name, instruction,
                         tuple(goal_ids), modality_, order)
            out.append(GeneratedEpisode(ep, truth))
            made += 1
    return out


def generate_episodes(scenes: Sequence[Scene], cfg: EpisodesConfig, seed: int, progress: bool = False) -> list[GeneratedEpisode]:
    """Episodes for every scene, deterministic in (scenes, cfg, seed)."""
    it = scenes
    if progress:
        from tqdm.auto import tqdm

        it = tqdm(scenes, desc="episodes", unit="scene")
    out = []
    for s in it:
        out += generate_scene_episodes(s, cfg, seed)
    return out


def episode_summary(pairs: Sequence[GeneratedEpisode]) -> list[dict]:
    """One row per (scene, modality): episodes, mean goals, strict share."""
    rows: dict[tuple[str, str], dict] = {}
    for p in pairs:
        e = p.episode
        r = rows.setdefault((e.scene, e.modality), {"scene": e.scene, "modality": e.modality, "episodes": 0,
                                                    "goals": 0, "strict": 0})
        r["episodes"] += 1
        r["goals"] += len(e.goals)
        r["strict"] += e.order == "strict"
    out = []
    for r in rows.values():
        out.append({"scene": r["scene"], "modality": r["modality"], "episodes": r["episodes"],
                    "mean_goals": round(r["goals"] / r["episodes"], 2),
                    "strict_share": round(r["strict"] / r["episodes"], 2)})
    return out
