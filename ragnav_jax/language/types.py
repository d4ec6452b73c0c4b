"""TaskChain: the structured form of a multi-goal instruction (the paper's task sequence T = {t_1..t_n}).

A chain holds ordered subgoals and the dependencies between them, labelled as in the paper's
"Intelligent Task Decomposition": *spatial* (a subgoal is conditioned on an anchor, "A near B") and
*temporal* (an explicit visiting order, "first A, then B"). Every piece is a frozen dataclass with
`to_dict` / `from_dict`; `TASKCHAIN_SCHEMA` is the JSON schema of `TaskChain.to_dict()` and is what
LLM output is validated against before `from_dict` ever sees it.

JSON shape (format "ragnav-taskchain/1"):

    {"format": "ragnav-taskchain/1", "instruction": "...", "order": "strict" | "free",
     "parser": "rules" | "llm" | "truth",
     "subgoals": [{"index": 0, "text": "the sink next to the table",
                   "target": {"phrase": "steel sink", "head": "sink", "attributes": ["steel"],
                              "relations": [{"type": "next_to",
                                             "anchor": {"phrase": "table", "head": "table",
                                                        "attributes": [], "relations": []}}]},
                   "room": "kitchen" | null,
                   "location": {"x": 3.5, "y": 2.0} | null,
                   "sensors": [{"reading": "ndvi", "comparator": "gt", "value": 0.6, "unit": ""}]}],
     "dependencies": [{"type": "temporal", "subgoal": 1, "on": 0, "anchor": null, "relation": null},
                      {"type": "spatial", "subgoal": 0, "on": null, "anchor": "table", "relation": "next_to"}]}
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

from ragnav_jax.errors import UserError
from ragnav_jax.language.readings import READINGS as _READINGS

FORMAT = "ragnav-taskchain/1"

# Canonical relation types. Retrieval maps them to kernels: the proximity group to the Gaussian
# anchor kernel, "on"/"under"/"in" to a tight vertical/containment check, "in_room_with" to the room.
RELATION_TYPES = (
    "near",  # near, close to, around
    "next_to",  # next to, alongside
    "beside",
    "by",
    "on",  # on, on top of, sitting on
    "under",  # under, below, beneath
    "above",  # above, over (no number following)
    "in",  # in / inside a non-room container ("the book in the bookshelf")
    "with",  # "the table with the monitor": the anchor is on or next to the target
    "in_room_with",  # in the room with, in the same room as
    "in_front_of",
    "behind",
    "opposite",  # opposite, across from, facing
    "left_of",
    "right_of",
)
PROXIMITY_RELATIONS = ("near", "next_to", "beside", "by", "with", "in_front_of", "behind", "opposite", "left_of", "right_of")

# Sensor readings, named as the scene files name them.
READINGS = tuple(_READINGS)  # canonical sensor keys (language/readings.py)
# gt/lt/ge/le: thresholds; approx: "about 55 degrees"; max/min: superlatives ("warmest", "lowest NDVI").
COMPARATORS = ("lt", "le", "gt", "ge", "approx", "max", "min")
ORDERS = ("strict", "free")
DEPENDENCY_TYPES = ("spatial", "temporal")
PARSERS = ("rules", "llm", "truth")


class ParseError(UserError):
    """An instruction that cannot be turned into a TaskChain; the message says what was missing."""


def _finite(v: float) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


@dataclasses.dataclass(frozen=True)
class Target:
    """A noun phrase: the head noun (open vocabulary, may be several words) plus its modifiers.

    phrase: attributes and head as written ("grey fabric sofa"), lower case, no determiner.
    relations: spatial relations to anchors, each anchor itself a Target (so they nest).
    """

    phrase: str
    head: str
    attributes: tuple[str, ...] = ()
    relations: tuple[Relation, ...] = ()

    def to_dict(self) -> dict:
        return {
            "phrase": self.phrase,
            "head": self.head,
            "attributes": list(self.attributes),
            "relations": [r.to_dict() for r in self.relations],
        }

    @classmethod
    def from_dict(cls, d: dict) -> Target:
        return cls(
            phrase=str(d["phrase"]),
            head=str(d["head"]),
            attributes=tuple(str(a) for a in d.get("attributes", ())),
            relations=tuple(Relation.from_dict(r) for r in d.get("relations", ())),
        )


@dataclasses.dataclass(frozen=True)
class Relation:
    """A spatial relation of the enclosing target to an anchor: type in RELATION_TYPES."""

    type: str
    anchor: Target

    def to_dict(self) -> dict:
        return {"type": self.type, "anchor": self.anchor.to_dict()}

    @classmethod
    def from_dict(cls, d: dict) -> Relation:
        return cls(type=str(d["type"]), anchor=Target.from_dict(d["anchor"]))


@dataclasses.dataclass(frozen=True)
class Location:
    """A coordinate hint in the scene frame (metres)."""

    x: float
    y: float

    def to_dict(self) -> dict:
        return {"x": self.x, "y": self.y}

    @classmethod
    def from_dict(cls, d: dict) -> Location:
        return cls(float(d["x"]), float(d["y"]))


@dataclasses.dataclass(frozen=True)
class SensorConstraint:
    """A condition on a sensor reading.

    reading: one of READINGS (canonical sensor keys, language/readings.py). comparator: one of COMPARATORS.
    value: the threshold / target in the reading's canonical unit (degrees Celsius, NDVI, percent, ppm, dB,
    lux, W, kg, hPa); None for superlatives (max, min). unit: the unit as written ("c", "f", "%", "ppm", "kw",
    ..., "" when none was written).
    """

    reading: str
    comparator: str
    value: float | None = None
    unit: str = ""

    @property
    def is_superlative(self) -> bool:
        return self.comparator in ("max", "min")

    def to_dict(self) -> dict:
        return {"reading": self.reading, "comparator": self.comparator, "value": self.value, "unit": self.unit}

    @classmethod
    def from_dict(cls, d: dict) -> SensorConstraint:
        v = d.get("value")
        return cls(str(d["reading"]), str(d["comparator"]), None if v is None else float(v), str(d.get("unit", "")))


TIME_ORDERS = ("first", "last")
MAX_TIME_RANK = 9


@dataclasses.dataclass(frozen=True)
class TimeConstraint:
    """When the robot saw the target, among the objects of its kind (a time-indexed query).

    order "first", rank 1: the one it saw earliest ("the mug I saw first", "where the chair was before it moved");
    rank 2: the second it came across. order "last", rank 1: the one it saw most recently; rank 2: the one
    before that. Retrieval ranks the matching instances by the memory's timestamps (`kernels.time_term`).
    """

    order: str
    rank: int = 1

    def to_dict(self) -> dict:
        return {"order": self.order, "rank": self.rank}

    @classmethod
    def from_dict(cls, d: dict) -> TimeConstraint:
        return cls(str(d["order"]), int(d.get("rank", 1)))


@dataclasses.dataclass(frozen=True)
class Subgoal:
    """One goal of the chain: what to reach and every constraint the instruction puts on it.

    index: position in the instruction (0-based). text: the span of the instruction it came from.
    room: a room constraint as written ("kitchen", "living room"), or None.
    time: when the robot saw it (TimeConstraint), or None; `to_dict` writes the key only when set.
    """

    index: int
    target: Target
    room: str | None = None
    location: Location | None = None
    sensors: tuple[SensorConstraint, ...] = ()
    text: str = ""
    time: TimeConstraint | None = None

    def to_dict(self) -> dict:
        d = {
            "index": self.index,
            "text": self.text,
            "target": self.target.to_dict(),
            "room": self.room,
            "location": None if self.location is None else self.location.to_dict(),
            "sensors": [s.to_dict() for s in self.sensors],
        }
        if self.time is not None:
            d["time"] = self.time.to_dict()
        return d

    @classmethod
    def from_dict(cls, d: dict) -> Subgoal:
        loc = d.get("location")
        return cls(
            index=int(d["index"]),
            target=Target.from_dict(d["target"]),
            room=d.get("room") or None,
            location=None if loc is None else Location.from_dict(loc),
            sensors=tuple(SensorConstraint.from_dict(s) for s in d.get("sensors", ())),
            text=str(d.get("text", "")),
            time=None if d.get("time") is None else TimeConstraint.from_dict(d["time"]),
        )


@dataclasses.dataclass(frozen=True)
class Dependency:
    """An edge of the chain.

    temporal: subgoal `subgoal` comes after subgoal `on` (strict order).
    spatial: subgoal `subgoal` is conditioned on an anchor ("A near B": A depends on B); `anchor` is
    the anchor's phrase, `relation` its type, and `on` the index of the subgoal whose target the
    anchor is, when it is one (else None).
    """

    type: str
    subgoal: int
    on: int | None = None
    anchor: str | None = None
    relation: str | None = None

    def to_dict(self) -> dict:
        return {"type": self.type, "subgoal": self.subgoal, "on": self.on, "anchor": self.anchor,
                "relation": self.relation}

    @classmethod
    def from_dict(cls, d: dict) -> Dependency:
        on = d.get("on")
        return cls(str(d["type"]), int(d["subgoal"]), None if on is None else int(on), d.get("anchor"),
                   d.get("relation"))


@dataclasses.dataclass(frozen=True)
class TaskChain:
    """An instruction decomposed into ordered subgoals plus spatial and temporal dependencies."""

    instruction: str
    subgoals: tuple[Subgoal, ...]
    order: str = "strict"
    dependencies: tuple[Dependency, ...] = ()
    parser: str = "rules"

    def to_dict(self) -> dict:
        return {
            "format": FORMAT,
            "instruction": self.instruction,
            "order": self.order,
            "parser": self.parser,
            "subgoals": [s.to_dict() for s in self.subgoals],
            "dependencies": [d.to_dict() for d in self.dependencies],
        }

    @classmethod
    def from_dict(cls, d: dict, validate: bool = True) -> TaskChain:
        """Builds a chain from plain data; with validate, checks the schema first (raises ParseError)."""
        if validate:
            validate_chain_dict(d)
        subgoals = tuple(Subgoal.from_dict(s) for s in d["subgoals"])
        deps = d.get("dependencies")
        chain = cls(
            instruction=str(d.get("instruction", "")),
            subgoals=subgoals,
            order=str(d.get("order", "strict")),
            dependencies=tuple(Dependency.from_dict(x) for x in deps) if deps is not None else (),
            parser=str(d.get("parser", "rules")),
        )
        if deps is None:
            chain = dataclasses.replace(chain, dependencies=derive_dependencies(chain.subgoals, chain.order))
        return chain

    def describe(self) -> str:
        """Readable multi-line text of the chain (what `ragnav parse` prints)."""
        lines = [f"instruction: {self.instruction}", f"order: {self.order} ({len(self.subgoals)} subgoal(s), parser: {self.parser})"]
        for s in self.subgoals:
            lines.append(f"  {s.index + 1}. {describe_target(s.target)}")
            if s.room:
                lines.append(f"       room: {s.room}")
            if s.location is not None:
                lines.append(f"       location hint: ({s.location.x:g}, {s.location.y:g})")
            for c in s.sensors:
                lines.append(f"       sensor: {describe_sensor(c)}")
        for d in self.dependencies:
            if d.type == "temporal":
                lines.append(f"  temporal: {d.subgoal + 1} after {d.on + 1}")
            else:
                tail = f" (subgoal {d.on + 1})" if d.on is not None else ""
                lines.append(f"  spatial: {d.subgoal + 1} {d.relation} '{d.anchor}'{tail}")
        return "\n".join(lines)


def describe_target(t: Target) -> str:
    attrs = f" [attributes: {', '.join(t.attributes)}]" if t.attributes else ""
    out = f"'{t.phrase}' (head '{t.head}'){attrs}"
    for r in t.relations:
        out += f" {r.type} {describe_target(r.anchor)}"
    return out


_CMP_TEXT = {"lt": "<", "le": "<=", "gt": ">", "ge": ">=", "approx": "~"}


def describe_sensor(c: SensorConstraint) -> str:
    if c.comparator == "max":
        return f"highest {c.reading}"
    if c.comparator == "min":
        return f"lowest {c.reading}"
    return f"{c.reading} {_CMP_TEXT.get(c.comparator, c.comparator)} {c.value:g}"


def derive_dependencies(subgoals: tuple[Subgoal, ...], order: str) -> tuple[Dependency, ...]:
    """Temporal edges between consecutive subgoals for a strict order; a spatial edge per relation.

    A relation's anchor is linked to an earlier or later subgoal (`on`) when the anchor's head
    equals that subgoal's head; pronoun anchors ("it") are resolved by the parser before this.
    """
    deps: list[Dependency] = []
    if order == "strict":
        deps += [Dependency("temporal", i, i - 1) for i in range(1, len(subgoals))]
    for s in subgoals:
        for r in s.target.relations:
            on = None
            for o in subgoals:
                if o.index != s.index and o.target.head == r.anchor.head and o.target.phrase == r.anchor.phrase:
                    on = o.index
                    break
            deps.append(Dependency("spatial", s.index, on, r.anchor.phrase, r.type))
    return tuple(deps)


# ----------------------------------------------------------------------------------------------------
# JSON schema (draft 2020-12) of TaskChain.to_dict(); "$defs/target" recurses for nested anchors.

_STR = {"type": "string"}
TASKCHAIN_SCHEMA: dict[str, Any] = {
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "$id": "ragnav/taskchain.schema.json",
    "title": "RAGNav task chain",
    "type": "object",
    "required": ["subgoals"],
    "additionalProperties": False,
    "properties": {
        "format": {"const": FORMAT},
        "instruction": _STR,
        "order": {"enum": list(ORDERS)},
        "parser": {"enum": list(PARSERS)},
        "subgoals": {"type": "array", "minItems": 1, "maxItems": 64, "items": {"$ref": "#/$defs/subgoal"}},
        "dependencies": {"type": "array", "items": {"$ref": "#/$defs/dependency"}},
    },
    "$defs": {
        "target": {
            "type": "object",
            "required": ["phrase", "head"],
            "additionalProperties": False,
            "properties": {
                "phrase": {"type": "string", "minLength": 1, "maxLength": 200},
                "head": {"type": "string", "minLength": 1, "maxLength": 100},
                "attributes": {"type": "array", "items": {"type": "string", "minLength": 1, "maxLength": 60}},
                "relations": {"type": "array", "items": {"$ref": "#/$defs/relation"}},
            },
        },
        "relation": {
            "type": "object",
            "required": ["type", "anchor"],
            "additionalProperties": False,
            "properties": {"type": {"enum": list(RELATION_TYPES)}, "anchor": {"$ref": "#/$defs/target"}},
        },
        "location": {
            "type": "object",
            "required": ["x", "y"],
            "additionalProperties": False,
            "properties": {"x": {"type": "number"}, "y": {"type": "number"}},
        },
        "sensor": {
            "type": "object",
            "required": ["reading", "comparator"],
            "additionalProperties": False,
            "properties": {
                "reading": {"enum": list(READINGS)},
                "comparator": {"enum": list(COMPARATORS)},
                "value": {"type": ["number", "null"]},
                "unit": _STR,
            },
        },
        "subgoal": {
            "type": "object",
            "required": ["index", "target"],
            "additionalProperties": False,
            "properties": {
                "index": {"type": "integer", "minimum": 0},
                "text": _STR,
                "target": {"$ref": "#/$defs/target"},
                "room": {"type": ["string", "null"]},
                "location": {"anyOf": [{"$ref": "#/$defs/location"}, {"type": "null"}]},
                "sensors": {"type": "array", "items": {"$ref": "#/$defs/sensor"}},
                "time": {"anyOf": [{"$ref": "#/$defs/time"}, {"type": "null"}]},
            },
        },
        "time": {
            "type": "object",
            "required": ["order"],
            "additionalProperties": False,
            "properties": {"order": {"enum": list(TIME_ORDERS)},
                           "rank": {"type": "integer", "minimum": 1, "maximum": MAX_TIME_RANK}},
        },
        "dependency": {
            "type": "object",
            "required": ["type", "subgoal"],
            "additionalProperties": False,
            "properties": {
                "type": {"enum": list(DEPENDENCY_TYPES)},
                "subgoal": {"type": "integer", "minimum": 0},
                "on": {"type": ["integer", "null"], "minimum": 0},
                "anchor": {"type": ["string", "null"]},
                "relation": {"anyOf": [{"enum": list(RELATION_TYPES)}, {"type": "null"}]},
            },
        },
    },
}


def validate_chain_dict(d: Any) -> None:
    """Checks plain data against TASKCHAIN_SCHEMA plus what a schema cannot say; raises ParseError."""
    import jsonschema

    validator = jsonschema.Draft202012Validator(TASKCHAIN_SCHEMA)
    errors = list(validator.iter_errors(d))
    if errors:
        err = jsonschema.exceptions.best_match(errors)
        where = "$" + "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in err.absolute_path)
        raise ParseError(f"task chain does not match the schema at {where}: {err.message[:200]}")
    n = len(d["subgoals"])
    for i, s in enumerate(d["subgoals"]):
        if s["index"] != i:
            raise ParseError(f"task chain: subgoal {i} has index {s['index']} (indices must be 0..n-1 in order)")
        loc = s.get("location")
        if loc is not None and not (_finite(loc["x"]) and _finite(loc["y"])):
            raise ParseError(f"task chain: subgoal {i} has a non-finite location")
        for c in s.get("sensors", ()):
            sup = c["comparator"] in ("max", "min")
            v = c.get("value")
            if sup != (v is None) or (v is not None and not _finite(v)):
                raise ParseError(f"task chain: subgoal {i}: comparator '{c['comparator']}' needs "
                                 + ("no value" if sup else "a finite value"))
    for d_ in d.get("dependencies", ()) or ():
        for k in ("subgoal", "on"):
            v = d_.get(k)
            if v is not None and v >= n:
                raise ParseError(f"task chain: dependency refers to subgoal {v}, but there are only {n}")
