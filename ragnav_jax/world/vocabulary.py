"""Object vocabulary of the procedural generator: per-room-type groups with co-occurrence.

Each catalog entry gives a category's footprint, the attributes it can carry and the sensor readings it
reports, with values that mean something (appliance temperatures, plant NDVI, humidity). Each room
type lists groups: an anchor object and companions placed near it or on top of it, so that the
generator produces realistic co-occurrence (TV on a stand with a remote nearby, desk with chair and
monitor, sink with a coffee machine).
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
