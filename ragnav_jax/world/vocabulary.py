"""Object vocabulary of the procedural generator: per-room-type groups with co-occurrence.

Each catalog entry gives a category's footprint, the attributes it can carry and the sensor readings it
reports, with values that mean something (appliance temperatures, plant NDVI, humidity). Each room
type lists groups: an anchor object and companions placed near it or on top of it, so that the
generator produces realistic co-occurrence (TV on a stand with a remote nearby, desk with chair and
monitor, sink with a coffee machine).

Two splits, like R2R's val_seen / val_unseen: the seen one (CATALOG, ROOM_GROUPS, PLANTS; what the paper's
scenes use) and the unseen one (UNSEEN_CATALOG, ROOM_GROUPS_UNSEEN, PLANTS_UNSEEN, with instruction-side
UNSEEN_SYNONYMS and UNSEEN_HYPERNYMS), chosen by `world.split` through `catalog_for` and friends.
"""

from __future__ import annotations

from typing import NamedTuple

COLORS = ("red", "blue", "green", "grey", "black", "white", "brown", "beige", "yellow", "navy", "orange")
WOODS = ("oak", "walnut", "pine", "white-painted", "cherry")
FABRICS = ("leather", "fabric", "velvet", "linen")
METALS = ("steel", "chrome", "black metal", "brass")


class Entry(NamedTuple):
    size: tuple[float, float, float]  # full extents (x, y, z) in metres before jitter
    attrs: tuple[tuple[str, tuple[str, ...]], ...] = ()  # attribute name -> options
    sensors: tuple[tuple[str, float, float], ...] = ()  # reading name, low, high
    wall: bool = False  # placed against a wall
    flat: bool = False  # does not block the robot (rugs, mats)


def _a(**kw) -> tuple[tuple[str, tuple[str, ...]], ...]:
    return tuple(kw.items())


PLANT_ATTRS = _a(color=("green", "dark green", "variegated"), pot=("terracotta", "ceramic", "white", "woven"))
CATALOG: dict[str, Entry] = {
    # kitchen
    "fridge": Entry((0.8, 0.7, 1.8), _a(color=("white", "silver", "black")), (("temperature_c", 3.0, 6.0),), True),
    "sink": Entry((0.8, 0.5, 0.9), _a(material=("steel", "ceramic", "granite")), (), True),
    "coffee machine": Entry(
        (0.35, 0.35, 0.4), _a(color=("black", "silver", "red")), (("temperature_c", 55.0, 92.0),), True
    ),
    "stove": Entry((0.6, 0.6, 0.9), _a(material=("steel", "enamel")), (("temperature_c", 21.0, 220.0),), True),
    "kettle": Entry((0.25, 0.2, 0.3), _a(color=("white", "steel", "blue")), (("temperature_c", 20.0, 98.0),), True),
    "microwave": Entry((0.5, 0.4, 0.35), _a(color=("white", "black", "silver")), (("temperature_c", 21.0, 45.0),), True),
    "dishwasher": Entry((0.6, 0.6, 0.85), _a(color=("white", "steel")), (("temperature_c", 21.0, 65.0),), True),
    "kitchen table": Entry((1.2, 0.8, 0.75), _a(material=WOODS)),
    "chair": Entry((0.45, 0.45, 0.9), _a(color=COLORS, material=("wood", "plastic", "metal"))),
    "trash bin": Entry((0.35, 0.35, 0.6), _a(color=("grey", "white", "steel")), (), True),
    # living room
    "sofa": Entry((2.0, 0.9, 0.8), _a(color=COLORS, material=FABRICS), (), True),
    "coffee table": Entry((1.0, 0.6, 0.45), _a(material=("glass", "oak", "walnut", "marble"))),
    "remote control": Entry((0.2, 0.1, 0.05), _a(color=("black", "grey", "white"))),
    "tv stand": Entry((1.4, 0.45, 0.5), _a(material=WOODS), (), True),
    "television": Entry((1.2, 0.25, 0.7), _a(color=("black", "silver")), (("temperature_c", 28.0, 40.0),)),
    "armchair": Entry((0.9, 0.9, 0.9), _a(color=COLORS, material=FABRICS)),
    "bookshelf": Entry((1.0, 0.4, 2.0), _a(material=WOODS), (), True),
    "floor lamp": Entry((0.4, 0.4, 1.6), _a(color=("black", "brass", "white")), (("temperature_c", 28.0, 45.0),)),
    "rug": Entry((2.0, 1.4, 0.02), _a(color=COLORS, pattern=("striped", "plain", "persian")), (), False, True),
    "radiator": Entry((1.0, 0.12, 0.6), _a(color=("white", "grey")), (("temperature_c", 30.0, 68.0),), True),
    "fireplace": Entry((1.4, 0.5, 1.1), _a(material=("brick", "stone", "marble")), (("temperature_c", 20.0, 250.0),), True),
    "piano": Entry((1.5, 0.6, 1.2), _a(color=("black", "white", "brown")), (), True),
    # bedroom
    "bed": Entry((1.6, 2.0, 0.5), _a(color=("white", "grey", "blue", "beige"), size=("double", "king")), (), True),
    "nightstand": Entry((0.5, 0.4, 0.5), _a(material=WOODS), (), True),
    "table lamp": Entry((0.25, 0.25, 0.45), _a(color=("white", "black", "green", "brass")), (("temperature_c", 26.0, 40.0),)),
    "wardrobe": Entry((1.2, 0.6, 2.0), _a(material=WOODS, color=("white", "brown", "grey")), (), True),
    "dresser": Entry((1.0, 0.5, 0.9), _a(material=WOODS), (), True),
    "mirror": Entry((0.8, 0.06, 1.2), _a(frame=("gold", "black", "wooden", "frameless")), (), True),
    "laundry basket": Entry((0.5, 0.4, 0.55), _a(material=("wicker", "plastic", "fabric"))),
    # study / office
    "desk": Entry((1.4, 0.7, 0.75), _a(material=WOODS), (), True),
    "office chair": Entry((0.6, 0.6, 1.0), _a(color=("black", "grey", "blue", "red"))),
    "computer monitor": Entry((0.6, 0.2, 0.4), _a(color=("black", "silver", "white")), (("temperature_c", 28.0, 42.0),)),
    "desk lamp": Entry((0.2, 0.2, 0.45), _a(color=("black", "white", "green")), (("temperature_c", 26.0, 40.0),)),
    "filing cabinet": Entry((0.5, 0.6, 1.3), _a(color=("grey", "black", "beige")), (), True),
    "printer": Entry((0.5, 0.45, 0.4), _a(color=("white", "black")), (("temperature_c", 21.0, 48.0),), True),
    "globe": Entry((0.45, 0.45, 0.9), _a(style=("antique", "modern"))),
    "whiteboard": Entry((1.6, 0.08, 1.2), _a(frame=("aluminium", "wooden")), (), True),
    "water cooler": Entry((0.4, 0.4, 1.2), _a(color=("white", "blue")), (("temperature_c", 6.0, 12.0),), True),
    "meeting table": Entry((2.0, 1.0, 0.75), _a(material=WOODS)),
    "coat rack": Entry((0.5, 0.5, 1.8), _a(material=("wood", "black metal", "chrome"))),
    # bathroom
    "toilet": Entry((0.4, 0.7, 0.8), _a(color=("white", "black")), (), True),
    "bathtub": Entry((1.7, 0.8, 0.6), _a(material=("acrylic", "enamel", "stone")), (("humidity_pct", 55.0, 90.0),), True),
    "shower": Entry((0.9, 0.9, 2.1), _a(door=("glass", "curtain")), (("humidity_pct", 60.0, 95.0),), True),
    "towel radiator": Entry((0.6, 0.12, 1.0), _a(color=("chrome", "white", "black")), (("temperature_c", 35.0, 60.0),), True),
    "washing machine": Entry((0.6, 0.6, 0.85), _a(color=("white", "grey")), (("temperature_c", 20.0, 60.0),), True),
    "bathroom cabinet": Entry((0.6, 0.35, 0.8), _a(color=("white", "oak")), (), True),
    # dining room
    "dining table": Entry((1.8, 0.9, 0.75), _a(material=WOODS + ("glass",))),
    "sideboard": Entry((1.6, 0.45, 0.85), _a(material=WOODS), (), True),
    "display cabinet": Entry((1.0, 0.45, 1.8), _a(material=WOODS), (), True),
    "wine rack": Entry((0.6, 0.35, 1.1), _a(material=("wood", "black metal")), (("temperature_c", 12.0, 18.0),), True),
    # hallway
    "shoe rack": Entry((0.8, 0.3, 0.5), _a(material=("wood", "black metal", "bamboo")), (), True),
    "console table": Entry((1.0, 0.35, 0.8), _a(material=WOODS + ("glass",)), (), True),
    "umbrella stand": Entry((0.3, 0.3, 0.6), _a(color=("black", "ceramic white", "brass"))),
    "bench": Entry((1.2, 0.4, 0.45), _a(material=("wood", "upholstered", "metal")), (), True),
    # gym
    "treadmill": Entry((0.8, 1.8, 1.3), _a(color=("black", "grey")), (("temperature_c", 21.0, 35.0),)),
    "rowing machine": Entry((0.6, 2.2, 0.5), _a(material=("wood", "steel"))),
    "exercise bike": Entry((0.6, 1.2, 1.2), _a(color=("black", "red", "white"))),
    "dumbbell rack": Entry((1.2, 0.5, 0.8), _a(color=("black", "chrome")), (), True),
    "yoga mat": Entry((0.6, 1.8, 0.01), _a(color=("purple", "blue", "green", "pink")), (), False, True),
    "weight bench": Entry((0.5, 1.3, 0.5), _a(color=("black", "red"))),
    "punching bag": Entry((0.4, 0.4, 1.5), _a(color=("red", "black", "brown"))),
    "fan": Entry((0.45, 0.45, 1.2), _a(color=("white", "black")), (("temperature_c", 20.0, 30.0),)),
    # greenhouse / plants
    "potted plant": Entry((0.5, 0.5, 0.9), PLANT_ATTRS, (("ndvi", 0.1, 0.9),)),
    "fern": Entry((0.5, 0.5, 0.6), PLANT_ATTRS, (("ndvi", 0.1, 0.9),)),
    "cactus": Entry((0.3, 0.3, 0.6), _a(pot=("terracotta", "ceramic", "white")), (("ndvi", 0.1, 0.6),)),
    "orchid": Entry((0.3, 0.3, 0.5), _a(color=("white", "pink", "purple")), (("ndvi", 0.1, 0.9),)),
    "tomato plant": Entry((0.5, 0.5, 1.2), _a(pot=("terracotta", "grow bag")), (("ndvi", 0.1, 0.9),)),
    "lemon tree": Entry((0.7, 0.7, 1.6), _a(pot=("terracotta", "ceramic")), (("ndvi", 0.1, 0.9),)),
    "planter box": Entry((1.2, 0.5, 0.6), _a(material=("wood", "stone")), (("ndvi", 0.1, 0.9), ("humidity_pct", 40.0, 85.0)), True),
    "potting bench": Entry((1.4, 0.6, 0.9), _a(material=("wood", "steel")), (), True),
    "seedling tray": Entry((0.5, 0.3, 0.1), _a(color=("black", "green")), (("ndvi", 0.1, 0.9),)),
    "watering can": Entry((0.4, 0.2, 0.3), _a(color=("green", "zinc", "red"))),
    "heater": Entry((0.5, 0.25, 0.6), _a(color=("white", "black")), (("temperature_c", 35.0, 75.0),), True),
    "hygrometer": Entry((0.15, 0.15, 1.4), _a(color=("white", "brass")), (("humidity_pct", 30.0, 95.0),)),
}

PLANTS = ("potted plant", "fern", "cactus", "orchid", "tomato plant", "lemon tree")


class Group(NamedTuple):
    anchor: str
    weight: float
    companions: tuple[tuple[str, str, float], ...] = ()  # (category, "near" | "on", probability)


ROOM_GROUPS: dict[str, tuple[Group, ...]] = {
    "kitchen": (
        Group("fridge", 3.0),
        Group("sink", 3.0, (("coffee machine", "near", 0.7), ("trash bin", "near", 0.3))),
        Group("stove", 2.0, (("kettle", "near", 0.5),)),
        Group("microwave", 1.0),
        Group("dishwasher", 1.0),
        Group("kitchen table", 1.5, (("chair", "near", 0.9), ("chair", "near", 0.7))),
        Group("potted plant", 0.7),
        Group("radiator", 0.5),
    ),
    "living room": (
        Group("sofa", 3.0, (("coffee table", "near", 0.8), ("remote control", "near", 0.6), ("rug", "near", 0.4))),
        Group("tv stand", 2.0, (("television", "on", 1.0),)),
        Group("armchair", 1.5, (("floor lamp", "near", 0.5),)),
        Group("bookshelf", 1.0),
        Group("potted plant", 1.0),
        Group("radiator", 1.0),
        Group("fireplace", 0.5),
        Group("piano", 0.4),
    ),
    "bedroom": (
        Group("bed", 3.0, (("nightstand", "near", 0.9), ("table lamp", "near", 0.5))),
        Group("wardrobe", 2.0),
        Group("dresser", 1.0, (("mirror", "near", 0.5),)),
        Group("desk", 0.6, (("chair", "near", 0.8),)),
        Group("radiator", 1.0),
        Group("potted plant", 0.6),
        Group("laundry basket", 0.5),
    ),
    "study": (
        Group("desk", 3.0, (("office chair", "near", 1.0), ("computer monitor", "on", 0.9), ("desk lamp", "on", 0.5))),
        Group("bookshelf", 2.0),
        Group("filing cabinet", 1.0),
        Group("printer", 0.8),
        Group("armchair", 0.6, (("floor lamp", "near", 0.5),)),
        Group("globe", 0.4),
        Group("potted plant", 0.6),
        Group("radiator", 0.8),
    ),
    "office": (
        Group("desk", 3.0, (("office chair", "near", 1.0), ("computer monitor", "on", 0.9))),
        Group("printer", 1.0),
        Group("whiteboard", 1.0),
        Group("filing cabinet", 1.0),
        Group("water cooler", 0.8),
        Group("meeting table", 0.7, (("chair", "near", 0.9), ("chair", "near", 0.8))),
        Group("coat rack", 0.5),
        Group("potted plant", 0.7),
    ),
    "bathroom": (
        Group("toilet", 3.0),
        Group("sink", 3.0, (("mirror", "near", 0.6),)),
        Group("bathtub", 1.5),
        Group("shower", 1.5),
        Group("towel radiator", 1.0),
        Group("washing machine", 0.8, (("laundry basket", "near", 0.5),)),
        Group("bathroom cabinet", 0.8),
    ),
    "dining room": (
        Group("dining table", 3.0, (("chair", "near", 1.0), ("chair", "near", 1.0), ("chair", "near", 0.7))),
        Group("sideboard", 1.5),
        Group("display cabinet", 1.0),
        Group("wine rack", 0.6),
        Group("potted plant", 1.0),
        Group("radiator", 0.8),
    ),
    "hallway": (
        Group("coat rack", 2.0),
        Group("shoe rack", 2.0),
        Group("console table", 1.5, (("table lamp", "on", 0.5),)),
        Group("umbrella stand", 1.0),
        Group("mirror", 1.0),
        Group("bench", 0.8),
        Group("potted plant", 0.8),
        Group("radiator", 0.8),
    ),
    "gym": (
        Group("treadmill", 2.0),
        Group("rowing machine", 1.5),
        Group("exercise bike", 1.5),
        Group("dumbbell rack", 1.5, (("weight bench", "near", 0.6),)),
        Group("yoga mat", 1.0),
        Group("punching bag", 0.7),
        Group("water cooler", 0.7),
        Group("fan", 0.6),
    ),
    "greenhouse": (
        Group("potted plant", 3.0),
        Group("planter box", 2.0),
        Group("potting bench", 1.5, (("seedling tray", "on", 0.8), ("watering can", "near", 0.5))),
        Group("fern", 1.0),
        Group("cactus", 1.0),
        Group("orchid", 1.0),
        Group("tomato plant", 1.0),
        Group("lemon tree", 0.7),
        Group("heater", 0.8),
        Group("hygrometer", 0.6),
    ),
}

# Rooms whose type is not in ROOM_GROUPS (user-configured types) get this generic mix.
GENERIC_GROUPS: tuple[Group, ...] = (
    Group("bookshelf", 1.0),
    Group("armchair", 1.0),
    Group("potted plant", 1.0),
    Group("radiator", 1.0),
    Group("console table", 1.0, (("table lamp", "on", 0.5),)),
)


# ----------------------------------------------------------------------------------------------------
# Unseen split (`world.split = "unseen"`, like R2R's val_unseen): room types, categories, attribute kinds
# and values that the seen catalogue above never uses. No unseen name contains a seen one (or another
# unseen one) as a word sequence, so a name never matches inside another. New attribute kinds: "state"
# (switched on/off, open/closed, empty/full; captions put it after the noun), "finish", "shade",
# "fabric", "era" (adjectives before the noun) and "planter" (a trailing phrase, like "pot"). Plants keep
# the generator's NDVI-derived "condition". Many small things stand on others ("on" companions).

SHADES = ("teal", "mustard", "burgundy", "olive", "charcoal", "cream", "ivory", "lilac", "coral", "turquoise")
FINISHES = ("matte", "glossy", "lacquered", "polished", "distressed")
WEAVES = ("tweed", "corduroy", "denim", "chenille", "wool")
ERAS = ("vintage", "retro")
ON_OFF = ("switched on", "switched off")
OPEN_SHUT = ("open", "closed")
EMPTY_FULL = ("empty", "full")
UNSEEN_PLANT_ATTRS = _a(planter=("glazed", "concrete", "copper", "rattan"))

UNSEEN_CATALOG: dict[str, Entry] = {
    # laundry room
    "tumble dryer": Entry((0.6, 0.6, 0.85), _a(shade=SHADES, state=ON_OFF), (("temperature_c", 35.0, 75.0),), True),
    "ironing board": Entry((1.3, 0.4, 0.9), _a(shade=SHADES, fabric=WEAVES)),
    "steam iron": Entry((0.3, 0.15, 0.16), _a(shade=SHADES, state=ON_OFF), (("temperature_c", 90.0, 200.0),)),
    "drying rack": Entry((0.6, 1.3, 1.0), _a(finish=FINISHES, state=EMPTY_FULL)),
    "linen cupboard": Entry(
        (1.0, 0.55, 2.0), _a(finish=FINISHES, state=OPEN_SHUT), (("humidity_pct", 30.0, 60.0),), True
    ),
    "dehumidifier": Entry((0.35, 0.3, 0.6), _a(shade=SHADES, state=ON_OFF), (("humidity_pct", 35.0, 75.0),), True),
    "recycling bin": Entry((0.4, 0.4, 0.7), _a(shade=SHADES, state=EMPTY_FULL), (), True),
    # shared storage and surfaces
    "shelf unit": Entry((1.0, 0.4, 1.0), _a(finish=FINISHES, shade=SHADES), (), True),
    "credenza": Entry((1.6, 0.5, 0.8), _a(finish=FINISHES, era=ERAS), (), True),
    # music room
    "drum kit": Entry((1.5, 1.2, 1.0), _a(shade=SHADES, finish=FINISHES)),
    "record player": Entry((0.45, 0.35, 0.15), _a(era=ERAS, state=ON_OFF)),
    "hi-fi speaker": Entry((0.25, 0.25, 0.4), _a(finish=FINISHES, state=ON_OFF)),
    "guitar": Entry((0.4, 0.15, 1.0), _a(finish=FINISHES, shade=SHADES)),
    "amplifier": Entry((0.5, 0.3, 0.45), _a(era=ERAS, state=ON_OFF), (("temperature_c", 30.0, 55.0),)),
    "harp": Entry((0.8, 0.5, 1.7), _a(finish=FINISHES)),
    "cello": Entry((0.45, 0.3, 1.25), _a(finish=FINISHES)),
    "music stand": Entry((0.5, 0.4, 1.2), _a(finish=FINISHES)),
    "reading lamp": Entry((0.35, 0.35, 1.5), _a(shade=SHADES, state=ON_OFF), (("temperature_c", 30.0, 48.0),)),
    # nursery
    "crib": Entry((0.75, 1.3, 1.0), _a(shade=SHADES, finish=FINISHES), (), True),
    "changing table": Entry((0.9, 0.55, 0.95), _a(shade=SHADES, finish=FINISHES), (), True),
    "night-light": Entry((0.12, 0.12, 0.15), _a(shade=SHADES, state=ON_OFF), (("temperature_c", 26.0, 36.0),)),
    "music box": Entry((0.16, 0.12, 0.1), _a(finish=FINISHES, state=OPEN_SHUT)),
    "diaper pail": Entry((0.3, 0.3, 0.6), _a(shade=SHADES, state=EMPTY_FULL)),
    "toy chest": Entry((0.9, 0.45, 0.5), _a(shade=SHADES, state=OPEN_SHUT), (), True),
    "teddy bear": Entry((0.3, 0.25, 0.35), _a(shade=SHADES, fabric=WEAVES)),
    "play mat": Entry((1.2, 1.2, 0.02), _a(shade=SHADES), (), False, True),
    "air purifier": Entry((0.35, 0.35, 0.7), _a(shade=SHADES, state=ON_OFF), (("humidity_pct", 30.0, 60.0),)),
    "bean bag": Entry((0.8, 0.8, 0.6), _a(shade=SHADES, fabric=WEAVES)),
    # workshop
    "workbench": Entry((1.8, 0.7, 0.9), _a(finish=FINISHES), (), True),
    "soldering station": Entry((0.3, 0.25, 0.15), _a(shade=SHADES, state=ON_OFF), (("temperature_c", 150.0, 380.0),)),
    "toolbox": Entry((0.5, 0.25, 0.25), _a(shade=SHADES, state=OPEN_SHUT)),
    "work light": Entry((0.2, 0.2, 0.5), _a(shade=SHADES, state=ON_OFF), (("temperature_c", 30.0, 60.0),)),
    "tool chest": Entry((0.7, 0.45, 1.0), _a(shade=SHADES, state=OPEN_SHUT), (), True),
    "table saw": Entry((0.8, 0.8, 0.9), _a(shade=SHADES, state=ON_OFF), (("temperature_c", 25.0, 50.0),)),
    # games room
    "pool table": Entry((2.2, 1.2, 0.8), _a(shade=SHADES, finish=FINISHES)),
    "ping-pong table": Entry((2.4, 1.3, 0.76), _a(shade=SHADES)),
    "arcade cabinet": Entry((0.7, 0.8, 1.8), _a(era=ERAS, state=ON_OFF), (("temperature_c", 25.0, 42.0),), True),
    "jukebox": Entry((0.9, 0.65, 1.5), _a(era=ERAS, state=ON_OFF), (("temperature_c", 25.0, 40.0),), True),
    "game console": Entry((0.35, 0.3, 0.08), _a(shade=SHADES, state=ON_OFF), (("temperature_c", 30.0, 55.0),)),
    "mini-fridge": Entry((0.5, 0.5, 0.85), _a(shade=SHADES, state=ON_OFF), (("temperature_c", 2.0, 8.0),), True),
    "popcorn machine": Entry((0.5, 0.4, 1.4), _a(era=ERAS, state=ON_OFF), (("temperature_c", 60.0, 180.0),)),
    # sunroom / plants
    "snake plant": Entry((0.4, 0.4, 0.9), UNSEEN_PLANT_ATTRS, (("ndvi", 0.1, 0.9),)),
    "peace lily": Entry((0.45, 0.45, 0.65), UNSEEN_PLANT_ATTRS, (("ndvi", 0.1, 0.9),)),
    "monstera": Entry((0.8, 0.8, 1.3), UNSEEN_PLANT_ATTRS, (("ndvi", 0.1, 0.9),)),
    "bonsai tree": Entry((0.35, 0.3, 0.35), UNSEEN_PLANT_ATTRS, (("ndvi", 0.1, 0.9),)),
    "spider plant": Entry((0.3, 0.3, 0.4), UNSEEN_PLANT_ATTRS, (("ndvi", 0.1, 0.9),)),
    "plant stand": Entry((0.5, 0.5, 0.8), _a(finish=FINISHES)),
    "daybed": Entry((1.9, 0.9, 0.6), _a(shade=SHADES, fabric=WEAVES), (), True),
    "fish tank": Entry(
        (0.8, 0.35, 0.45), _a(finish=FINISHES), (("temperature_c", 22.0, 28.0), ("humidity_pct", 60.0, 95.0))
    ),
    # library
    "chaise longue": Entry((1.6, 0.7, 0.8), _a(shade=SHADES, fabric=WEAVES)),
    "bureau": Entry((1.0, 0.5, 1.1), _a(finish=FINISHES, state=OPEN_SHUT), (), True),
    "typewriter": Entry((0.45, 0.4, 0.18), _a(era=ERAS, shade=SHADES)),
    "lectern": Entry((0.5, 0.45, 1.2), _a(finish=FINISHES)),
    "magazine rack": Entry((0.4, 0.3, 0.5), _a(finish=FINISHES, state=EMPTY_FULL)),
    # craft room
    "craft table": Entry((1.6, 0.8, 0.9), _a(finish=FINISHES), (), True),
    "sewing machine": Entry((0.45, 0.25, 0.35), _a(era=ERAS, state=ON_OFF), (("temperature_c", 22.0, 40.0),)),
    "yarn basket": Entry((0.35, 0.3, 0.3), _a(shade=SHADES, state=EMPTY_FULL)),
    "easel": Entry((0.7, 0.6, 1.7), _a(finish=FINISHES)),
    "dress form": Entry((0.45, 0.4, 1.6), _a(fabric=WEAVES)),
    "kiln": Entry((0.7, 0.7, 0.9), _a(state=ON_OFF), (("temperature_c", 200.0, 950.0),), True),
    # garage
    "chest freezer": Entry(
        (1.1, 0.65, 0.85), _a(shade=SHADES, state=OPEN_SHUT), (("temperature_c", -24.0, -15.0),), True
    ),
    "bicycle": Entry((1.8, 0.6, 1.0), _a(shade=SHADES, era=ERAS)),
    "lawn mower": Entry((0.6, 1.4, 1.0), _a(shade=SHADES)),
    "wheelbarrow": Entry((0.7, 1.4, 0.7), _a(shade=SHADES, state=EMPTY_FULL)),
    "boiler": Entry((0.5, 0.4, 0.8), _a(shade=SHADES), (("temperature_c", 40.0, 80.0),), True),
    # pantry
    "butcher block": Entry((1.6, 0.65, 0.9), _a(finish=FINISHES), (), True),
    "stand mixer": Entry((0.4, 0.25, 0.35), _a(shade=SHADES, state=ON_OFF)),
    "fruit bowl": Entry((0.3, 0.3, 0.12), _a(finish=FINISHES, state=EMPTY_FULL)),
    "bread maker": Entry((0.35, 0.3, 0.35), _a(shade=SHADES, state=ON_OFF), (("temperature_c", 60.0, 180.0),)),
    "toaster": Entry((0.3, 0.18, 0.2), _a(shade=SHADES, era=ERAS, state=ON_OFF), (("temperature_c", 120.0, 250.0),)),
    "spice rack": Entry((0.6, 0.15, 0.5), _a(finish=FINISHES, state=EMPTY_FULL)),
}

PLANTS_UNSEEN = ("snake plant", "peace lily", "monstera", "bonsai tree", "spider plant")

ROOM_GROUPS_UNSEEN: dict[str, tuple[Group, ...]] = {
    "laundry room": (
        Group("tumble dryer", 3.0, (("drying rack", "near", 0.4),)),
        Group("ironing board", 2.0, (("steam iron", "on", 0.8),)),
        Group("linen cupboard", 1.5),
        Group("shelf unit", 1.5, (("steam iron", "on", 0.4), ("yarn basket", "on", 0.3))),
        Group("dehumidifier", 1.2),
        Group("drying rack", 1.0),
        Group("recycling bin", 0.6),
    ),
    "music room": (
        Group("drum kit", 2.0),
        Group("credenza", 2.0, (("record player", "on", 0.9), ("hi-fi speaker", "on", 0.7))),
        Group("guitar", 1.5, (("amplifier", "near", 0.7),)),
        Group("cello", 0.8, (("music stand", "near", 0.7),)),
        Group("harp", 0.8),
        Group("music stand", 1.0),
        Group("shelf unit", 1.0, (("hi-fi speaker", "on", 0.8), ("hi-fi speaker", "on", 0.4))),
        Group("reading lamp", 0.5),
        Group("snake plant", 0.5),
    ),
    "nursery": (
        Group("crib", 3.0),
        Group(
            "changing table", 2.0, (("night-light", "on", 0.7), ("music box", "on", 0.6), ("diaper pail", "near", 0.7))
        ),
        Group("toy chest", 1.5, (("teddy bear", "on", 0.7),)),
        Group("shelf unit", 1.0, (("night-light", "on", 0.5), ("teddy bear", "on", 0.4))),
        Group("play mat", 1.0),
        Group("air purifier", 0.8),
        Group("bean bag", 0.6),
        Group("peace lily", 0.5),
    ),
    "workshop": (
        Group("workbench", 3.0, (("soldering station", "on", 0.7), ("toolbox", "on", 0.6), ("work light", "on", 0.6))),
        Group("tool chest", 2.0, (("toolbox", "on", 0.5),)),
        Group("table saw", 1.5),
        Group("shelf unit", 1.0, (("work light", "on", 0.5),)),
        Group("recycling bin", 0.6),
        Group("dehumidifier", 0.4),
    ),
    "games room": (
        Group("pool table", 2.5),
        Group("arcade cabinet", 2.0),
        Group("ping-pong table", 1.2),
        Group("credenza", 1.5, (("game console", "on", 0.8), ("hi-fi speaker", "on", 0.5))),
        Group("bean bag", 1.5, (("bean bag", "near", 0.5),)),
        Group("mini-fridge", 1.2),
        Group("jukebox", 1.0),
        Group("popcorn machine", 0.8),
        Group("monstera", 0.6),
    ),
    "sunroom": (
        Group("snake plant", 2.0),
        Group("plant stand", 1.5, (("bonsai tree", "on", 0.9),)),
        Group("plant stand", 1.0, (("spider plant", "on", 0.9),)),
        Group("peace lily", 1.5),
        Group("monstera", 1.5),
        Group("daybed", 1.2),
        Group("credenza", 1.2, (("fish tank", "on", 0.9),)),
        Group("chaise longue", 0.6),
    ),
    "library": (
        Group("shelf unit", 3.0, (("hi-fi speaker", "on", 0.3), ("spider plant", "on", 0.3))),
        Group("bureau", 1.5, (("typewriter", "on", 0.7),)),
        Group("chaise longue", 1.5, (("reading lamp", "near", 0.8),)),
        Group("lectern", 1.0),
        Group("credenza", 0.8, (("fish tank", "on", 0.8),)),
        Group("magazine rack", 1.0),
        Group("dehumidifier", 0.6),
        Group("peace lily", 0.6),
    ),
    "craft room": (
        Group("craft table", 3.0, (("sewing machine", "on", 0.8), ("yarn basket", "near", 0.6))),
        Group("easel", 1.5),
        Group("dress form", 1.2),
        Group("kiln", 1.0),
        Group("shelf unit", 1.0, (("yarn basket", "on", 0.5), ("spider plant", "on", 0.3))),
        Group("ironing board", 0.6, (("steam iron", "on", 0.6),)),
        Group("reading lamp", 0.5),
    ),
    "garage": (
        Group("chest freezer", 2.0),
        Group("workbench", 2.0, (("toolbox", "on", 0.6), ("work light", "on", 0.5))),
        Group("bicycle", 1.5, (("bicycle", "near", 0.4),)),
        Group("lawn mower", 1.2),
        Group("boiler", 1.0),
        Group("recycling bin", 1.0, (("recycling bin", "near", 0.5),)),
        Group("wheelbarrow", 0.8),
        Group("tool chest", 0.8),
    ),
    "pantry": (
        Group("butcher block", 2.0, (("stand mixer", "on", 0.7), ("fruit bowl", "on", 0.6))),
        Group("butcher block", 1.5, (("bread maker", "on", 0.7), ("toaster", "on", 0.6))),
        Group("shelf unit", 2.0, (("spice rack", "on", 0.7),)),
        Group("chest freezer", 1.0),
        Group("mini-fridge", 0.8),
        Group("recycling bin", 0.8),
    ),
}
ROOM_TYPES_UNSEEN = tuple(ROOM_GROUPS_UNSEEN)

GENERIC_GROUPS_UNSEEN: tuple[Group, ...] = (
    Group("shelf unit", 1.0, (("spider plant", "on", 0.5),)),
    Group("credenza", 1.0, (("record player", "on", 0.5),)),
    Group("snake plant", 1.0),
    Group("dehumidifier", 1.0),
    Group("reading lamp", 1.0),
)

# Instruction-side vocabulary for unseen goals: other names a person may write (partly different from
# the captioner's surface forms) and hypernyms; the seen equivalents live in `language/episodes.py`.
UNSEEN_SYNONYMS: dict[str, tuple[str, ...]] = {
    "tumble dryer": ("dryer", "clothes dryer"),
    "fish tank": ("aquarium",),
    "ping-pong table": ("table tennis table",),
    "record player": ("turntable", "record deck"),
    "hi-fi speaker": ("speaker", "stereo speaker"),
    "mini-fridge": ("minibar",),
    "crib": ("cot",),
    "diaper pail": ("nappy bin",),
    "amplifier": ("amp",),
    "drum kit": ("drums", "drum set"),
    "night-light": ("nightlight",),
    "game console": ("games console",),
    "steam iron": ("iron",),
    "bean bag": ("beanbag",),
    "chaise longue": ("chaise lounge",),
    "lawn mower": ("lawnmower", "mower"),
    "bicycle": ("bike",),
    "monstera": ("cheese plant",),
    "peace lily": ("lily",),
    "bonsai tree": ("bonsai",),
    "stand mixer": ("mixer",),
    "bread maker": ("bread machine",),
    "chest freezer": ("freezer",),
    "work light": ("work lamp",),
    "toy chest": ("toy box",),
    "pool table": ("billiard table",),
    "arcade cabinet": ("arcade machine",),
    "shelf unit": ("shelves", "shelving unit"),
    "lectern": ("reading stand",),
    "soldering station": ("soldering iron",),
    "linen cupboard": ("airing cupboard",),
    "drying rack": ("clothes airer",),
    "air purifier": ("air cleaner",),
}
UNSEEN_HYPERNYMS: dict[str, frozenset[str]] = {
    "instrument": frozenset(("drum kit", "guitar", "cello", "harp")),
    "appliance": frozenset(
        ("tumble dryer", "steam iron", "dehumidifier", "air purifier", "mini-fridge", "popcorn machine",
         "chest freezer", "boiler", "stand mixer", "bread maker", "toaster", "sewing machine", "kiln")
    ),
    "plant": frozenset(PLANTS_UNSEEN),
    "lamp": frozenset(("reading lamp", "work light", "night-light")),
    "light": frozenset(("reading lamp", "work light", "night-light")),
    "table": frozenset(("pool table", "ping-pong table", "changing table", "craft table")),
    "seat": frozenset(("bean bag", "chaise longue", "daybed")),
    "bin": frozenset(("recycling bin", "diaper pail")),
    "electronics": frozenset(
        ("game console", "record player", "hi-fi speaker", "amplifier", "jukebox", "arcade cabinet")
    ),
    "tool": frozenset(("soldering station", "table saw")),
}

SPLITS = ("seen", "unseen")


def catalog_for(split: str) -> dict[str, Entry]:
    """The object catalogue of a world split ("seen" | "unseen")."""
    return {"seen": CATALOG, "unseen": UNSEEN_CATALOG}[split]


def room_groups_for(split: str) -> dict[str, tuple[Group, ...]]:
    """Room type -> object groups of a world split."""
    return {"seen": ROOM_GROUPS, "unseen": ROOM_GROUPS_UNSEEN}[split]


def generic_groups_for(split: str) -> tuple[Group, ...]:
    """Groups for rooms whose type has none in the split (user-configured types)."""
    return {"seen": GENERIC_GROUPS, "unseen": GENERIC_GROUPS_UNSEEN}[split]


def plants_for(split: str) -> tuple[str, ...]:
    """Plant categories of a world split (they get an NDVI-derived condition)."""
    return {"seen": PLANTS, "unseen": PLANTS_UNSEEN}[split]


def room_types_for(split: str) -> tuple[str, ...]:
    """Default room types of a world split."""
    from ragnav_jax.config import ROOM_TYPES

    return {"seen": ROOM_TYPES, "unseen": ROOM_TYPES_UNSEEN}[split]
