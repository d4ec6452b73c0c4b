"""Spatial fingerprints d_t: a caption per key pose, written from what it observed.

Default: a deterministic template captioner with realistic, seeded perception noise: detections missed
more often far away and for small things, occasional confusion with a similar category, synonyms
(couch/sofa, TV/television, nightstand/bedside table, ...), attributes sometimes dropped, sensor readings
with noise, varied sentence templates and word order. It is never told room types. Optional: an
OpenAI-compatible chat endpoint (`llm.base_url`) describes the same detections (`memory.captioner=llm`).
"""

from __future__ import annotations

import dataclasses
import math
import re
import zlib
from collections.abc import Sequence

import numpy as np

from ragnav_jax.memory.keyposes import NodeObservation
from ragnav_jax.world.scene import Scene, SceneObject

# Surface forms per category; the first is the canonical name.
SYNONYMS: dict[str, tuple[str, ...]] = {
    "sofa": ("sofa", "couch"),
    "television": ("television", "TV", "flat-screen TV"),
    "nightstand": ("nightstand", "bedside table"),
    "fridge": ("fridge", "refrigerator"),
    "trash bin": ("trash bin", "garbage can", "waste bin"),
    "remote control": ("remote control", "TV remote", "remote"),
    "computer monitor": ("computer monitor", "monitor", "computer screen"),
    "office chair": ("office chair", "desk chair", "swivel chair"),
    "potted plant": ("potted plant", "houseplant"),
    "armchair": ("armchair", "easy chair"),
    "coffee machine": ("coffee machine", "espresso machine", "coffee maker"),
    "wardrobe": ("wardrobe", "closet"),
    "bookshelf": ("bookshelf", "bookcase"),
    "dresser": ("dresser", "chest of drawers"),
    "tv stand": ("tv stand", "TV cabinet", "media console"),
    "coffee table": ("coffee table", "low table"),
    "floor lamp": ("floor lamp", "standing lamp"),
    "table lamp": ("table lamp", "bedside lamp"),
    "washing machine": ("washing machine", "washer"),
    "bathtub": ("bathtub", "tub"),
    "stove": ("stove", "cooker", "hob"),
    "microwave": ("microwave", "microwave oven"),
    "rug": ("rug", "carpet"),
    "heater": ("heater", "space heater"),
    "water cooler": ("water cooler", "water dispenser"),
    "treadmill": ("treadmill", "running machine"),
    "exercise bike": ("exercise bike", "stationary bike"),
    "punching bag": ("punching bag", "boxing bag"),
    "yoga mat": ("yoga mat", "exercise mat"),
    "filing cabinet": ("filing cabinet", "file cabinet"),
    "sideboard": ("sideboard", "buffet cabinet"),
    "coat rack": ("coat rack", "coat stand"),
    "shoe rack": ("shoe rack", "shoe shelf"),
    "toilet": ("toilet", "WC"),
    "dishwasher": ("dishwasher", "dish washer"),
    "laundry basket": ("laundry basket", "laundry hamper"),
    "towel radiator": ("towel radiator", "heated towel rail"),
    "kettle": ("kettle", "electric kettle"),
    # unseen split (world.split=unseen)
    "tumble dryer": ("tumble dryer", "clothes dryer"),
    "fish tank": ("fish tank", "aquarium"),
    "record player": ("record player", "turntable"),
    "hi-fi speaker": ("hi-fi speaker", "loudspeaker"),
    "mini-fridge": ("mini-fridge", "minibar"),
    "crib": ("crib", "cot"),
    "diaper pail": ("diaper pail", "nappy bin"),
    "ping-pong table": ("ping-pong table", "table tennis table"),
    "amplifier": ("amplifier", "amp"),
    "drum kit": ("drum kit", "drum set"),
    "game console": ("game console", "games console"),
    "bean bag": ("bean bag", "beanbag"),
    "lawn mower": ("lawn mower", "lawnmower"),
    "stand mixer": ("stand mixer", "food mixer"),
    "monstera": ("monstera", "cheese plant"),
    "work light": ("work light", "work lamp"),
    "air purifier": ("air purifier", "air cleaner"),
    "chest freezer": ("chest freezer", "deep freezer"),
    "shelf unit": ("shelf unit", "shelving unit"),
}
# Plausible detector confusions (category -> what it is sometimes taken for).
CONFUSIONS: dict[str, str] = {
    "armchair": "chair", "office chair": "chair", "fern": "potted plant", "orchid": "potted plant",
    "kettle": "coffee machine", "dresser": "sideboard", "console table": "sideboard", "heater": "radiator",
    "towel radiator": "radiator", "desk": "kitchen table", "meeting table": "dining table", "globe": "floor lamp",
    # unseen split
    "cello": "guitar", "guitar": "cello", "amplifier": "hi-fi speaker", "peace lily": "spider plant",
    "snake plant": "spider plant", "work light": "reading lamp", "arcade cabinet": "jukebox", "toolbox": "tool chest",
    "craft table": "workbench", "dehumidifier": "air purifier", "mini-fridge": "chest freezer",
    "chaise longue": "daybed", "bread maker": "toaster",
}
# Attribute keys that read as adjectives before the noun, in English adjective order; those of TRAILING become
# trailing phrases ("state", of the unseen split, reads "a tumble dryer that is switched on"); any other key a
# scene uses ("colour", "kind") is said before the noun, ahead of these.
ADJECTIVE_KEYS = ("size", "condition", "style", "era", "finish", "color", "shade", "pattern", "material", "fabric")
TRAILING = {
    "pot": "in a {} pot", "frame": "with a {} frame", "door": "with a {} door", "planter": "in a {} planter",
    "state": "that is {}",
}
SENSOR_TEXT = {
    "temperature_c": ("at about {:.0f} °C", 1.0),
    "ndvi": ("with NDVI {:.2f}", 0.02),
    "humidity_pct": ("at {:.0f}% humidity", 2.0),
}
TEMPLATES = (
    "A view with {list}.",
    "I can see {list}.",
    "{List} in view.",
    "In front of the robot: {list}.",
    "There is {list} here.",
    "{first} nearby, and {rest} further away.",
    "Close by: {first}. Beyond it, {rest}.",
)
EMPTY = ("A bare wall.", "An empty stretch of floor.", "Nothing notable in view.", "A plain corner of a room.")


def canonical(label: str) -> str:
    """Canonical category of a surface form (the label itself when unknown)."""
    low = label.lower()
    for cat, forms in SYNONYMS.items():
        if low in (f.lower() for f in forms):
            return cat
    return low


def find_words(needle: str, text: str) -> re.Match | None:
    """`needle` in `text` as whole words (a hyphen joins words: 'white' is not in 'white-painted')."""
    return re.search(r"(?<![\w-])" + re.escape(needle) + r"(?![\w-])", text)


@dataclasses.dataclass(frozen=True)
class CaptionNoise:
    detect_near: float = 0.97  # detection probability within 1.5 m
    detect_falloff: float = 4.0  # metres: detection probability decays as exp(-(d - 1.5) / falloff)
    small_penalty: float = 0.8  # factor for objects whose largest side is under 0.3 m
    confusion: float = 0.03
    synonym: float = 0.35
    attribute_keep: float = 0.6
    sensor_text: float = 0.7  # chance to mention a reading of an object within 3 m
    max_objects: int = 8


@dataclasses.dataclass(frozen=True)
class Caption:
    text: str
    labels: tuple[str, ...]  # the surface labels used, in caption order (what a summariser can read)
    objects: tuple[int, ...] = ()  # scene object index each described instance refers to, caption order
    phrases: tuple[str, ...] = ()  # the phrase describing each of them, caption order


def _rng(seed: int, scene: str, node: int) -> np.random.Generator:
    return np.random.default_rng(np.random.SeedSequence([int(seed), zlib.crc32(scene.encode()), int(node)]))


def _article(phrase: str) -> str:
    if phrase[:2].isupper() or phrase.startswith("TV"):
        return "a " + phrase
    return ("an " if phrase[0].lower() in "aeiou" else "a ") + phrase


def _phrase(rng, o: SceneObject, label: str, dist: float, noise: CaptionNoise) -> str:
    attrs = o.attrs
    # a scene may name its attributes as it likes ("colour", "kind", "brand"): what the known keys do not
    # place is said before the noun too, first
    keys = [k for k in attrs if k not in ADJECTIVE_KEYS and k not in TRAILING] + list(ADJECTIVE_KEYS)
    adjs = [attrs[k] for k in keys if k in attrs and rng.uniform() < noise.attribute_keep]
    if len(adjs) > 1 and rng.uniform() < 0.3:
        adjs = adjs[::-1]
    text = " ".join([*adjs, label])
    for k, fmt in TRAILING.items():
        if k in attrs and rng.uniform() < noise.attribute_keep:
            text += " " + fmt.format(attrs[k])
    if o.description and rng.uniform() < noise.attribute_keep:  # the scene's own words for how it looks
        text += ", " + o.description.strip().rstrip(".").lower()
    if dist < 3.0:
        for k, v in o.sensors:
            if k in SENSOR_TEXT and rng.uniform() < noise.sensor_text:
                fmt, sd = SENSOR_TEXT[k]
                text += " " + fmt.format(v + rng.normal(0.0, sd))
    return _article(text)


def describe_object(rng, o: SceneObject, dist: float, noise: CaptionNoise) -> tuple[str, str]:
    """(name, phrase) of one detection at `dist` metres: a rare confusion, a synonym, the attributes kept,
    readings within 3 m ('couch', 'a grey fabric couch')."""
    cat = o.category
    if cat in CONFUSIONS and rng.uniform() < noise.confusion:
        cat = CONFUSIONS[cat]
    forms = SYNONYMS.get(cat, (cat,))
    label = forms[0] if len(forms) == 1 or rng.uniform() >= noise.synonym else forms[int(rng.integers(1, len(forms)))]
    return label, _phrase(rng, o, label, dist, noise)


def _join(rng, items: Sequence[str]) -> str:
    if len(items) == 1:
        return items[0]
    style = rng.integers(3)
    if style == 0:
        return ", ".join(items[:-1]) + " and " + items[-1]
    if style == 1:
        return ", ".join(items)
    return "; ".join(items)


def template_caption(scene: Scene, obs: NodeObservation, node: int, seed: int, noise: CaptionNoise) -> Caption:
    """The caption of one key pose: deterministic in (seed, scene name, node index)."""
    rng = _rng(seed, scene.name, node)
    kept = []
    for oi, d in zip(obs.objects, obs.distances):
        o = scene.objects[oi]
        p = noise.detect_near * math.exp(-max(0.0, d - 1.5) / noise.detect_falloff)
        if max(o.size[0], o.size[1]) < 0.3:
            p *= noise.small_penalty
        if rng.uniform() < p:
            kept.append((oi, d))
    kept = kept[: noise.max_objects]
    if not kept:
        return Caption(EMPTY[int(rng.integers(len(EMPTY)))], ())
    labels, phrases = [], []
    for oi, d in kept:
        label, phrase = describe_object(rng, scene.objects[oi], d, noise)
        labels.append(label)
        phrases.append(phrase)
    order = list(range(len(phrases)))
    if rng.uniform() < 0.4:  # otherwise nearest first
        rng.shuffle(order)
    phrases = [phrases[i] for i in order]
    labels = [labels[i] for i in order]
    objects = [int(kept[i][0]) for i in order]
    t = TEMPLATES[int(rng.integers(len(TEMPLATES)))]
    if "{first}" in t and len(phrases) < 2:
        t = TEMPLATES[0]
    if "{first}" in t:
        text = t.format(first=phrases[0][0].upper() + phrases[0][1:], rest=_join(rng, phrases[1:]))
    else:
        lst = _join(rng, phrases)
        text = t.format(list=lst, List=lst[0].upper() + lst[1:])
    return Caption(text, tuple(labels), tuple(objects), tuple(phrases))


# A reply that starts like chat ("Sure! Here is ...") or refuses is talk to the user, not a view's caption.
CHAT_OPENERS = ("sure", "certainly", "of course", "absolutely", "okay", "ok,", "ok!", "here is", "here's",
                "below is", "as an ai", "as a language model", "i'm sorry", "i am sorry", "sorry", "i cannot",
                "i can't", "i can not", "unfortunately", "hello", "hi!", "hi,", "great question")
MAX_CAPTION_CHARS = 500  # the prompt asks for one or two sentences


def caption_problem(text: str) -> str | None:
    """Why an LLM reply is not a caption of one view (a short phrase), or None when it reads as one."""
    t = text.strip()
    if not t:
        return "an empty reply"
    if len(t) > MAX_CAPTION_CHARS:
        return f"{len(t)} characters long (a caption is one or two sentences)"
    if t.lower().startswith(CHAT_OPENERS):
        return "a chat reply, not a caption"
    if "\n\n" in t or t.startswith(("```", "#", "- ", "* ", "1.", "{", "[")):
        return "formatted text (paragraphs, a list, code or JSON), not a caption"
    if "?" in t:
        return "a question, not a description"
    if not t.replace("\n", " ").isprintable():
        return "control characters in the text"
    return None


def llm_caption(scene: Scene, obs: NodeObservation, llm_cfg, fallback: Caption) -> tuple[Caption, str | None]:
    """Asks the configured OpenAI-compatible endpoint to describe the detections of one key pose.

    Returns (caption, problem): a reply that does not read as a caption (`caption_problem`) is replaced
    by `fallback` (the template caption of the same view) and `problem` says why; else problem is None."""
    from ragnav_jax.memory.llm import chat

    lines = []
    for oi, d, b in zip(obs.objects, obs.distances, obs.bearings):
        o = scene.objects[oi]
        said = [f"{k}={v}" for k, v in [*o.attributes, *o.sensors]] + ([o.description] if o.description else [])
        extra = ", ".join(said)
        lines.append(f"- {o.category} at {d:.1f} m, bearing {math.degrees(b):.0f} deg" + (f" ({extra})" if extra else ""))
    prompt = (
        "You are the camera of a household robot. Describe this view in one or two sentences for a map of the home. "
        "Mention the objects with their notable attributes and readings; do not guess the room type.\n"
        + ("\n".join(lines) if lines else "(no objects detected)")
    )
    text = chat(llm_cfg, [{"role": "user", "content": prompt}]).strip()
    if problem := caption_problem(text):
        return fallback, f"{problem}: {text[:60]!r}"
    labels = tuple(scene.objects[oi].category for oi in obs.objects)
    return Caption(text, labels, tuple(int(oi) for oi in obs.objects), labels), None
