"""Closed-class word lists of the rule parser: function words, never object categories.

The parser is open-vocabulary: any noun it has never seen can be a goal ("rowing machine",
"defibrillator", "x-ray viewer"). What it needs to know are the words around the nouns: verbs and
politeness that introduce a goal, determiners, relation and order phrases, descriptive adjectives
(colours, materials, patterns, sizes, states), relative-clause words (pronouns, copulas), room words,
sensor reading names, units, comparators and number words.
"""

from __future__ import annotations

COLOURS = frozenset(
    "red blue green grey gray black white brown beige yellow navy orange purple pink silver gold golden "
    "cream teal turquoise violet maroon tan ivory charcoal olive khaki magenta cyan crimson lilac lavender "
    "burgundy mint amber bronze copper rose scarlet emerald azure indigo".split()
)
INTENSIFIERS = frozenset("dark light pale bright deep pastel dusty".split())  # modifiers only before a colour
MATERIALS = frozenset(
    "wood wooden oak walnut pine cherry maple birch teak mahogany bamboo wicker rattan steel stainless chrome "
    "brass iron metal metallic aluminium aluminum zinc tin glass plastic ceramic porcelain stone marble granite "
    "brick concrete leather fabric velvet linen cotton wool woollen woolen upholstered acrylic enamel terracotta "
    "clay cardboard rubber felt suede lacquered painted wrought cast-iron".split()
)
DESCRIPTORS = frozenset(
    # patterns and styles
    "striped plain persian patterned checked checkered chequered floral spotted dotted tartan plaid "
    "antique modern vintage old new classic rustic retro contemporary traditional ornate fancy simple "
    # sizes and shapes
    "big small large little tiny huge giant tall short wide narrow single double twin queen king mini "
    "round square rectangular oval compact "
    # states
    "open closed empty full broken clean dirty used healthy unhealthy wilting wilted dying dry fresh lush "
    "fair sick warm hot cold cool frosted shiny dusty framed frameless glazed curtained sliding electric "
    "digital portable folding upright variegated mirrored padded cushioned leafy flowering blooming "
    "freestanding wall-mounted spare main".split()
)
# States an object can be in, as written after a copula ("the lamp that is switched on", "the cabinet that's
# open") -> the attribute string kept (multi-word states stay one attribute). A bare "on"/"off" after a
# copula is a state only where no noun follows ("the lamp, which is on," but "the lamp that is on the table").
STATE_PHRASES: dict[str, str] = {
    "switched on": "switched on", "switched off": "switched off", "turned on": "turned on",
    "turned off": "turned off", "powered on": "powered on", "powered off": "powered off",
    "plugged in": "plugged in", "unplugged": "unplugged", "lit": "lit", "unlit": "unlit", "running": "running",
    "idle": "idle", "folded": "folded", "unfolded": "unfolded", "folded up": "folded", "open": "open",
    "opened": "open", "closed": "closed", "shut": "closed", "empty": "empty", "full": "full", "in use": "in use",
    "on standby": "on standby", "on": "switched on", "off": "switched off", "left on": "switched on",
    "left off": "switched off", "left open": "open", "locked": "locked", "unlocked": "unlocked",
    "half full": "half full", "half-full": "half full", "half empty": "half empty", "half-empty": "half empty",
}
# "not lit" -> "unlit": negated states that have a named opposite.
STATE_OPPOSITES: dict[str, str] = {
    "switched on": "switched off", "switched off": "switched on", "turned on": "turned off",
    "turned off": "turned on", "powered on": "powered off", "powered off": "powered on", "plugged in": "unplugged",
    "unplugged": "plugged in", "lit": "unlit", "unlit": "lit", "running": "idle", "idle": "running",
    "folded": "unfolded", "unfolded": "folded", "open": "closed", "closed": "open", "empty": "full", "full": "empty",
    "locked": "unlocked", "unlocked": "locked",
}
# States and conditions that say the same of an object, as a description may put it ("running" is what
# "switched on" says of a dryer, "dying" what "wilting" says of a plant): a state is seen where any phrase of its
# class is said. The encoder cannot tell these: it places "dying" nearer "healthy" than "wilting".
_SAME_STATES = (
    ("switched on", "turned on", "powered on", "running", "in use"),
    ("switched off", "turned off", "powered off", "unplugged"),
    ("open", "opened"),
    ("closed", "shut"),
    ("lit", "switched on", "turned on"),
    ("unlit", "switched off", "turned off"),
    ("wilting", "wilted", "withered", "dying", "drooping", "droopy", "sickly", "unhealthy", "struggling", "ailing"),
    ("healthy", "thriving", "flourishing", "vigorous"),
)
SAME_STATES: dict[str, tuple[str, ...]] = {
    s: tuple(dict.fromkeys(x for c in _SAME_STATES if s in c for x in c)) for c in _SAME_STATES for s in c}
# Participle states that may follow the noun without a copula ("the lamp switched on", "the kettle unplugged")
# or precede it hyphenated ("the switched-on lamp"); adjectives such as "open" need "that is" after a noun.
PARTICIPLE_STATES = frozenset(
    "switched on|switched off|turned on|turned off|powered on|powered off|plugged in|unplugged|lit|unlit|"
    "running|folded|unfolded|in use|on standby".split("|")
)
# Single-word states that read as modifiers before a noun ("the unlit candle"); "running" is left out
# ("running shoes", "running machine" are nouns).
STATE_MODIFIERS = frozenset("lit unlit unplugged idle folded unfolded".split())
MODIFIER_WORDS = COLOURS | MATERIALS | DESCRIPTORS | STATE_MODIFIERS
SIZE_WORDS = frozenset(
    "big small large little tiny huge giant tall short wide narrow mini compact single double twin queen king".split()
)
# A hyphenated word is a modifier when its last part is one of these or ends in -ed ("gold-framed").
HYPHEN_MODIFIER_TAILS = frozenset("size sized style styled tone toned colour color coloured colored".split())

ROOM_WORDS = frozenset(
    "kitchen bedroom bathroom study office hallway hall gym greenhouse garage lounge pantry nursery den attic "
    "basement cellar corridor foyer entrance entryway lobby closet porch conservatory library workshop studio "
    "playroom washroom lavatory loo laundry utility kitchenette bedchamber vestibule landing mudroom sunroom "
    "storeroom boxroom loft hayloft barn stable stables shed veranda verandah patio terrace balcony scullery parlour "
    "parlor reception ward surgery dispensary pharmacy infirmary atrium gallery annex annexe cloakroom larder sauna "
    "darkroom dormitory dorm classroom staffroom boardroom showroom workroom stockroom schoolroom sickbay chapel "
    "bunkroom bedsit kennel garret".split()
)
ROOM_SUFFIXES = ("room", "area", "zone", "wing", "space")
# Words before a room noun that make it a relation's, not a room's name ("in the same room as", "the next room")
ROOM_RELATION_WORDS = frozenset({"same", "next", "adjacent", "adjoining", "neighbouring", "neighboring", "nearby",
                                 "opposite", "different", "shared", "common"})

DETERMINERS = frozenset(
    "the a an my our your their his her its this that these those some any whichever whatever".split()
)
# Noun phrases made only of these words name no goal ("these", "the following", "all of them").
FILLER_NOUNS = frozenset(
    "it them that this there here one ones these those following each both all everything of three two four "
    "five places place spots spot locations objects things items targets goals stops waypoints ones them route routes "
    "itinerary tour trip plan list circuit errands rounds order sequence task tasks job mission request robot note "
    "instructions agenda".split()
)
PRONOUN_ANCHORS = frozenset("it that this them there one".split())
# Head nouns that name no kind of object: "the hottest thing in the den" is whatever the other parts single out.
GENERIC_HEADS = frozenset("thing object item something".split())

# Relation phrases, longest first at match time; values are RELATION_TYPES.
RELATION_PHRASES: dict[str, str] = {
    "in the same room as": "in_room_with",
    "in the same room with": "in_room_with",
    "in the room with": "in_room_with",
    "in the room that has": "in_room_with",
    "in the room containing": "in_room_with",
    "in the same room as the": "in_room_with",
    # "in the room where the kiln is": the clause's closing "is" is left as a dangling word of the anchor
    "in the room where": "in_room_with",
    "in the same room where": "in_room_with",
    "in the room in which": "in_room_with",
    "in the same room in which": "in_room_with",
    "on top of": "on",
    "on": "on",
    "onto": "on",
    "atop": "on",
    "upon": "on",
    "next to": "next_to",
    "alongside": "next_to",
    "adjacent to": "next_to",
    "beside": "beside",
    "besides": "beside",
    "by": "by",
    "near": "near",
    "near to": "near",
    "close by": "near",
    "nearby": "near",
    "in the vicinity of": "near",
    "a few steps from": "near",
    "a little way from": "near",
    "a little way away from": "near",
    "a short way from": "near",
    "a short distance from": "near",
    "a little distance from": "near",
    "up against": "next_to",
    "right up against": "next_to",
    "pushed up against": "next_to",
    "against": "next_to",
    "in close proximity to": "near",
    "in the proximity of": "near",
    "within close proximity of": "near",
    "a few steps away from": "near",
    "a stone's throw from": "near",
    "a short walk from": "near",
    "within reach of": "near",
    "side by side with": "next_to",
    "at the side of": "beside",
    "by the side of": "beside",
    "to the side of": "beside",
    "down by": "by",
    "up on": "on",
    "up above": "above",
    "out in front of": "in_front_of",
    "straight across from": "opposite",
    "right across from": "opposite",
    "in the neighbourhood of": "near",
    "in the neighborhood of": "near",
    "not far from": "near",
    "nearest to": "near",
    "nearest": "near",
    "closest to": "near",
    "close to": "near",
    "around": "near",
    "at": "near",
    "under": "under",
    "underneath": "under",
    "beneath": "under",
    "below": "under",
    "above": "above",
    "over": "above",
    "in front of": "in_front_of",
    "behind": "behind",
    "at the back of": "behind",
    "opposite": "opposite",
    "opposite to": "opposite",
    "opposite of": "opposite",
    "across from": "opposite",
    "facing": "opposite",
    "faces": "opposite",
    "face": "opposite",
    "to the left of": "left_of",
    "on the left of": "left_of",
    "left of": "left_of",
    "to the right of": "right_of",
    "on the right of": "right_of",
    "with": "with",
    "that has": "with",
    "which has": "with",
    "having": "with",
    "holding": "with",
    # a finite verb of possession after a relative pronoun or "and": "which has a kettle on it", "and has ..."
    "has": "with",
    "have": "with",
    "holds": "with",
    "in": "in",
    "inside": "in",
    "inside of": "in",
    "within": "in",
    "into": "in",
}
# "shares a room with", "sharing the same room as": a verb of sharing before a room noun is in_room_with.
for _v in ("share", "shares", "sharing", "shared"):
    for _d in ("a", "the", "the same", "one", "a common"):
        for _p in ("with", "as"):
            RELATION_PHRASES[f"{_v} {_d} room {_p}"] = "in_room_with"

# "in a room together with", "in one room with": one room shared is in_room_with.
for _d in ("a", "one", "the one"):
    for _t in ("", "together "):
        RELATION_PHRASES.setdefault(f"in {_d} room {_t}with", "in_room_with")
RELATION_PHRASES.setdefault("together in a room with", "in_room_with")

# "within a few paces of", "within easy reach of": a distance said as a measure of effort is near.
for _m in ("a few steps", "a few paces", "a couple of steps", "a couple of paces", "a step or two", "a pace or two",
           "a short walk", "a short stroll", "a stone's throw", "easy reach", "arm's reach", "walking distance",
           "easy walking distance", "spitting distance", "a whisker"):
    RELATION_PHRASES.setdefault(f"within {_m} of", "near")
RELATION_PHRASES.update({"close at hand to": "near", "near at hand to": "near", "handy for": "near", "handy to": "near",
                         "hard by": "by", "close beside": "beside", "shoulder to shoulder with": "next_to",
                         "immediately adjoining": "next_to", "directly adjoining": "next_to", "bearing": "with",
                         "sporting": "with", "carrying": "with", "within striking distance of": "near",
                         "in striking distance of": "near"})

# "in whichever room holds", "in the room that also houses": a room picked out by what it holds is in_room_with.
for _d in ("the", "whichever", "whatever", "any"):
    for _r in ("", "that ", "which ", "that also ", "which also ", "also "):
        for _h in ("has", "holds", "contains", "houses", "keeps"):
            RELATION_PHRASES.setdefault(f"in {_d} room {_r}{_h}", "in_room_with")
    for _h in ("with", "containing", "holding", "housing", "that has", "that holds"):
        RELATION_PHRASES.setdefault(f"in {_d} room {_h}", "in_room_with")

# Words that may stand between a noun and its relation ("the lamp that is right next to the sofa").
RELATIVE_LEADERS = frozenset(
    "that which who is are sits stands lies located positioned placed situated sitting standing lying "
    "resting found right just directly immediately somewhere mounted hanging kept rests hangs perched parked "
    "stored stationed installed sat stood propped tucked pushed sited lives live sit rest lie hang".split()
)

# Relative clauses: "the lamp that is switched on", "the sofa which is red", "the cabinet that's open".
RELATIVE_PRONOUNS = frozenset("that which who".split())
RELATIVE_CONTRACTED = frozenset("that's which's who's thats".split())  # pronoun + "is"
TRUE_COPULAS = frozenset("is are was were be been being seems seem appears appear looks look stays stay remains remain".split())
MODALS = frozenset("should must will would can could might may".split())
# Words that may stand between a relative pronoun and a state ("that has been left on", "which is currently lit").
COPULA_WORDS = TRUE_COPULAS | MODALS | frozenset("has have had currently now still already presently also left kept".split())
NEGATED_COPULAS = frozenset("isn't aren't wasn't weren't not".split())
MADE_OF = (("made", "of"), ("made", "from"), ("made", "out", "of"))

# Reading names as written -> scene sensor key.
READING_NAMES: dict[str, str] = {
    "ndvi": "ndvi",
    "vegetation index": "ndvi",
    "greenness index": "ndvi",
    "greenness": "ndvi",
    "plant health": "ndvi",
    "health index": "ndvi",
    "temperature": "temperature_c",
    "temp": "temperature_c",
    "thermometer reading": "temperature_c",
    "surface temperature": "temperature_c",
    "heat": "temperature_c",
    "relative humidity": "humidity_pct",
    "hygrometer reading": "humidity_pct",
    "humidity": "humidity_pct",
    "moisture": "humidity_pct",
    "rh": "humidity_pct",
    # readings no generator writes, for scenes users write (language/readings.py: their keys and units)
    "co2": "co2_ppm",
    "co₂": "co2_ppm",
    "carbon dioxide": "co2_ppm",
    "co2 level": "co2_ppm",
    "co2 concentration": "co2_ppm",
    "noise": "noise_db",
    "noise level": "noise_db",
    "sound level": "noise_db",
    "loudness": "noise_db",
    "light level": "light_lux",
    "illuminance": "light_lux",
    "brightness": "light_lux",
    "light intensity": "light_lux",
    "battery": "battery_pct",
    "battery level": "battery_pct",
    "battery charge": "battery_pct",
    "charge level": "battery_pct",
    "power": "power_w",
    "power draw": "power_w",
    "power consumption": "power_w",
    "power usage": "power_w",
    "wattage": "power_w",
    "weight": "weight_kg",
    "mass": "weight_kg",
    "pressure": "pressure_hpa",
    "air pressure": "pressure_hpa",
    "barometric pressure": "pressure_hpa",
    "atmospheric pressure": "pressure_hpa",
}

# Gradable adjectives of the sensor readings: word -> (reading, +1 more / -1 less).
GRADABLE: dict[str, tuple[str, int]] = {
    "warm": ("temperature_c", 1),
    "hot": ("temperature_c", 1),
    "cold": ("temperature_c", -1),
    "cool": ("temperature_c", -1),
    "chilly": ("temperature_c", -1),
    "healthy": ("ndvi", 1),
    "green": ("ndvi", 1),
    "lush": ("ndvi", 1),
    "unhealthy": ("ndvi", -1),
    "sick": ("ndvi", -1),
    "wilted": ("ndvi", -1),
    "thriving": ("ndvi", 1), "flourishing": ("ndvi", 1), "vigorous": ("ndvi", 1), "luxuriant": ("ndvi", 1),
    "verdant": ("ndvi", 1), "withered": ("ndvi", -1), "shrivelled": ("ndvi", -1), "shriveled": ("ndvi", -1),
    "wilting": ("ndvi", -1), "sickly": ("ndvi", -1), "droopy": ("ndvi", -1),
    "humid": ("humidity_pct", 1),
    "damp": ("humidity_pct", 1),
    "wet": ("humidity_pct", 1),
    "steamy": ("humidity_pct", 1),
    "moist": ("humidity_pct", 1),
    "dry": ("humidity_pct", -1),
    "loud": ("noise_db", 1),
    "noisy": ("noise_db", 1),
    "quiet": ("noise_db", -1),
    "bright": ("light_lux", 1),
    "dim": ("light_lux", -1),
    "heavy": ("weight_kg", 1),
}
SUPERLATIVES: dict[str, tuple[str, int]] = {
    "warmest": ("temperature_c", 1),
    "hottest": ("temperature_c", 1),
    "coldest": ("temperature_c", -1),
    "coolest": ("temperature_c", -1),
    "chilliest": ("temperature_c", -1),
    "healthiest": ("ndvi", 1),
    "greenest": ("ndvi", 1),
    "lushest": ("ndvi", 1),
    "unhealthiest": ("ndvi", -1),
    "sickest": ("ndvi", -1),
    "sickliest": ("ndvi", -1),
    "iciest": ("temperature_c", -1),
    "frostiest": ("temperature_c", -1),
    "muggiest": ("humidity_pct", 1),
    "dampest": ("humidity_pct", 1),
    "wettest": ("humidity_pct", 1),
    "steamiest": ("humidity_pct", 1),
    "driest": ("humidity_pct", -1),
    "dryest": ("humidity_pct", -1),
    "loudest": ("noise_db", 1),
    "noisiest": ("noise_db", 1),
    "quietest": ("noise_db", -1),
    "brightest": ("light_lux", 1),
    "dimmest": ("light_lux", -1),
    "heaviest": ("weight_kg", 1),
}
COMPARATIVES: dict[str, tuple[str, int]] = {
    "warmer": ("temperature_c", 1),
    "hotter": ("temperature_c", 1),
    "colder": ("temperature_c", -1),
    "cooler": ("temperature_c", -1),
    "chillier": ("temperature_c", -1),
    "healthier": ("ndvi", 1),
    "greener": ("ndvi", 1),
    "more humid": ("humidity_pct", 1),
    "damper": ("humidity_pct", 1),
    "wetter": ("humidity_pct", 1),
    "drier": ("humidity_pct", -1),
    "dryer": ("humidity_pct", -1),
    "less humid": ("humidity_pct", -1),
    "louder": ("noise_db", 1),
    "noisier": ("noise_db", 1),
    "quieter": ("noise_db", -1),
    "brighter": ("light_lux", 1),
    "dimmer": ("light_lux", -1),
    "heavier": ("weight_kg", 1),
}
# A value said to be above or below every other one's is the most or the least ("whose NDVI is lower than any
# other", "a temperature higher than all the rest", "whose reading beats all the others"): bare comparatives and
# verbs of outdoing, with their sign.
OUTDO_COMPARATIVES = {"higher": 1, "greater": 1, "bigger": 1, "larger": 1, "more": 1, "lower": -1, "less": -1,
                      "smaller": -1}
OUTDO_VERBS = {"beats": 1, "tops": 1, "outdoes": 1, "outstrips": 1, "exceeds": 1, "surpasses": 1, "leads": 1,
               "trumps": 1, "outranks": 1, "is above": 1, "sits above": 1, "is over": 1, "is below": -1,
               "sits below": -1, "is under": -1, "trails": -1, "undercuts": -1}
EXTREME_WORDS = {
    "highest": 1, "maximum": 1, "max": 1, "greatest": 1, "largest": 1, "biggest": 1, "top": 1, "peak": 1,
    "lowest": -1, "minimum": -1, "min": -1, "smallest": -1, "least": -1, "most": 1,
}

# Comparator phrases -> comparator code.
COMPARATOR_PHRASES: dict[str, str] = {
    "above": "gt", "over": "gt", "greater than": "gt", "more than": "gt", "higher than": "gt", "bigger than": "gt",
    "larger than": "gt", "exceeding": "gt", "in excess of": "gt", "upwards of": "gt", ">": "gt",
    "at least": "ge", "no less than": "ge", "not less than": "ge", ">=": "ge", "≥": "ge", "minimum of": "ge",
    "below": "lt", "under": "lt", "less than": "lt", "lower than": "lt", "smaller than": "lt", "<": "lt",
    "at most": "le", "no more than": "le", "not more than": "le", "up to": "le", "<=": "le", "≤": "le",
    "maximum of": "le",
    "about": "approx", "around": "approx", "roughly": "approx", "approximately": "approx", "approx": "approx",
    "approx.": "approx", "~": "approx", "≈": "approx", "circa": "approx", "nearly": "approx", "close to": "approx",
    "near": "approx", "exactly": "approx", "=": "approx", "equal to": "approx", "of about": "approx",
    "of around": "approx", "somewhere around": "approx", "in the region of": "approx",
    "in the neighbourhood of": "approx", "in the neighborhood of": "approx", "in the vicinity of": "approx",
    "short of": "lt", "shy of": "lt", "topping": "gt", "north of": "gt", "past": "gt", "south of": "lt",
    "in the ballpark of": "approx", "nigh on": "approx", "just about": "approx", "just around": "approx",
    "more or less": "approx", "roughly around": "approx", "hovering around": "approx", "hovers around": "approx",
    "somewhere near": "approx", "give or take": "approx",
}
_NEGATABLE = {
    "gt": ("above", "over", "greater than", "more than", "higher than", "bigger than", "larger than", "exceeding",
           "in excess of", "warmer than", "hotter than"),
    "lt": ("below", "under", "less than", "lower than", "smaller than", "colder than", "cooler than"),
}
COMPARATOR_PHRASES.update({
    "exceeds": "gt", "exceed": "gt", "exceeding": "gt", "surpasses": "gt", "surpassing": "gt", "beyond": "gt",
    "tops": "gt", "goes above": "gt", "is above": "gt", "rises above": "gt",
    "greater than or equal to": "ge", "more than or equal to": "ge", "higher than or equal to": "ge",
    "equal to or greater than": "ge", "equal to or more than": "ge", "equal to or higher than": "ge",
    "at or above": "ge", "a minimum of": "ge",
    "less than or equal to": "le", "lower than or equal to": "le", "equal to or less than": "le",
    "equal to or lower than": "le", "at or below": "le", "a maximum of": "le",
    "does not exceed": "le", "doesn't exceed": "le", "not exceed": "le", "never exceeds": "le",
    "not exceeding": "le", "does not go above": "le", "doesn't go above": "le",
    "does not drop below": "ge", "doesn't drop below": "ge", "never drops below": "ge", "not dropping below": "ge",
    "beneath": "lt", "falls below": "lt", "falling below": "lt", "drops below": "lt", "dropping below": "lt",
    "stays below": "lt", "staying below": "lt", "does not reach": "lt", "doesn't reach": "lt", "not reaching": "lt",
    "never reaches": "lt", "stays above": "gt", "staying above": "gt", "goes over": "gt", "rising above": "gt",
    "does not fall below": "ge", "doesn't fall below": "ge", "never falls below": "ge", "not falling below": "ge",
    "does not go below": "ge", "doesn't go below": "ge",
})
# "never sinks beneath 20", "doesn't climb above 40": a reading that never passes a bound stays on its side of it.
_DOWN = (("sinks", "sink"), ("dips", "dip"), ("drops", "drop"), ("falls", "fall"), ("slips", "slip"), ("goes", "go"),
         ("gets", "get"))
_UP = (("rises", "rise"), ("climbs", "climb"), ("goes", "go"), ("gets", "get"), ("creeps", "creep"),
       ("strays", "stray"))
for _neg, _form in (("never", 0), ("does not", 1), ("doesn't", 1), ("won't", 1), ("will not", 1)):
    for _v in _DOWN:
        for _p in ("below", "beneath", "under"):
            COMPARATOR_PHRASES.setdefault(f"{_neg} {_v[_form]} {_p}", "ge")
    for _v in _UP:
        for _p in ("above", "over", "beyond", "past"):
            COMPARATOR_PHRASES.setdefault(f"{_neg} {_v[_form]} {_p}", "le")
# "not above 20" -> le 20, "no lower than 55" -> ge 55 (thresholds only: comparatives live in COMPARATIVES).
for _code, _phrases in _NEGATABLE.items():
    for _p in _phrases:
        if _p in COMPARATOR_PHRASES:
            for _neg in ("not", "no") if _p.endswith("than") else ("not",):
                COMPARATOR_PHRASES.setdefault(f"{_neg} {_p}", "le" if _code == "gt" else "ge")
COMPARATOR_POSTFIX = {"or more": "ge", "or higher": "ge", "or above": "ge", "or greater": "ge", "or over": "ge",
                      "or less": "le", "or lower": "le", "or below": "le", "or under": "le", "and up": "ge",
                      "and above": "ge", "and below": "le",
                      "or thereabouts": "approx", "or so": "approx", "give or take": "approx", "and under": "le",
                      "at the very least": "ge", "at the least": "ge", "at the lowest": "ge", "at the highest": "le",
                      "at the most": "le", "at the very most": "le",
                      "or more or less": "approx", "or warmer": "ge", "or hotter": "ge", "or colder": "le",
                      "or cooler": "le", "or drier": "le", "or damper": "ge", "or more humid": "ge",
                      "or healthier": "ge", "or greener": "ge"}

NUMBER_WORDS = {
    "zero": 0, "nought": 0, "naught": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
    "eight": 8, "nine": 9,
    "ten": 10, "eleven": 11, "twelve": 12, "thirteen": 13, "fourteen": 14, "fifteen": 15, "sixteen": 16,
    "seventeen": 17, "eighteen": 18, "nineteen": 19, "twenty": 20, "thirty": 30, "forty": 40, "fifty": 50,
    "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90,
}

ORDINAL_WORDS = ("first", "next", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth",
                 "final", "last", "penultimate")
# Subordinate clauses that only sequence goals ("once you've finished there", "when you get there"): a segment
# opening with one of these words and naming nothing (no determiner) is dropped.
SUBORDINATORS = frozenset("once when whenever after upon having as soon if".split())
SUBJECT_PRONOUNS = frozenset("you you've you're you'll you'd we we've we're i i've i'm".split())
# Words that say someone is to attend a place ("your excellency is expected at the bureau", "the guests are awaited
# at the harp"): after "is" or "are" they make what precedes them an addressee, not a goal (`parser._attendance`).
ATTENDANCE = frozenset("expected awaited requested invited summoned wanted needed required due".split())

# Verbs and politeness that introduce a goal ("please head over to", "I need you to check").
LEAD_PHRASES = (
    "please", "kindly", "now", "ok", "okay", "hey", "so", "and", "also", "then", "next", "first of all", "first",
    "fourthly", "fifthly", "sixthly", "seventhly",
    "firstly", "to begin with", "to begin", "to start with", "to start", "second", "secondly", "third", "thirdly",
    "finally", "lastly", "last of all", "at the last", "at last", "at the end", "in the end", "last", "after that",
    "afterwards", "afterward", "subsequently",
    "from there", "once there", "after this", "plus", "but", "robot",
    "could you", "can you", "would you", "will you", "would you mind", "i'd like you to", "i would like you to",
    "i need you to", "i want you to", "i need to", "i want to", "i'd like to", "you should", "you need to",
    "you must", "you have to", "we need to", "let's", "lets", "make sure to", "make sure you", "be sure to",
    "try to", "go ahead and", "be so kind as to",
    "start at", "start with", "start by going to", "start by visiting", "start from", "start off at", "start",
    "begin at", "begin with", "begin by going to", "begin by visiting", "begin",
    "continue on to", "continue to", "continue towards", "continue toward", "continue with", "carry on to",
    "proceed to", "move on to", "go on to", "then on to", "on to", "onto",
    "finish at", "finish with", "finish by going to", "finish by visiting", "finish up at", "finish",
    "end at", "end up at", "end with", "end by visiting", "end", "stop at", "wrap up at", "conclude at",
    "once you have visited", "once you've visited", "after visiting", "after going to", "after checking",
    "after you visit", "after you check",
    # other politeness and framing: "your job is to", "i'd love it if you could", "it would be great if you could"
    "your job is to", "your task is to", "your mission is to", "your goal is to", "your assignment is to",
    "the job is to", "the task is to", "the goal is to", "the plan is to", "the mission is to",
    "i'd love it if you could", "i would love it if you could", "i'd love it if you would", "i'd love for you to",
    "i would love for you to", "i'd love you to", "i would love you to", "it would be great if you could",
    "it'd be great if you could", "it would be nice if you could", "it would help if you could",
    "i'd appreciate it if you could", "i would appreciate it if you could", "i'd be grateful if you could",
    "if you could", "if you would", "would you be able to", "are you able to", "do me a favour and",
    "do me a favor and", "i'd ask you to", "i ask you to", "you'll need to", "you will need to", "you are to",
    "you're to", "you ought to", "we'll", "we will", "let us", "it's time to", "time to", "i'd like for you to",
    "any chance you could", "any chance you can", "is there any chance you could", "is it possible for you to",
    "would it be possible for you to", "i was wondering if you could", "i was wondering if you'd",
    "do you think you could", "could you possibly", "can you please", "could you please", "would you please",
    # sequencing openers and closers: "to kick things off", "once you're done there", "wrap up with"
    "to kick things off", "to kick off", "kick things off at", "kick things off with", "kick off at",
    "kick off with", "first things first", "first up", "first off", "next up", "last but not least",
    "start off with", "start off by visiting", "start off by going to", "to start off", "to finish",
    "to finish off", "to finish up", "to wrap up", "to wrap things up", "to end", "wrap up with",
    "wrap up by visiting", "wrap things up at", "wrap things up with", "round off with", "round off at",
    "round things off at", "round things off with", "finish off at", "finish off with", "end off at",
    "wind up at", "once you're done there", "once you are done there", "once you're done", "once you are done",
    "when you're done there", "when you are done there", "when you're done", "when you are done",
    "once you're finished", "once you are finished", "when you're finished", "when you are finished",
    "once done", "once finished", "once that's done", "once that is done", "when that's done",
    "when that is done", "after that's done", "after that is done", "after you've done that",
    "after you have done that", "having done that", "with that done", "that done", "after you're done there",
    "follow that with", "follow this with", "follow up with", "follow it with", "go on to", "then go on to",
    "at the very end", "at the end", "and at the very end", "after which", "next stop", "final stop",
    "after you are done there",
    *(f"{d}{o} {n}{v}" for d in ("your ", "the ", "our ", "") for o in ORDINAL_WORDS
      for n in ("stop ", "destination ", "target ", "goal ", "waypoint ", "port of call ", "one ", "")
      for v in ("is", "should be", "will be", "must be", "has to be") if d or n),
    # the subject of an imperative or of a clause after "before"/"after": "before you head for the kiln"
    "you", "you can", "you could", "you may", "you might", "you will", "you'll", "you then", "then you",
    # "begin by tracking down", "would you mind checking": the -ing verb after these is dropped (parser)
    "begin by", "start by", "start off by", "finish by", "finish off by", "end by", "wrap up by", "kick off by",
    "round off by", "conclude by", "do you mind", "would you mind", "finish up by", "wind up by", "end up by",
    "start by", "begin by",
    # sequencing adverbs
    *ORDINAL_WORDS, "later", "later on", "eventually", "ultimately", "in the end", "to conclude", "to close",
    "to round off", "following that", "following this", "after which", "thereafter", "from there on",
)
# Leads after which a verb's -ing form follows ("begin by <verb>ing", "would you mind <verb>ing").
ING_LEADS = frozenset({"by", "mind"})
VERBS = (
    "report to", "attend to", "verify the condition of", "check the condition of", "inspect the condition of",
    "carry out a check on", "carry out an inspection of", "verify", "find your way to", "finding your way to", "find your way over to", "go round to", "going round to",
    "pull up at", "pulling up at", "pull up by", "head across to", "heading across to", "go", "going", "head", "heading", "walk", "walking", "run", "move", "moving", "drive", "driving", "travel",
    "navigate", "navigating", "proceed", "return", "come", "get", "getting", "make your way", "take me",
    "take us", "bring me", "guide me", "lead me", "show me", "visit", "visiting", "find", "finding", "locate",
    "locating", "search for", "searching for", "look for", "looking for", "seek", "check", "checking",
    "check on", "check out", "inspect", "inspecting", "examine", "look at", "approach", "reach", "reaching",
    "see", "seeing", "stop by", "swing by", "drop by", "pass by", "pay a visit to", "go and see", "go see",
    "go and check", "tour", "roll", "fly", "steer",
    "pop", "nip", "hop", "dash", "zip", "scoot", "wander", "stroll", "swing", "head on", "make a stop",
    "make a quick stop", "stop off", "stop in", "call in", "drop in on", "drop in", "look in on", "pass",
    "go past", "make for", "aim for", "track down", "seek out", "hunt down", "hunt for", "set off", "get yourself",
    "take yourself", "go visit", "go find", "go check", "go inspect", "arrive", "end up", "reach for",
    "popping", "nipping", "hopping", "dashing", "zipping", "scooting", "wandering", "strolling", "swinging",
    "making a stop", "stopping off", "stopping by", "dropping by", "passing", "heading", "making your way",
)
VERB_PARTICLES = ("over", "up", "down", "back", "across", "out", "straight", "directly", "quickly", "right", "on",
                  "along", "round", "past", "yourself", "itself", "around", "away")
VERB_PREPOSITIONS = ("to", "towards", "toward", "into", "for", "at", "by", "onto", "past")
TRAILING_FILLERS = (
    *ORDINAL_WORDS, "to begin with", "to start with", "to start", "to begin", "to finish", "to end with",
    "at the very end", "when you get a moment", "when you get a chance", "when you can", "of the lot",
    "please", "first", "last", "too", "again", "now", "afterwards", "afterward", "as well", "quickly", "thanks",
    "thank you", "then", "for me", "if you can", "if possible", "nearby", "next", "also", "straight away",
    "right away", "as soon as possible", "asap", "at the end", "at the start", "at the beginning",
    "of all", "of them all", "of all of them", "among them", "overall", "there", "over there", "in there", "itself",
    # "X comes first, then Y", "X is your last stop"
    *(f"{v} {o}" for v in ("comes", "goes", "is", "should come", "should be", "will be", "must be", "has to be")
      for o in (*ORDINAL_WORDS, "at the end", "after that", "in the middle")),
    *(f"{v} {d} {o} {n}" for v in ("is", "should be", "will be", "must be", "has to be") for d in ("your", "the")
      for o in ("first", "next", "second", "third", "final", "last") for n in ("stop", "destination", "goal")),
)


def is_modifier(word: str, next_word: str | None = None) -> bool:
    """True for a descriptive word that can precede a head noun ("red", "oak", "gold-framed")."""
    if word in MODIFIER_WORDS:
        return True
    if word in INTENSIFIERS:
        return next_word is not None and (next_word in COLOURS or next_word.split("-")[0] in COLOURS)
    if word.endswith("ish") and word[:-3] in COLOURS:
        return True
    if "-" in word and word.replace("-", " ") in PARTICIPLE_STATES:  # "switched-on", "plugged-in"
        return True
    if "-" in word:
        parts = word.split("-")
        if all(p in COLOURS or p in INTENSIFIERS for p in parts) and parts[-1] in COLOURS:
            return True
        tail = parts[-1]
        if len(parts) == 2 and parts[0] and (tail in HYPHEN_MODIFIER_TAILS or (len(tail) > 3 and tail.endswith("ed"))):
            return True
    return False


def is_room_phrase(words: list[str] | tuple[str, ...]) -> bool:
    """True when a noun phrase names a room ("kitchen", "living room", "office area")."""
    if not words:
        return False
    last = words[-1]
    return last in ROOM_WORDS or (last in ROOM_SUFFIXES and len(words) >= 2) or tuple(words) == ("room",)

# English closed-class words (articles, pronouns, prepositions, conjunctions, auxiliaries, number words,
# discourse particles) with the function-word tables above: none of them names an object, so a goal's head
# containing one is a misreading to repair against the memory's names (evaluation/grounding.py).
CLOSED_CLASS = frozenset(
    """a an the this that these those some any each every either neither no all both another other such what
    whatever which whichever who whom whose i me my mine you your yours he him his she her hers it its we us our
    ours they them their theirs myself yourself itself themselves one ones am is are was were be been being do
    does did done doing have has had having will would shall should can could may might must to of in on at by
    for from with without into onto upon about above across after against along among around before behind below
    beneath beside besides between beyond down during except inside near off out outside over past since through
    throughout till toward towards under underneath until unto up via within and or but nor so yet if then than
    because while whereas although though unless once when whenever where wherever whether not just only also too
    very really quite rather please kindly thanks thank okay ok um uh er erm like oh hey hi yes s t ll re ve d m
    hundred thousand point comma""".split()
) | DETERMINERS | PRONOUN_ANCHORS | TRUE_COPULAS | MODALS | SUBORDINATORS | SUBJECT_PRONOUNS | frozenset(
    NUMBER_WORDS) | frozenset(ORDINAL_WORDS) | frozenset(VERB_PARTICLES) | frozenset(VERB_PREPOSITIONS)
