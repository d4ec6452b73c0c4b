"""Open-vocabulary verification for the reflection: is a perceived object the subgoal's target?

    verifier = Verifier.build(embedder, cfg)                        # thresholds from data/fitted.json
    views = memory_views(verifier, bank, scenes)                     # scene name -> what its memory holds
    table = verdict_table(verifier, views, episodes, subgoals)        # [e][g] -> (O,) bool over scene objects

What the robot perceives of an object is what its captioner emits at close range (`looks` looks, each
a name and a description with seeded perception noise: `perceive`), its sensor readings, and positions
(its own, the coordinate hint's, and those of the anchors its memory recorded). A subgoal is checked
against that:

- name: the target's head noun against the object's names (what the robot calls it now, and every
  alias its memory learnt for it: `name_classes`). When the house's own vocabulary holds the head noun,
  only objects known by that word or a name the memory learnt it means pass ("chair" is not the office
  chair, "cot" is a crib where the memory once called one so); otherwise through the
  sentence encoder: the cosine must reach `tau_head` and lie within `head_margin` of the best match
  among the names recorded in the scene ("couch" finds the sofa, "appliance" the fridge, "aquarium"
  the fish tank);
- attributes and states: said in one of the looks (whole words; a hyphenated value such as
  "gold-framed" by its first part): at close range, an attribute nobody sees is not there;
- room: the rooms the forest's summariser labels with exactly the room phrase; for a room name no
  prototype knows, a choice among the rooms the phrase could tell apart (the object's own and those of
  the recorded objects that pass every other check): the object's room must fit the phrase through the
  encoder within `room_margin` of the best of them (`room_scores`), and within the looser `room_gate`
  of the best room of the house. "The lamp in the workshop" asks which lamp's room is the workshop,
  which is easier than which room of the house is; the gate keeps a lone lamp in the hall out;
- structured checks: coordinate hints, sensor thresholds and superlatives (ranked among the recorded
  instances that pass the same checks), relations by position against recorded anchors that pass the
  name and attribute checks (an anchor the memory never recorded leaves a relation unchecked);
- a goal measured by a sensor, under a head noun the house never uses, that no recorded object passes:
  the name is checked among the objects that pass everything else, where the best-named pass, and a
  superlative ranks them all; where some object passes, a superlative ranks every object whose name fits
  within `head_margin` of the best-named of those, with no absolute bar. The reading singles the object out
  where the encoder does not know that a soldering station is a tool or a chest freezer an appliance.

RAGNav's pre-check (`contradicts`) reads the memory's own, distant descriptions instead, where
attributes are often left unsaid: there an attribute rules an instance out only when another value of
its kind is said (cosine >= `tau_kind` to a descriptor: "walnut" against a wanted "oak").

Nothing here reads a ground-truth category or attribute: only the captioner's words. The thresholds are
fitted on the seen split only (`fit_verifier`, `ragnav fit-verifier`) and kept, with where they came
from, in ragnav_jax/data/fitted.json (`load_fitted`).
"""

from __future__ import annotations

import dataclasses
import functools
import json
import math
import re
import zlib
from collections import Counter
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from ragnav_jax.errors import UserError
from ragnav_jax.language.episodes import relation_holds, sensor_holds
from ragnav_jax.language.lexicon import GENERIC_HEADS, SAME_STATES
from ragnav_jax.language.types import Subgoal, Target
from ragnav_jax.memory.captioner import CaptionNoise, canonical, describe_object, find_words
from ragnav_jax.memory.names import alias_sets, name_classes
from ragnav_jax.world.scene import Scene, SceneObject

FITTED_PATH = Path(__file__).resolve().parent.parent / "data" / "fitted.json"
FITTED_FORMAT = "ragnav-fitted/1"
_STOP = frozenset("a an the in with at about of and that is which its it's a's has having reading".split())
_CUT = re.compile(r",|;|\(|\)|\b(?:in|with|at|that|which|whose|reading)\b")
_NUMBER = re.compile(r"^[-+]?\d*[.,]?\d+$|^[°%]|^°c$|^ndvi$|^humidity$|^%$")


@dataclasses.dataclass(frozen=True)
class VerifierParams:
    """Thresholds of the check (fitted on the seen split, see module docstring)."""

    tau_head: float = 0.5
    head_margin: float = 0.1
    tau_kind: float = 0.5
    room_margin: float = 0.05
    room_gate: float = 0.1  # an unknown room name's room also fits within this of the house-wide best
    tau_ground: float = 0.5  # a run of instruction words names a recorded object (grounding.py)
    tau_bare: float = 0.0  # a goal with nothing but its name names a recorded object (grounding.py; 0: always)


def load_fitted(embedder_name: str, path: str | Path | None = None) -> VerifierParams:
    """The verifier thresholds fitted for an embedder (`minilm` | `hashing`) from a fitted.json."""
    path = Path(path) if path else FITTED_PATH
    try:
        d = json.loads(path.read_text())
    except (OSError, ValueError) as e:
        raise UserError(f"{path}: cannot read fitted values ({e})") from None
    if d.get("format") != FITTED_FORMAT:
        raise UserError(f"{path}: not a {FITTED_FORMAT} file (format: {d.get('format')!r})")
    entry = d.get("verifier", {}).get(embedder_name)
    if entry is None:
        raise UserError(f"{path}: verifier: no thresholds for embedder '{embedder_name}' (run ragnav fit-verifier)")
    names = [f.name for f in dataclasses.fields(VerifierParams)]
    params = entry.get("params") if isinstance(entry, dict) else None
    bad = [k for k in names if not isinstance(params, dict) or not isinstance(params.get(k), (int, float))]
    if bad:
        raise UserError(f"{path}: verifier.{embedder_name}.params.{bad[0]}: missing or not a number")
    return VerifierParams(**{k: float(params[k]) for k in names})


@functools.cache
def _summariser():
    from ragnav_jax.memory.summarise import Summariser

    return Summariser()


# ----------------------------------------------------------------------------------------------------
# Perception and reading descriptions


@dataclasses.dataclass(frozen=True)
class Perceived:
    """What the robot perceives of one object: the captioner's name and description of it."""

    name: str  # lower case ("couch")
    text: str  # the description, lower case, no article ("grey fabric couch, switched on")


def perceive(rng: np.random.Generator, o: SceneObject, noise: CaptionNoise) -> Perceived:
    """One close-range look at object o (no sensor text: readings come from the sensors)."""
    label, phrase = describe_object(rng, o, 99.0, noise)
    return Perceived(label.lower(), _strip_article(phrase.lower()))


def _strip_article(s: str) -> str:
    return re.sub(r"^(?:an?|the)\s+", "", s.strip())


def descriptors(p: Perceived) -> tuple[str, ...]:
    """The descriptive words of a description, each a word before the name or a chunk after it
    ('grey fabric sofa in a terracotta pot, switched on' -> ('grey', 'fabric', 'terracotta pot', 'switched on'))."""
    m = find_words(p.name, p.text)
    pre, post = (p.text[: m.start()], p.text[m.end():]) if m else ("", p.text)
    out = [w for w in pre.split() if w not in _STOP]
    for chunk in _CUT.split(post):
        words = [w for w in chunk.split() if w not in _STOP and not _NUMBER.match(w)]
        if words:
            out.append(" ".join(words))
    return tuple(dict.fromkeys(out))


def said(attr: str, text: str) -> bool:
    """The description states this attribute: as whole words, a hyphenated value by its first part, or a state
    by any phrase that says the same (`lexicon.SAME_STATES`: "running" is said by "switched on")."""
    return (any(find_words(a, text) for a in SAME_STATES.get(attr, (attr,)))
            or ("-" in attr and bool(find_words(attr.split("-")[0], text))))


def attributes_seen(t: Target, looks: Sequence[Sequence[Perceived]]) -> np.ndarray:
    """(len(looks),) bool: every attribute of t is said in one of each object's looks."""
    ok = np.ones(len(looks), bool)
    for a in t.attributes:
        ok &= np.array([any(said(a, p.text) for p in ls) for ls in looks], bool)
    return ok


# ----------------------------------------------------------------------------------------------------
# The check


class Verifier:
    """Name, attribute and room checks on encoder similarities, plus the structured checks."""

    def __init__(self, embedder, params: VerifierParams, near_distance: float, location_radius: float,
                 noise: CaptionNoise, seed: int, looks: int = 3):
        self.embedder, self.p, self.looks = embedder, params, looks
        self.near, self.radius, self.noise, self.seed = near_distance, location_radius, noise, seed
        self._vec: dict[str, np.ndarray] = {}
        # methods evaluated on the same memory share its views and their checks (`memory_views`, `verdict_table`)
        self._views: dict[tuple, tuple] = {}
        self._checks: dict[tuple, tuple] = {}

    @classmethod
    def build(cls, embedder, cfg, params: VerifierParams | None = None) -> Verifier:
        params = params or load_fitted(getattr(embedder, "name", cfg.memory.embedder), cfg.eval.verifier_file or None)
        noise = CaptionNoise(confusion=cfg.eval.verify_confusion, synonym=cfg.memory.caption_synonym,
                             attribute_keep=cfg.eval.verify_attribute_keep)
        return cls(embedder, params, cfg.episodes.near_distance, cfg.episodes.location_radius, noise, cfg.seed,
                   cfg.eval.verify_looks)

    # -- encoder similarities, cached per string
    def vectors(self, texts: Sequence[str]) -> np.ndarray:
        new = sorted({t for t in texts if t not in self._vec})
        if new:
            for t, v in zip(new, np.asarray(self.embedder.embed(new), np.float32)):
                self._vec[t] = v
        return np.stack([self._vec[t] for t in texts]) if texts else np.zeros((0, 1), np.float32)

    def cos(self, a: Sequence[str], b: Sequence[str]) -> np.ndarray:
        """(len(a), len(b)) cosine similarities (rows are unit vectors)."""
        if not len(a) or not len(b):
            return np.zeros((len(a), len(b)), np.float32)
        return self.vectors(list(a)) @ self.vectors(list(b)).T

    # -- the three encoder checks
    def names_match(self, head: str, names: Sequence[Sequence[str]], vocab: Sequence[str],
                    classes: dict | None = None) -> np.ndarray:
        """(len(names),) bool: the head noun names these objects, each known by a set of names (what the robot
        calls it now and what its memory called the same instance); vocab: every name recorded in the scene;
        classes: name -> the names the memory learnt mean the same (`name_classes`)."""
        heads = (classes or {}).get(head, {head})
        exact = np.array([bool(heads & set(ns)) for ns in names], bool)
        if head in GENERIC_HEADS and head not in vocab:  # "the hottest thing in the den": any object
            return np.ones(len(names), bool)
        if head in vocab:  # the house's own word for it (or a word its memory learnt means it): trust its naming
            return exact
        flat = sorted({n for ns in names for n in ns})
        if not flat:
            return exact
        c = dict(zip(flat, self.cos([head], flat)[0]))
        best = max(float(self.cos([head], list(vocab)).max()) if len(vocab) else -1.0, max(c.values()))
        score = np.array([max((c[n] for n in ns), default=-1.0) for ns in names])
        return exact | ((score >= self.p.tau_head) & (score >= best - self.p.head_margin))

    def contradicted(self, attr: str, p: Perceived) -> bool:
        """The description says another value of the attribute's kind and not the attribute."""
        if said(attr, p.text):
            return False
        ds = [d for d in descriptors(p) if d != attr]
        return bool(ds) and float(self.cos([attr], ds).max()) >= self.p.tau_kind

    def target_fits(self, t: Target, looks: Sequence[Sequence[Perceived]], vocab: Sequence[str],
                    aliases: Sequence[Sequence[str]] | None = None, classes: dict | None = None) -> np.ndarray:
        """(len(looks),) bool: name and attributes (no relations) of t fit each object's close-range looks;
        aliases: the names the memory recorded for each object; classes: as in `names_match`. At close range
        an attribute must be seen: said in one of the looks."""
        aliases = aliases if aliases is not None else [()] * len(looks)
        ok = self.names_match(t.head, [{p.name for p in ls} | set(a) for ls, a in zip(looks, aliases)], vocab, classes)
        return ok & attributes_seen(t, looks)

    def room_scores(self, room: str, names: dict[str, Sequence[str]],
                    known: Sequence[str] | None = None) -> dict[str, float]:
        """Room id -> how well the room phrase fits the names the memory recorded there: the mean of its three
        best names' distinctiveness, a name's cosine to the phrase less its mean cosine to the other room
        types the summariser knows (seen: a shelf unit is close to every room and tells none apart). Chosen on
        seen-split houses against the plain cosine and whole-description embeddings (the true room of a
        type among the rooms holding one category: 0.88 against 0.78 and 0.65). known: the room types to set
        the phrase against (default: those the summariser knows, less the phrase)."""
        known = list(known) if known is not None else sorted(set(_summariser().rooms) - {room})
        out = {}
        for r, ns in names.items():
            if ns:
                ns = list(ns)
                d = self.cos([room], ns)[0] - self.cos(known, ns).mean(0)
                out[r] = float(np.sort(d)[::-1][:3].mean())
        return out

    def rooms_match(self, room: str, view: SceneView, among: set[str] | None = None) -> set[str]:
        """Room ids the room phrase may mean: the rooms the forest's summariser labels with exactly that type
        when there are any (a house may have two bedrooms); otherwise, of the rooms `among` (default: all),
        those whose recorded names fit it within room_margin of the best of them and within room_gate of the
        best of all (`room_scores`), so room names no prototype knows work. Rooms with no recorded names are
        unknown and pass."""
        out = {r for r, ns in view.room_names.items() if not ns}
        labelled = {r for r, t in view.room_type.items() if t == room}
        if labelled:
            return out | labelled
        sc = self.room_scores(room, view.room_names)
        gate = max(sc.values(), default=0.0) - self.p.room_gate
        top = max((x for r, x in sc.items() if among is None or r in among), default=0.0)
        return out | {r for r, x in sc.items() if (among is None or r in among) and x >= max(top - self.p.room_margin, gate)}

    # -- the verdict table
    def scene_view(self, scene: Scene, known: Sequence[int], recorded_names: dict[int, Sequence[str]],
                   memory_scene: Scene | None = None, seen: Sequence[tuple[int, int]] = ()) -> SceneView:
        """What the robot's memory holds of a scene: recorded objects, their names, each room's names and type
        (the rooms of `memory_scene`, the scene as the memory saw it, where the world changed since), and when it
        saw each object (seen: (O,) (first, last) records, for time-indexed goals)."""
        room = [o.room for o in (memory_scene or scene).objects]
        vocab = vocabulary(recorded_names)
        classes, frequent = name_classes(recorded_names)
        aliases = alias_sets(recorded_names, classes, frequent)
        by_room: dict[str, list[str]] = {r.id: [] for r in scene.rooms}
        for oi, ns in recorded_names.items():
            for n in ns:
                if n.lower() not in by_room[room[oi]]:
                    by_room[room[oi]].append(n.lower())
        counts = {r: Counter(canonical(n) for o, ns in recorded_names.items() if room[o] == r for n in ns)
                  for r in by_room}
        types = {r: _summariser().infer_type(counts[r], 2)[0] for r, ns in by_room.items() if ns}
        return SceneView(scene, tuple(sorted(set(known))), tuple(vocab), {r: tuple(ns) for r, ns in by_room.items()},
                         types, aliases, classes, tuple(map(tuple, seen)))

    def perceptions_of(self, scene: Scene, key: str) -> list[tuple[Perceived, ...]]:
        """`looks` close-range perceptions of every scene object (the look-around on arrival sees it from
        several headings), seeded by (seed, key)."""
        rng = np.random.default_rng(np.random.SeedSequence([int(self.seed), zlib.crc32(key.encode())]))
        return [tuple(perceive(rng, o, self.noise) for _ in range(self.looks)) for o in scene.objects]

    def verdicts(self, view: SceneView, sg: Subgoal, ps: Sequence[Sequence[Perceived]],
                 names: Sequence[set[str]] | None = None) -> np.ndarray:
        """(O,) bool: each scene object, perceived as ps (its looks), passes the check for subgoal sg.

        A goal measured by a sensor whose head noun the house never uses ("the tool in the workshop at about
        167 degrees", where the encoder does not know a soldering station is a tool) and that no recorded
        object passes is checked by name among the objects that pass everything else: those whose names fit
        the head best pass (`best_named`); a superlative ranks all of them. A superlative under such a head
        that some object does pass ("the chilliest appliance in the pantry") ranks every object whose name fits
        the head within `head_margin` of the best-named of those, with no absolute bar: the head is often a
        word for a kind, and MiniLM puts "appliance" at 0.49 to "mini-fridge" but 0.31 to "chest freezer", so
        the bar would leave the freezer out and crown the coldest of what is left. names: each object's names
        (`SceneView.names_of`), where the caller has them already."""
        objs = view.scene.objects
        names = names if names is not None else [view.names_of(i, ps[i]) for i in range(len(objs))]
        named = self.target_fits(sg.target, ps, view.vocab, names, view.classes)
        ok = self._constrained(view, sg, ps, named)
        pool = list(view.known)
        if sg.sensors and sg.target.head not in view.vocab:
            seen = attributes_seen(sg.target, ps)
            superlative = any(c.is_superlative for c in sg.sensors)
            if superlative and ok[pool].any():
                fit = self._constrained(view, sg, ps, named, rank=False)
                seen_as = [ns | {p.name for p in looks} for ns, looks in zip(names, ps)]
                near = self.best_named(sg.target.head, seen_as, fit, np.flatnonzero(fit), self.p.head_margin)
                ok = self._constrained(view, sg, ps, seen & near)
            elif not ok[pool].any():
                rest = self._constrained(view, sg, ps, seen, rank=False)
                if not superlative:
                    rest &= self.best_named(sg.target.head, names, rest, pool)
                ok = self._constrained(view, sg, ps, rest)
        return ok

    def misfits(self, view: SceneView, sg: Subgoal, ps: Sequence[Sequence[Perceived]]) -> np.ndarray:
        """(O,) float: how many parts of subgoal sg each scene object fails, every attribute, relation, sensor
        constraint, coordinate hint and room checked alone with the name (`verdicts`); inf where the name does
        not fit (nor does a sensor part's, which may name by the best fit: `verdicts`). The reflection's
        fallback (`eval.fallback`) declares the object seen for a goal that fails fewest once every candidate
        is rejected: the one that fits the instruction best where no object fits all of it."""
        t = dataclasses.replace(sg.target, attributes=(), relations=())
        bare = dataclasses.replace(sg, target=t, room=None, location=None, sensors=())
        sensor = [dataclasses.replace(bare, sensors=(c,)) for c in sg.sensors]
        parts = sensor + [dataclasses.replace(bare, target=dataclasses.replace(t, attributes=(a,))) for a in sg.target.attributes]
        parts += [dataclasses.replace(bare, target=dataclasses.replace(t, relations=(r,))) for r in sg.target.relations]
        parts += [dataclasses.replace(bare, location=sg.location)] if sg.location is not None else []
        parts += [dataclasses.replace(bare, room=sg.room)] if sg.room is not None else []
        names = [view.names_of(i, ps[i]) for i in range(len(view.scene.objects))]
        ok = [self.verdicts(view, p, ps, names) for p in parts]
        named = np.logical_or.reduce([self.verdicts(view, bare, ps, names)] + ok[: len(sensor)])
        return np.where(named, sum((~k).astype(np.float32) for k in ok) if ok else 0.0, np.inf).astype(np.float32)

    def best_named(self, head: str, names: Sequence[set[str]], among: np.ndarray, pool: Sequence[int],
                   margin: float = 0.0) -> np.ndarray:
        """(O,) bool: objects whose best name fits the head at least as well, less margin, as that of every
        object of pool that is among ((O,) bool)."""
        flat = sorted({n for ns in names for n in ns})
        c = dict(zip(flat, self.cos([head], flat)[0])) if flat else {}
        score = np.array([max((c[n] for n in ns), default=-1.0) for ns in names])
        rivals = [i for i in pool if among[i]]
        return score >= (score[rivals].max() if rivals else -1.0) - margin - 1e-6

    def _constrained(self, view: SceneView, sg: Subgoal, ps: Sequence[Sequence[Perceived]], ok: np.ndarray,
                     rank: bool = True) -> np.ndarray:
        """(O,) bool: of the objects ok ((O,) bool: passing the name and attribute checks), those that pass
        the relation, coordinate, sensor and room checks and (rank) the superlatives."""
        objs = view.scene.objects
        O = len(objs)
        pool = list(view.known)
        ok = ok & self.relations_hold(sg.target, view, ps)
        if sg.location is not None:
            ok &= np.array([math.dist(o.position[:2], (sg.location.x, sg.location.y)) <= self.radius for o in objs])
        for c in sg.sensors:
            has = np.array([c.reading in o.readings for o in objs])
            ok &= has
            if not c.is_superlative:
                ok &= np.array([h and sensor_holds(c, o.readings[c.reading]) for h, o in zip(has, objs)])
        if sg.room is not None:  # a choice among the object's room and those of recorded objects that pass
            recorded = {objs[i].room for i in pool if ok[i]}
            ok &= np.array([bool(ok[i]) and o.room in self.rooms_match(sg.room, view, recorded | {o.room})
                            for i, o in enumerate(objs)])
        for c in sg.sensors:
            if rank and c.is_superlative:  # rank among the recorded instances passing the same checks (same room)
                rivals = [i for i in set(pool) | set(np.flatnonzero(ok).tolist()) if ok[i]]
                keep = np.zeros(O, bool)
                for i in np.flatnonzero(ok):
                    vals = [objs[j].readings[c.reading] for j in rivals
                            if sg.room is None or objs[j].room == objs[i].room]
                    v = objs[i].readings[c.reading]
                    keep[i] = v == (max(vals) if c.comparator == "max" else min(vals)) if vals else True
                ok &= keep
        if rank and sg.time is not None:  # "the mug you saw first": its place among the recorded ones passing too
            ok &= self._at_time(view, sg, ok)
        return ok

    @staticmethod
    def _at_time(view: SceneView, sg: Subgoal, ok: np.ndarray) -> np.ndarray:
        """(O,) bool: of the objects ok, those at sg.time's place (rank-th first or last seen by the memory's
        sighting log) among the recorded objects that pass the same checks, in the same room when sg names one.
        An object the memory never saw has no place."""
        objs = view.scene.objects
        when = {i: (t[0] if sg.time.order == "first" else -t[1]) for i, t in enumerate(view.seen) if t[0] >= 0}
        rivals = [i for i in view.known if ok[i] and i in when]
        keep = np.zeros(len(objs), bool)
        for i in np.flatnonzero(ok):
            if i in when:
                same = [j for j in rivals if sg.room is None or objs[j].room == objs[i].room]
                keep[i] = sum(when[j] < when[i] for j in same) == sg.time.rank - 1
        return keep

    def relations_hold(self, t: Target, view: SceneView, ps: Sequence[Sequence[Perceived]]) -> np.ndarray:
        """(O,) bool: t's relations hold for each scene object against anchors the memory recorded that fit
        the anchor's name, attributes and, in turn, its own relations ("the workbench with the toolbox near
        the tool chest"). An anchor the memory never recorded leaves its relation unchecked; nested
        relations that no recorded anchor meets are left unchecked likewise."""
        objs, pool = view.scene.objects, list(view.known)
        ok = np.ones(len(objs), bool)
        for r in t.relations:
            fit = self.target_fits(r.anchor, [ps[i] for i in pool], view.vocab, [view.names_of(i, ps[i]) for i in pool],
                                   view.classes)
            named = [i for i, f in zip(pool, fit) if f]
            if r.anchor.relations and named:
                nested = self.relations_hold(r.anchor, view, ps)
                named = [i for i in named if nested[i]] or named
            if named:
                ok &= np.array([any(relation_holds(r.type, o, objs[i], self.near) for i in named) for o in objs])
        return ok

    def contradicts(self, sg: Subgoal, names: Sequence[str], texts: Sequence[str], vocab: Sequence[str],
                    classes: dict | None = None) -> bool:
        """RAGNav's pre-check on what the memory recorded of an instance (its names and descriptions, seen from
        afar, where attributes are often left unsaid): every description names something else, or every
        one that names the target says another value of a wanted attribute (`contradicted`). classes: name
        -> its aliases (`name_classes`)."""
        if not len(names):
            return False
        ps = [Perceived(n.lower(), _strip_article(t.lower())) for n, t in zip(names, texts)]
        cls = classes or {}
        if not self.names_match(sg.target.head, [{y for p in ps for y in cls.get(p.name, {p.name})}], vocab, cls)[0]:
            return True  # no name the memory gave the instance (or its aliases) fits the target
        fit = self.names_match(sg.target.head, [cls.get(p.name, {p.name}) for p in ps], vocab, cls)
        return any(all(self.contradicted(a, p) for p, f in zip(ps, fit) if f) for a in sg.target.attributes)


@dataclasses.dataclass(frozen=True)
class SceneView:
    scene: Scene
    known: tuple[int, ...]  # scene objects the memory recorded
    vocab: tuple[str, ...]  # every name the memory's captions used
    room_names: dict  # room id -> the names the memory recorded there (empty when none)
    room_type: dict  # room id -> the type the forest's summariser infers from them (rooms with names only)
    aliases: dict  # object index -> every name the memory recorded for it (lower case)
    classes: dict = dataclasses.field(default_factory=dict)  # name -> the names the memory learnt mean the same
    seen: tuple = ()  # (O,) (first, last) exploration record the memory saw each object, (-1, -1) never

    def names_of(self, i: int, looks: Sequence[Perceived]) -> set[str]:
        """Every name object i goes by: what its memory recorded and the learnt aliases of what it is called
        now (an object the memory never recorded is still a 'clothes dryer' where its 'tumble dryer' is one)."""
        return set(self.aliases.get(i, ())) | {y for p in looks for y in self.classes.get(p.name.lower(), ())}


def vocabulary(recorded_names: dict[int, Sequence[str]]) -> list[str]:
    """Every name the memory's captions used in a scene, lower case, sorted (`recorded`'s first part)."""
    return sorted({n.lower() for ns in recorded_names.values() for n in ns})


def recorded(meta, scene: Scene) -> tuple[dict[int, list[str]], dict[str, str]]:
    """From a scene's memory: the names its captions gave each recorded object, and each (article-free)
    caption phrase's name."""
    from ragnav_jax.retrieval.index import node_slots

    objs, phrases = node_slots(meta, scene)
    names: dict[int, list[str]] = {}
    name_of: dict[str, str] = {}
    for os_, ps, ls in zip(objs, phrases, meta.caption_labels):
        for oi, ph, lab in zip(os_, ps, ls):
            names.setdefault(int(oi), []).append(lab)
            name_of.setdefault(ph, lab)
    return names, name_of


def _node_times(obs: np.ndarray, mask: np.ndarray, record: np.ndarray, n_objects: int) -> tuple:
    """(O,) (first, last) records of the key poses that observed each object ((-1, -1) none): the sighting log of
    a bank built before memories kept one. obs: (N, K) observed objects; mask: (N,); record: (N,)."""
    out = [[-1, -1] for _ in range(n_objects)]
    for i in np.flatnonzero(mask):
        for o in obs[i][obs[i] >= 0]:
            t = out[int(o)]
            t[0] = int(record[i]) if t[0] < 0 else min(t[0], int(record[i]))
            t[1] = max(t[1], int(record[i]))
    return tuple(map(tuple, out))


def memory_views(verifier: Verifier, bank, scenes: Sequence[Scene], memory_scenes: Sequence[Scene] | None = None
                 ) -> dict[str, SceneView]:
    """Scene name -> what its memory holds (`Verifier.scene_view`), for the bank's scenes among `scenes`; kept on
    the verifier for the same bank and scene objects. memory_scenes: the scenes as the memory saw them, where the
    world (`scenes`, same object indices) changed since: the rooms it recorded objects in are theirs."""
    memory_scenes = memory_scenes or scenes
    key = (id(bank), *map(id, scenes), *map(id, memory_scenes))
    hit = verifier._views.get(key)
    if hit is not None and hit[0] is bank and all(a is b for a, b in zip(hit[1], (*scenes, *memory_scenes))):
        return hit[2]
    by_name = {s.name: s for s in scenes}
    before = {s.name: s for s in memory_scenes}
    obs = np.asarray(bank.memory.obs_object)
    mask = np.asarray(bank.memory.node_mask)
    rec = np.asarray(bank.memory.record)
    views = {}
    for b, meta in enumerate(bank.metas):
        if meta.scene in by_name:
            scene = by_name[meta.scene]
            known = sorted({int(x) for x in obs[b][mask[b]].ravel() if x >= 0})
            old = before.get(meta.scene, scene)
            seen = meta.object_seen or _node_times(obs[b], mask[b], rec[b], len(old.objects))
            views[meta.scene] = verifier.scene_view(scene, known, recorded(meta, old)[0], old, seen)
    verifier._views[key] = (bank, (*scenes, *memory_scenes), views)
    return views


def verdict_table(verifier: Verifier, views: dict[str, SceneView], episodes, subgoals,
                  graded: bool = False) -> list[list[np.ndarray]]:
    """[e][g] -> (O,) bool verdicts over the scene's objects for every parsed subgoal (empty list for an
    episode that did not parse); graded: (O,) float parts failed instead (`Verifier.misfits`). Perception
    noise is seeded by (cfg.seed, episode id). Each check is kept on the verifier: methods that read the same
    subgoals of an episode (RAGNav's ablations, the retrieval baselines) share it."""
    check = verifier.misfits if graded else verifier.verdicts
    out = []
    for ep, sgs in zip(episodes, subgoals):
        view, ps, row = views[ep.scene] if sgs else None, None, []
        for sg in sgs or ():
            key = (id(view), ep.id, sg, graded)
            hit = verifier._checks.get(key)
            if hit is None or hit[0] is not view:
                ps = verifier.perceptions_of(view.scene, ep.id) if ps is None else ps
                v = check(view, sg, ps)
                if view.scene.absent:  # objects that left the world pass nothing
                    gone = np.array([o.id in view.scene.absent for o in view.scene.objects])
                    v = np.where(gone, np.inf if graded else False, v).astype(v.dtype)
                hit = verifier._checks[key] = (view, v)
            row.append(hit[1])
        out.append(row)
    return out
