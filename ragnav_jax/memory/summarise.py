"""Labels and summaries of the semantic forest's parents.

Default: a deterministic summariser that reads only what the captioner wrote (the surface labels of the
member nodes' captions), maps synonyms to categories, and infers a functional area (level 1) or room type
(higher levels) by TF-IDF cosine similarity to prototypes (e.g. coffee machine + sink -> "breakfast nook").
Optional: the OpenAI-compatible endpoint of the `llm` section (`memory.summariser=llm`), falling back to
the template on any failure.
"""

from __future__ import annotations

import math
from collections import Counter

import numpy as np

from ragnav_jax.memory.captioner import canonical
from ragnav_jax.world.vocabulary import ROOM_GROUPS

FUNCTIONAL_AREAS: dict[str, tuple[str, ...]] = {
    "breakfast nook": ("coffee machine", "sink", "kettle", "kitchen table", "chair"),
    "cooking area": ("stove", "kettle", "microwave", "fridge", "dishwasher"),
    "entertainment area": ("sofa", "television", "tv stand", "remote control", "coffee table", "rug"),
    "reading corner": ("armchair", "floor lamp", "bookshelf"),
    "fireplace corner": ("fireplace", "armchair", "rug"),
    "music corner": ("piano",),
    "sleeping area": ("bed", "nightstand", "table lamp"),
    "dressing area": ("wardrobe", "dresser", "mirror", "laundry basket"),
    "workstation": ("desk", "office chair", "computer monitor", "desk lamp"),
    "records area": ("filing cabinet", "printer", "bookshelf"),
    "meeting area": ("meeting table", "chair", "whiteboard"),
    "dining area": ("dining table", "chair", "sideboard", "display cabinet", "wine rack"),
    "laundry corner": ("washing machine", "laundry basket"),
    "washing area": ("sink", "toilet", "mirror", "bathroom cabinet"),
    "bathing area": ("bathtub", "shower", "towel radiator"),
    "entrance": ("coat rack", "shoe rack", "umbrella stand", "bench", "console table"),
    "cardio area": ("treadmill", "exercise bike", "rowing machine", "fan"),
    "strength area": ("dumbbell rack", "weight bench", "punching bag", "yoga mat"),
    "plant corner": ("potted plant", "fern", "orchid", "cactus", "lemon tree"),
    "potting station": ("potting bench", "seedling tray", "watering can", "planter box", "tomato plant"),
}


def room_prototypes() -> dict[str, dict[str, float]]:
    """Room type -> category weights from the vocabulary's groups (anchors by weight, companions by weight x p)."""
    out = {}
    for room, groups in ROOM_GROUPS.items():
        w: Counter = Counter()
        for g in groups:
            w[g.anchor] += g.weight
            for cat, _, p in g.companions:
                w[cat] += g.weight * p
        out[room] = dict(w)
    return out


class Summariser:
    """Deterministic template summariser with TF-IDF prototype matching."""

    def __init__(self):
        self.rooms = room_prototypes()
        self.areas = {k: {c: 1.0 for c in v} for k, v in FUNCTIONAL_AREAS.items()}
        protos = [*self.rooms.values(), *self.areas.values()]
        df = Counter(c for p in protos for c in p)
        self.idf = {c: math.log((1 + len(protos)) / (1 + k)) + 1.0 for c, k in df.items()}

    def _vec(self, weights: dict[str, float]) -> dict[str, float]:
        v = {c: w * self.idf.get(c, math.log(1 + len(self.rooms) + len(self.areas)) + 1.0) for c, w in weights.items()}
        n = math.sqrt(sum(x * x for x in v.values())) or 1.0
        return {c: x / n for c, x in v.items()}

    def infer_type(self, counts: Counter, level: int) -> tuple[str, float]:
        """Best prototype (functional areas and rooms at level 1, rooms above) and its cosine score."""
        if not counts:
            return "passage", 0.0
        q = self._vec(dict(counts))
        cands = dict(self.rooms)
        if level <= 1:
            cands.update(self.areas)
        best, score = "open area", 0.0
        for name, proto in sorted(cands.items()):
            p = self._vec(proto)
            s = sum(q[c] * p.get(c, 0.0) for c in q)
            if s > score + 1e-12:
                best, score = name, s
        return (best if score >= 0.15 else "open area"), score

    def summarise(self, level: int, labels: list[tuple[str, ...]], position: np.ndarray, sensors: dict[str, float],
                  child_labels: list[str]) -> tuple[str, str]:
        """(label, summary) of a parent from its member nodes' caption labels."""
        counts: Counter = Counter(canonical(x) for ls in labels for x in ls)
        kind, _ = self.infer_type(counts, level)
        top = [c for c, _ in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))[:4]]
        label = f"{kind}: {', '.join(top[:3])}" if top else kind
        parts = [f"Likely a {kind} around ({position[0]:.1f}, {position[1]:.1f})"]
        if top:
            parts.append("with " + ", ".join(top))
        if sensors:
            parts.append("readings " + ", ".join(f"{k} {v:.2f}".rstrip("0").rstrip(".") for k, v in sorted(sensors.items())))
        summary = "; ".join(parts) + f"; {len(labels)} views"
        if child_labels:
            summary += "; parts: " + ", ".join(sorted(set(cl.split(":")[0] for cl in child_labels)))
        return label, summary + "."


def leaf_label(labels: tuple[str, ...]) -> str:
    return ", ".join(dict.fromkeys(canonical(x) for x in labels[:3])) or "empty view"


def llm_summary(llm_cfg, level: int, captions: list[str], fallback: tuple[str, str]) -> tuple[str, str]:
    """Label and summary from the LLM endpoint (first line label, rest summary); the template on failure."""
    from ragnav_jax.memory.llm import LLMError, chat

    prompt = (
        "These are descriptions of views a robot recorded in one area of a home. Reply with a short label for the "
        "area (at most four words, e.g. 'breakfast nook' or 'kitchen') on the first line, then a one-sentence "
        "summary on the second line.\n" + "\n".join(f"- {c}" for c in captions[:30])
    )
    try:
        text = chat(llm_cfg, [{"role": "user", "content": prompt}]).strip().splitlines()
    except LLMError:
        return fallback
    lines = [t.strip() for t in text if t.strip()]
    if not lines:
        return fallback
    return lines[0][:60], (" ".join(lines[1:]) or fallback[1])
