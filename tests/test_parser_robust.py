"""The rule parser on phrasings the seen generator never writes: relative clauses and states, appositions and
parentheticals, comparatives and superlatives in other words, number, unit and coordinate formats, other
imperatives, sequencing and free-order phrases.

The held-out set (tests/data/heldout_phrasings.jsonl) was written by hand before the parser was extended for
it, with nouns the repository never uses; a goal agrees when its head, attributes (as strings), room,
location, sensor constraints and top-level relations (type, anchor head) all match.
"""

import json
import string
from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from ragnav_jax.language import lexicon as L
from ragnav_jax.language.parser import parse_instruction, words_to_number
from ragnav_jax.language.types import ParseError, SensorConstraint, validate_chain_dict

HELDOUT = Path(__file__).resolve().parent / "data" / "heldout_phrasings.jsonl"


def _close(a, b) -> bool:
    if a is None or b is None:
        return a is None and b is None
    return abs(a - b) <= 1e-3 * max(1.0, abs(a), abs(b))


def goal_differences(sg, g: dict) -> list[str]:
    """Differences between a parsed subgoal and a held-out goal ([] when they agree)."""
    t, out = sg.target, []
    if t.head != g["head"]:
        out.append(f"head {t.head!r} != {g['head']!r}")
    if sorted(t.attributes) != sorted(g["attributes"]):
        out.append(f"attributes {list(t.attributes)} != {g['attributes']}")
    if (sg.room or None) != g["room"]:
        out.append(f"room {sg.room!r} != {g['room']!r}")
    loc = None if sg.location is None else (sg.location.x, sg.location.y)
    if (loc is None) != (g["location"] is None) or (loc and not all(map(_close, loc, g["location"]))):
        out.append(f"location {loc} != {g['location']}")
    got = [(c.reading, c.comparator) for c in sg.sensors]
    want = [(c["reading"], c["comparator"]) for c in g["sensors"]]
    if got != want or not all(_close(a.value, b["value"]) for a, b in zip(sg.sensors, g["sensors"])):
        out.append(f"sensors {[c.to_dict() for c in sg.sensors]} != {g['sensors']}")
    rels = [(r.type, r.anchor.head) for r in t.relations]
    if rels != [(r["type"], r["anchor_head"]) for r in g["relations"]]:
        out.append(f"relations {rels} != {g['relations']}")
    return out


def row_differences(row: dict) -> list[str]:
    try:
        c = parse_instruction(row["text"])
    except ParseError as e:
        return [f"ParseError: {e}"]
    out = [] if c.order == row["order"] else [f"order {c.order} != {row['order']}"]
    if len(c.subgoals) != len(row["goals"]):
        return out + [f"{len(c.subgoals)} goals != {len(row['goals'])}: {[s.target.head for s in c.subgoals]}"]
    for i, (sg, g) in enumerate(zip(c.subgoals, row["goals"])):
        out += [f"goal {i}: {d}" for d in goal_differences(sg, g)]
    return out


def _heldout() -> list[dict]:
    return [json.loads(line) for line in HELDOUT.read_text().splitlines() if line.strip()]


def test_heldout_set_is_well_formed_and_covers_unseen_nouns():
    rows = _heldout()
    assert len(rows) >= 60
    for r in rows:
        assert set(r) == {"text", "order", "goals"} and r["order"] in ("strict", "free") and r["goals"]
        for g in r["goals"]:
            assert set(g) == {"head", "attributes", "room", "location", "sensors", "relations"}
    heads = {g["head"] for r in rows for g in r["goals"]}
    assert {"ironing board", "drum kit", "x-ray viewer", "ping-pong table", "hi-fi speaker", "sewing machine"} <= heads


def test_heldout_phrasings_agree():
    # 32 / 101 before this parser version, 98 / 101 with it; the three left are compounds whose first word is
    # a known adjective ("hot tub", "mint plant", "wood-fired oven"), read as attribute + head.
    rows = _heldout()
    failures = {r["text"]: d for r in rows if (d := row_differences(r))}
    assert len(rows) - len(failures) >= 0.95 * len(rows), json.dumps(failures, indent=1)


# ----------------------------------------------------------------------------------------------------
# 1. Relative clauses and states


def _goals(text: str) -> list[tuple]:
    c = parse_instruction(text)
    return [(s.target.head, sorted(s.target.attributes), s.room, [(r.type, r.anchor.head) for r in s.target.relations])
            for s in c.subgoals]


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Go to the hammock that is folded up.", [("hammock", ["folded"], None, [])]),
        ("Find the heat press that's switched off beside the easel.", [("heat press", ["switched off"], None, [("beside", "easel")])]),
        ("Find the heat press that is on the easel.", [("heat press", [], None, [("on", "easel")])]),  # relation
        ("Find the heat press on the easel, which is on.", [("heat press", ["switched on"], None, [("on", "easel")])]),
        ("Check the kiln that isn't lit, then the loom.", [("kiln", ["unlit"], None, []), ("loom", [], None, [])]),
        ("Go to the workbench that is made of oak.", [("workbench", ["oak"], None, [])]),
        ("Go to the trapdoor that is ajar.", [("trapdoor", ["ajar"], None, [])]),  # an adjective the lexicon lacks
        ("Go to that hammock that is open.", [("hammock", ["open"], None, [])]),
        ("Go to the plugged-in router and the switched on lava lamp.",
         [("router", ["plugged in"], None, []), ("lava lamp", ["switched on"], None, [])]),
        ("Go to the router switched off in the den.", [("router", ["switched off"], "den", [])]),
        ("Go to the karaoke machine which is currently running and is plugged in.",
         [("karaoke machine", ["plugged in", "running"], None, [])]),
    ],
)
def test_relative_clauses_and_states(text, expected):
    assert _goals(text) == expected


def test_a_clause_describes_the_nearest_noun():
    (sg,) = parse_instruction("Go to the lamp next to the futon that is grey.").subgoals
    assert sg.target.attributes == () and sg.target.relations[0].anchor.attributes == ("grey",)
    assert sg.target.phrase == "lamp"  # the phrase is the noun phrase before any clause


# ----------------------------------------------------------------------------------------------------
# 2. Appositions and parentheticals


@pytest.mark.parametrize(
    "text, expected",
    [
        ("Go to the boombox, the silver one, then the kayak.", [("boombox", ["silver"], None, []), ("kayak", [], None, [])]),
        ("Find the kayak (the one in the garage).", [("kayak", [], "garage", [])]),
        ("Find the kayak (near the door) and the paddle.", [("kayak", [], None, [("near", "door")]), ("paddle", [], None, [])]),
        ("Find the kayak, the kitchen one.", [("kayak", [], "kitchen", [])]),
        ("Go to the workbench (wooden).", [("workbench", ["wooden"], None, [])]),
        # a list, not an apposition: the second phrase clashes with the first (two colours, two relations)
        ("Go to the red kayak, the blue one and the green one.",
         [("kayak", ["red"], None, []), ("kayak", ["blue"], None, []), ("kayak", ["green"], None, [])]),
        ("Go to the kayak, the one near the door, and the one near the window.",
         [("kayak", [], None, [("near", "door")]), ("kayak", [], None, [("near", "window")])]),
        # a verb starts a new goal
        ("Go to the kayak, visit the blue one too.", [("kayak", [], None, []), ("kayak", ["blue"], None, [])]),
    ],
)
def test_appositions_and_parentheticals(text, expected):
    assert _goals(text) == expected


def test_parenthesised_coordinates_stay_coordinates():
    a, b = parse_instruction("Go to the kayak (2.5, -1) (the red one), then the paddle (the one at 3, 4).").subgoals
    assert (a.location.x, a.location.y) == (2.5, -1.0) and a.target.attributes == ("red",)
    assert (b.location.x, b.location.y) == (3.0, 4.0) and b.target.head == "paddle"


# ----------------------------------------------------------------------------------------------------
# 3. Comparatives and superlatives, 4. numbers and units


@pytest.mark.parametrize(
    "text, reading, comparator, value",
    [
        ("Go to the appliance that is the coldest.", "temperature_c", "min", None),
        ("Find whichever succulent is greenest.", "ndvi", "max", None),
        ("Go to the terrarium that reads the highest humidity of all.", "humidity_pct", "max", None),
        ("Go to the hotplate that reads more than 60 degrees.", "temperature_c", "gt", 60.0),
        ("Go to the hotplate running hotter than 60 °C.", "temperature_c", "gt", 60.0),
        ("Go to the hotplate sitting at 60 degrees.", "temperature_c", "approx", 60.0),
        ("Go to the humidor whose humidity exceeds 70 percent.", "humidity_pct", "gt", 70.0),
        ("Go to the hotplate with a temperature no lower than 55°C.", "temperature_c", "ge", 55.0),
        ("Go to the hotplate that is not above 20 degrees.", "temperature_c", "le", 20.0),
        ("Go to the hotplate that is no warmer than 20 degrees.", "temperature_c", "le", 20.0),
        ("Go to the fern with an NDVI greater than or equal to 0.5.", "ndvi", "ge", 0.5),
        ("Go to the freezer whose temperature does not exceed minus ten degrees.", "temperature_c", "le", -10.0),
        ("Go to the hotplate at sixty-five degrees.", "temperature_c", "approx", 65.0),
        ("Go to the hotplate at 65 ºC.", "temperature_c", "approx", 65.0),  # masculine ordinal, not a degree sign
        ("Go to the hotplate at 65 ˚C.", "temperature_c", "approx", 65.0),
        ("Go to the hotplate at about 65 deg C.", "temperature_c", "approx", 65.0),
        ("Go to the hotplate at 65 degrees Celsius.", "temperature_c", "approx", 65.0),
        ("Go to the hotplate at 149 degrees Fahrenheit.", "temperature_c", "approx", 65.0),
        ("Go to the humidor at 70%.", "humidity_pct", "approx", 70.0),
        ("Go to the humidor at seventy per cent.", "humidity_pct", "approx", 70.0),
        ("Go to the fern with an NDVI of 0.70.", "ndvi", "approx", 0.7),
        ("Go to the fern with an NDVI of .7.", "ndvi", "approx", 0.7),
    ],
)
def test_sensor_phrasings(text, reading, comparator, value):
    (sg,) = parse_instruction(text).subgoals
    assert len(sg.sensors) == 1 and sg.target.relations == () and sg.target.attributes == ()
    c = sg.sensors[0]
    assert (c.reading, c.comparator) == (reading, comparator)
    assert value is None and c.value is None or abs(c.value - value) < 1e-3
    assert sg.target.head in ("appliance", "succulent", "terrarium", "hotplate", "humidor", "fern", "freezer")


def test_number_words():
    assert words_to_number("sixty-five") == 65.0 and words_to_number("seventy") == 70.0
    assert words_to_number("two hundred and five") == 205.0 and words_to_number("zero point seven") == 0.7


# ----------------------------------------------------------------------------------------------------
# 5. Coordinates


@pytest.mark.parametrize(
    "hint",
    ["(3.5, 2)", "x=3.5, y=2", "at position 3.5, 2", "at the point x 3.5 y 2", "around (3.5 m, 2 m)",
     "at x: 3.5 and y: 2", "at coordinates x=3.5; y=2", "at (3.5 | 2)", "at 3.5/2", "at [3.5; 2]",
     "with an x coordinate of 3.5 and a y coordinate of 2", "at x = 3.5 m, y = 2 m", "located at (3.5 , 2.0)"],
)
def test_coordinate_formats(hint):
    (sg,) = parse_instruction(f"Go to the hat stand {hint}.").subgoals
    assert sg.target.head == "hat stand" and sg.target.relations == ()
    assert (sg.location.x, sg.location.y) == (3.5, 2.0)


@pytest.mark.parametrize("text", ["Go to the hat stand at (3.5 | abc).", "Go to the hat stand at x=3.5 y=abc."])
def test_unreadable_coordinates_still_raise(text):
    with pytest.raises(ParseError, match="coordinates"):
        parse_instruction(text)


# ----------------------------------------------------------------------------------------------------
# 6. Imperatives, sequencing, free order


@pytest.mark.parametrize(
    "text, heads, order",
    [
        ("Your job is to reach the hat stand.", ["hat stand"], "strict"),
        ("I'd love it if you could stop at the hat stand.", ["hat stand"], "strict"),
        ("Swing past the hat stand, then make a stop at the umbrella stand.", ["hat stand", "umbrella stand"], "strict"),
        ("Head for the hat stand and then pop over to the shoe horn.", ["hat stand", "shoe horn"], "strict"),
        ("Could you pop over to the hat stand?", ["hat stand"], "strict"),
        ("Start off at the hat stand; after that the shoe horn; wrap up with the key hook.",
         ["hat stand", "shoe horn", "key hook"], "strict"),
        ("The hat stand comes first, then the shoe horn.", ["hat stand", "shoe horn"], "strict"),
        ("Go to the hat stand. Once you're done there, the shoe horn.", ["hat stand", "shoe horn"], "strict"),
        ("Before anything else, visit the hat stand, and then the shoe horn.", ["hat stand", "shoe horn"], "strict"),
        ("Visit the shoe horn after the hat stand.", ["hat stand", "shoe horn"], "strict"),
        ("Your first stop is the hat stand; your final stop is the shoe horn.", ["hat stand", "shoe horn"], "strict"),
        ("The hat stand and the shoe horn \u2014 the order is your call.", ["hat stand", "shoe horn"], "free"),
        ("Visit the hat stand and the shoe horn in any sequence you like.", ["hat stand", "shoe horn"], "free"),
        ("Visit the hat stand and the shoe horn in whatever order works best.", ["hat stand", "shoe horn"], "free"),
        ("The hat stand and the shoe horn; you choose the order.", ["hat stand", "shoe horn"], "free"),
    ],
)
def test_imperatives_and_sequencing(text, heads, order):
    c = parse_instruction(text)
    assert [s.target.head for s in c.subgoals] == heads and c.order == order
    assert all(not s.target.attributes and not s.target.relations for s in c.subgoals)


# ----------------------------------------------------------------------------------------------------
# Properties over nouns the parser has never seen

_SYLLABLES = [c + v for c in "bdfgklmnprstvz" for v in "aeiou"]
_WORD = st.lists(st.sampled_from(_SYLLABLES), min_size=2, max_size=3).map("".join)
_NOUN = st.lists(_WORD, min_size=1, max_size=2).map(" ".join)
_STATES = [("switched on", "switched on"), ("switched off", "switched off"), ("turned on", "turned on"),
           ("turned off", "turned off"), ("plugged in", "plugged in"), ("unplugged", "unplugged"), ("lit", "lit"),
           ("unlit", "unlit"), ("running", "running"), ("idle", "idle"), ("folded", "folded"),
           ("unfolded", "unfolded"), ("open", "open"), ("closed", "closed"), ("empty", "empty"), ("full", "full"),
           ("on", "switched on"), ("off", "switched off")]
_CLAUSES = ["that is {}", "which is {}", "that's {}", "that is currently {}", "which is still {}", "who is {}"]


def _plain_head(noun: str) -> bool:
    """The noun alone reads back as itself and holds no verb of the lexicon (random syllables can spell a
    closed-class word, or a verb such as "move" that the clause rules read as one)."""
    try:
        (sg,) = parse_instruction(f"go to the {noun}").subgoals
    except (ParseError, ValueError):
        return False
    return sg.target.head == noun and not sg.target.attributes and not set(noun.split()) & set(L.VERBS)


_FAST = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@_FAST
@given(_NOUN, _NOUN, st.sampled_from(_STATES), st.sampled_from(_CLAUSES), st.booleans(), st.booleans())
def test_relative_clause_state_after_any_noun(noun, anchor, state, clause, commas, relation):
    assume(_plain_head(noun) and _plain_head(anchor) and noun != anchor)
    written, attr = state
    rel = f" next to the {anchor}" if relation else ""
    text = f"Go to the {noun}, {clause.format(written)},{rel} then the {anchor}." if commas else \
        f"Go to the {noun} {clause.format(written)}{rel}, then the {anchor}."
    a, b = parse_instruction(text).subgoals
    assert (a.target.head, a.target.attributes) == (noun, (attr,))
    assert [(r.type, r.anchor.head) for r in a.target.relations] == ([("next_to", anchor)] if relation else [])
    assert (b.target.head, b.target.attributes) == (anchor, ())


@_FAST
@given(_NOUN, _NOUN)
def test_on_before_a_noun_is_a_relation(noun, anchor):
    assume(_plain_head(noun) and _plain_head(anchor) and noun != anchor)
    (sg,) = parse_instruction(f"find the {noun} that is on the {anchor}").subgoals
    assert sg.target.head == noun and sg.target.attributes == ()
    assert [(r.type, r.anchor.head) for r in sg.target.relations] == [("on", anchor)]


@_FAST
@given(_NOUN, st.sampled_from(["black", "oak", "dark green", "striped"]), st.sampled_from(["{}, the {} one,", "{} (the {} one)"]))
def test_apposition_after_any_noun_is_one_goal(noun, attr, form):
    assume(_plain_head(noun))
    c = parse_instruction("Go to the " + form.format(noun, attr) + " then the sofa.")
    assert [(s.target.head, s.target.attributes) for s in c.subgoals] == [(noun, (attr,)), ("sofa", ())]


_COORD = st.decimals(min_value=-50, max_value=50, places=1).map(float)


@_FAST
@given(_NOUN, _COORD, _COORD, st.sampled_from(["({x}, {y})", "x={x}, y={y}", "at position {x}, {y}", "at ({x} m, {y} m)",
                                                "at x: {x} and y: {y}", "({x} | {y})", "at the point x {x} y {y}"]))
def test_coordinates_after_any_noun(noun, x, y, form):
    assume(_plain_head(noun))
    (sg,) = parse_instruction(f"go to the {noun} " + form.format(x=f"{x:g}", y=f"{y:g}")).subgoals
    assert sg.target.head == noun and (sg.location.x, sg.location.y) == (x, y)


@_FAST
@given(_NOUN, _COORD, _COORD, st.sampled_from(["@ ({x}, {y})", "@ {x}, {y}", "at x {x} / y {y}", "near x{x} y{y}",
                                                "at x {x} | y {y}"]))
def test_more_coordinate_forms_after_any_noun(noun, x, y, form):
    """Round 12: "@" for "at", a slash or bar between the axes, an axis written against its number."""
    assume(_plain_head(noun))
    (sg,) = parse_instruction(f"go to the {noun} " + form.format(x=f"{x:g}", y=f"{y:g}")).subgoals
    assert sg.target.head == noun and (sg.location.x, sg.location.y) == (x, y)


@_FAST
@given(st.lists(_NOUN, min_size=2, max_size=4, unique=True),
       st.sampled_from(["{k}/ the {n} ", "The {n} / ", "The {n}\n", "the {n}\n", "- the {n}\n", "{k}. The {n}\n"]),
       st.sampled_from(["", "Jobs for today:\n", "To do:\n", "Places to check: "]))
def test_list_layouts_give_one_goal_an_item(nouns, item, heading):
    """Round 12: a list written one item a line, with spaced slashes or with "1/" numbers is read item by item,
    and a heading before a colon names nothing."""
    assume(all(_plain_head(n) for n in nouns))
    text = heading + "".join(
        item.format(k=k + 1, n=n) for k, n in enumerate(nouns)).rstrip(" /\n")
    c = parse_instruction(text)
    assert [(s.target.head, s.target.attributes, s.location) for s in c.subgoals] == [(n, (), None) for n in nouns]


@pytest.mark.parametrize("text,heads", [("go to the red\nsofa and then the fridge", ["sofa"]),
                                        ("go to the\nfridge, then the lamp near\nthe bed", ["fridge", "lamp"]),
                                        ("the fern with an ndvi of 0.3 / 0.5", None)])
def test_a_wrapped_line_is_not_a_list(text, heads):
    """A line break inside a sentence (lower case, no determiner, or after a word that needs what follows) only
    wraps it; a slash between numbers stays out of the list rule."""
    c = parse_instruction(text)
    if heads is None:
        assert len(c.subgoals) >= 1 and c.subgoals[0].target.head.startswith("fern")
    else:
        assert [s.target.head for s in c.subgoals][: len(heads)] == heads
        assert len(c.subgoals) == 2


@pytest.mark.parametrize("text,heads,room,rel", [
    ("Go to the lily a few steps from the lounge.", ["lily"], None, "near"),
    ("Go to the lily from the lounge.", ["lily"], "lounge", None),
    ("Visit the kiln.\n\nKind regards,\nPat", ["kiln"], None, None),
    ("The kettle that's switched on\nThe toaster", ["kettle", "toaster"], None, None),
    ("Honey jar on the shelf", ["honey jar"], None, "on"),
    ("Love seat by the window, then the lamp", ["love seat", "lamp"], None, "by"),
    ("Dear, could you check the kettle?", ["kettle"], None, None)])
def test_round13_leaves_relations_and_names_alone(text, heads, room, rel):
    """Rounds 12-13: "from the ROOM" is the room only where no distance word stands before "from"; a closing and
    the name under it name nothing; a line ending in a state ("switched on") ends its item; a term of address goes
    only after "now", "ok", ... or before a comma ("honey jar" and "love seat" stay names)."""
    c = parse_instruction(text)
    assert [s.target.head for s in c.subgoals] == heads
    assert c.subgoals[0].room == room and [r.type for r in c.subgoals[0].target.relations] == ([rel] if rel else [])


_SOUP = st.sampled_from(
    (string.ascii_lowercase[:6] + " ").split() + "go to the a lamp that is which that's isn't not switched turned on off "
    "plugged in unplugged lit running open one ones , ( ) [ ] ; . - — and then the order is your call whichever "
    "hottest exceeds no lower than above 60 degrees ºc deg c per cent % ndvi .7 x= y= 3.5 / | m minus made of "
    "your job is to pop over make a stop comes first once you're done there before anything else ajar being "
    "shares a room with sharing where close by in vicinity of or thereabouts beneath begin by tracking would mind "
    "when you've finished all i need for you could it's has or next to — exactly that order which doesn't matter "
    "olive locked half full iron map position [ ]".split()
)


@settings(max_examples=800, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(_SOUP, max_size=25))
def test_fuzz_new_vocabulary_only_raises_parse_error(words):
    try:
        c = parse_instruction(" ".join(words))
    except ParseError:
        return
    validate_chain_dict(c.to_dict())
    assert all(s.target.head.strip() for s in c.subgoals)


# ----------------------------------------------------------------------------------------------------
# 7. General rules added against the development templates (invented nouns, not their sentences)


def _tree(t) -> str:
    """'phrase[attrs] <rel> (anchor ...)': the target as the agreement check compares it."""
    s = t.phrase + ("[" + ",".join(sorted(t.attributes)) + "]" if t.attributes else "")
    return s + "".join(f" <{r.type}> ({_tree(r.anchor)})" for r in t.relations)


def _trees(text: str) -> list[str]:
    return [_tree(s.target) for s in parse_instruction(text).subgoals]


@pytest.mark.parametrize(
    "text, expected",
    [
        # verbs of position, sharing and possession in relative clauses and after "and"
        ("Find the zorbel which shares a room with the quillet.", ["zorbel <in_room_with> (quillet)"]),
        ("Find the zorbel sharing the same room as the quillet.", ["zorbel <in_room_with> (quillet)"]),
        ("Find the zorbel in the room where the quillet is.", ["zorbel <in_room_with> (quillet)"]),
        ("Find the zorbel in the room where the quillet that is lit is.", ["zorbel <in_room_with> (quillet[lit])"]),
        ("Find the zorbel that lies next to the quillet and has a glimmet on it.",
         ["zorbel <next_to> (quillet) <with> (glimmet)"]),
        ("Find the zorbel, the teal one, perched on the quillet.", ["teal zorbel[teal] <on> (quillet)"]),
        ("Find the zorbel which can be found near the quillet.", ["zorbel <near> (quillet)"]),
        ("Find the zorbel close by the quillet, then the glimmet in the vicinity of the quillet.",
         ["zorbel <near> (quillet)", "glimmet <near> (quillet)"]),
        # "on or next to it", "on it or beside it": one relation to the pronoun, which names the anchor itself
        ("Find the zorbel with the quillet on or next to it.", ["zorbel <with> (quillet)"]),
        ("Find the zorbel which has the quillet on it or beside it, and the glimmet.", ["zorbel <with> (quillet)", "glimmet"]),
        # coordinated states and attributes continue the clause's noun, however deep it is
        ("Find the zorbel near the quillet that is teal and switched on, then the glimmet.",
         ["zorbel <near> (teal quillet[switched on,teal])", "glimmet"]),
        ("Find the zorbel that is lilac and closed, and the glimmet.", ["lilac zorbel[closed,lilac]", "glimmet"]),
        ("Find the zorbel that is lilac and open in the den.", ["lilac zorbel[lilac,open]"]),
        ("Find the zorbel which is ivory and shares a room with the quillet.", ["ivory zorbel[ivory] <in_room_with> (quillet)"]),
        # descriptive words after the noun join the phrase, states do not
        ("Go to the zorbel which is olive.", ["olive zorbel[olive]"]),
        ("Go to the zorbel that's locked and the quillet that is half full.", ["zorbel[locked]", "quillet[half full]"]),
        # a noun that is also a material ("iron") is a noun when no other noun follows it
        ("Go to the iron, the charcoal one, then the zorbel.", ["charcoal iron[charcoal]", "zorbel"]),
        ("Go to the iron.", ["iron"]),
        ("Go to the big, red zorbel.", ["big red zorbel[big,red]"]),
        # a pronoun subject describes the previous goal
        ("Go to the zorbel; it's next to the quillet.", ["zorbel <next_to> (quillet)"]),
        # dashes set off an apposition
        ("Go to the zorbel \u2014 the red one \u2014 and then the quillet.", ["red zorbel[red]", "quillet"]),
    ],
)
def test_general_clause_rules(text, expected):
    assert _trees(text) == expected


@pytest.mark.parametrize(
    "text, heads",
    [
        # framing that ends in "you" + a modal or "to"
        ("All I need is for you to scurry over to the zorbel.", ["zorbel"]),
        ("It would be wonderful if you could locate the zorbel.", ["zorbel"]),
        # -ing verbs the lexicon does not know, after "begin by", "would you mind"
        ("Begin by photographing the zorbel, carry on to the quillet and end by polishing the glimmet.",
         ["zorbel", "quillet", "glimmet"]),
        ("Would you mind dusting off the zorbel?", ["zorbel"]),
        ("Begin by dropping in at the zorbel, then the quillet.", ["zorbel", "quillet"]),
        # subordinate clauses: with an object it is a goal that comes first, without one it only sequences
        ("Once you've reached the zorbel, head to the quillet.", ["zorbel", "quillet"]),
        ("After you have inspected the zorbel, look for the quillet.", ["zorbel", "quillet"]),
        ("Look for the quillet after you have inspected the zorbel.", ["zorbel", "quillet"]),
        ("Before you scurry to the quillet, visit the zorbel.", ["zorbel", "quillet"]),
        ("Visit the zorbel before you make a stop at the quillet.", ["zorbel", "quillet"]),
        ("Once you have taken a look at the zorbel, visit the quillet.", ["zorbel", "quillet"]),
        ("Visit the zorbel. When you've finished there, scurry over to the quillet.", ["zorbel", "quillet"]),
        ("Visit the zorbel. As soon as you're done, the quillet.", ["zorbel", "quillet"]),
        ("If you don't mind, visit the zorbel.", ["zorbel"]),
        ("Visit the zorbel, then over to the quillet.", ["zorbel", "quillet"]),
        ("Your first stop is the zorbel, your second is the quillet, and your fifth is the glimmet.",
         ["zorbel", "quillet", "glimmet"]),
    ],
)
def test_general_imperatives_and_sequencing(text, heads):
    c = parse_instruction(text)
    assert [s.target.head for s in c.subgoals] == heads and c.order == "strict"
    assert all(not s.target.relations for s in c.subgoals)


@pytest.mark.parametrize(
    "text, order",
    [
        ("Visit the zorbel and the quillet. Which one comes first doesn't matter.", "free"),
        ("Visit the zorbel and the quillet; it does not matter which you visit first.", "free"),
        ("Visit the zorbel and the quillet, in exactly that order.", "strict"),
        ("In this exact order, visit the zorbel and the quillet.", "strict"),
        ("Visit the zorbel and the quillet one after another.", "strict"),
        # a negation alone is no indifference: it forbids disorder, unless it negates emphasis
        ("Visit the zorbel, then the quillet; no station out of sequence.", "strict"),
        ("Visit the zorbel, then the quillet. Do not alter the order.", "strict"),
        ("Visit the zorbel and the quillet in no particular order.", "free"),
        ("Visit the zorbel and the quillet; the order is not important.", "free"),
        ("Visit the zorbel and the quillet; the order makes no difference.", "free"),
    ],
)
def test_order_phrases_are_removed(text, order):
    c = parse_instruction(text)
    assert [s.target.phrase for s in c.subgoals] == ["zorbel", "quillet"] and c.order == order


@pytest.mark.parametrize(
    "text, reading, comparator, value",
    [
        ("Go to the zorbel with an NDVI of 0.14 or thereabouts.", "ndvi", "approx", 0.14),
        ("Go to the zorbel that reads 45 deg C or above.", "temperature_c", "ge", 45.0),
        ("Go to the zorbel with a humidity beneath 30 percent.", "humidity_pct", "lt", 30.0),
        ("Go to the zorbel whose NDVI falls below 0.5.", "ndvi", "lt", 0.5),
        ("Go to the zorbel whose temperature does not reach 20 degrees.", "temperature_c", "lt", 20.0),
    ],
)
def test_more_sensor_wordings(text, reading, comparator, value):
    (sg,) = parse_instruction(text).subgoals
    assert sg.target.phrase == "zorbel" and [(c.reading, c.comparator, c.value) for c in sg.sensors] == [
        (reading, comparator, value)]


@pytest.mark.parametrize("hint", ["at map position [3.5, 2]", "in the vicinity of (3.5, 2)", "close by (3.5, 2)"])
def test_more_coordinate_leads(hint):
    (sg,) = parse_instruction(f"Go to the zorbel {hint}.").subgoals
    assert sg.target.relations == () and (sg.location.x, sg.location.y) == (3.5, 2.0)


@_FAST
@given(_NOUN, _NOUN, st.sampled_from(["shares a room with", "sits next to", "stands beside", "lies near", "is close by",
                                      "can be found near", "has"]),
       st.sampled_from(["that {}", "which {}", "and {}"]))
def test_relative_clause_after_any_noun(noun, anchor, verb, form):
    assume(_plain_head(noun) and _plain_head(anchor) and noun != anchor)
    lead = "that is teal " if form.startswith("and") else ""
    (sg,) = parse_instruction(f"Go to the {noun} {lead}{form.format(verb)} the {anchor}.").subgoals
    rtype = {"shares a room with": "in_room_with", "sits next to": "next_to", "stands beside": "beside",
             "has": "with"}.get(verb, "near")
    assert sg.target.head == noun and [(r.type, r.anchor.phrase) for r in sg.target.relations] == [(rtype, anchor)]


@_FAST
@given(_NOUN, _NOUN, st.sampled_from(["once you've finished there", "when you are done", "after that",
                                      "once you have reached the {a}", "when you get to the {a}"]))
def test_sentence_initial_subordinate_clause(noun, anchor, clause):
    assume(_plain_head(noun) and _plain_head(anchor) and noun != anchor)
    text = f"Visit the {anchor}. {clause.format(a=anchor).capitalize()}, scurry over to the {noun}."
    assert [s.target.head for s in parse_instruction(text).subgoals] == (
        [anchor, anchor, noun] if "{a}" in clause else [anchor, noun])


ROUNDS = sorted((Path(__file__).resolve().parent / "data").glob("round*_phrasings.jsonl"))


@pytest.mark.parametrize("path", ROUNDS, ids=[p.stem for p in ROUNDS])
def test_later_round_constructions_agree(path):
    """The general constructions of parser rounds 3 to 10 (list markers, arrows, time adverbs, apposition
    markers, light verbs, headings, participle clauses about the previous goal, axis, slash and brace
    coordinates, superlatives over a plural, possessive rooms, object relatives, rooms of other objects,
    thresholds against a "mark", order said in other words, greetings and courtesies, speech transcripts,
    formal task notes, chat shorthand, bracketed states and rooms, remarks about the order read by their cue
    words; round 10: bare coordinate pairs after a place word, "after that the X by it", "start in the ROOM at
    the X", "the healthier of the two Xs", property nouns ("with the walnut finish"), "both Xs" and "the two Xs"
    as two goals, "there's a X", "which X is Y? go to that one", a room before the goal, "either order") on
    hand-written sentences with nouns no generator writes."""
    rows = [json.loads(line) for line in path.read_text().splitlines() if line.strip()]
    assert len(rows) >= 15
    for row in rows:
        for g in row["goals"]:
            for c in g["sensors"]:
                c.setdefault("value", None)
    bad = {row["text"]: d for row in rows if (d := row_differences(row))}
    assert not bad, bad


@pytest.mark.parametrize("text", ["Go to the lamp, then the sofa or the armchair, whichever is closer.",
                                  "Visit either the kettle or the toaster.",
                                  "Check the fern or the palm, whichever of the two is nearer"])
def test_a_choice_between_objects_is_a_clear_error(text):
    """A task chain holds goals, not alternatives: a choice is refused with a message that names it (rather
    than read as a goal called "is closer")."""
    with pytest.raises(ParseError, match="choice between objects"):
        parse_instruction(text)
    chain = parse_instruction("Go to the kettle with the toaster either on it or beside it.")
    assert [sg.target.head for sg in chain.subgoals] == ["kettle"]


@pytest.mark.parametrize("text,head,rel", [("Go to the one in front of the sofa, then the lamp.", "one", "in_front_of"),
                                           ("Go to the box for maintenance tools.", "box for maintenance tools", None)])
def test_later_rounds_leave_ordinary_phrases_alone(text, head, rel):
    """'the one in front of X' is not a superlative's scope, and 'for maintenance' inside a noun phrase is no
    purpose remark."""
    sg = parse_instruction(text).subgoals[0]
    assert sg.target.head == head
    assert [r.type for r in sg.target.relations] == ([rel] if rel else [])


# ----------------------------------------------------------------------------------------------------
# Round 15: items run together (a symbol the parser gives no meaning to, or no word at all between them)

_ITEMS = ["samovar", "hatstand", "gramophone", "spinning wheel", "tea caddy", "weather vane", "music box", "loom"]


@settings(max_examples=60, deadline=None)
@given(items=st.lists(st.sampled_from(_ITEMS), min_size=2, max_size=4, unique=True),
       sep=st.sampled_from(["|", "~", ">", "#", "+", "✓", "⇒", "»", "×", "||", "~>", ";", "•", "->"]),
       article=st.booleans())
def test_a_symbol_between_items_separates_them(items, sep, article):
    """A symbol standing alone between two items never joins their words into one name: each item is a goal."""
    text = f" {sep} ".join(("the " if article else "") + x for x in items)
    assert [s.target.head for s in parse_instruction(text).subgoals] == items


@pytest.mark.parametrize("text, reading", [("the samovar with temp > 20 degrees", ("temperature_c", "gt", 20.0)),
                                           ("the samovar with temp > twenty degrees", ("temperature_c", "gt", 20.0)),
                                           ("the fern, ndvi < 0.4", ("ndvi", "lt", 0.4))])
def test_a_comparator_before_a_number_stays_a_comparator(text, reading):
    (sg,) = parse_instruction(text).subgoals
    assert [(c.reading, c.comparator, c.value) for c in sg.sensors] == [reading]


@settings(max_examples=40, deadline=None)
@given(items=st.lists(st.sampled_from(_ITEMS), min_size=2, max_size=4, unique=True),
       glue=st.sampled_from(["", " also", " too", " additionally"]))
def test_items_with_no_word_between_are_two_goals(items, glue):
    """'the loom the music box': a noun phrase holds no article after its noun, so a second article starts the
    next item (a glue word before it is not part of the name)."""
    text = f"{glue} ".join(f"the {x}" for x in items)
    assert [s.target.head for s in parse_instruction(text).subgoals] == items


@pytest.mark.parametrize("text, heads", [
    ("the hatstand the oak one near the umbrella bin", [("hatstand", ["oak"])]),   # an apposition, not two goals
    ("the loom in the attic the spinning wheel", [("loom", []), ("spinning wheel", [])]),
    ("in the attic the loom by the window", [("loom", [])]),                          # a room first is the room
])
def test_run_together_items_and_appositions(text, heads):
    assert [(s.target.head, sorted(s.target.attributes)) for s in parse_instruction(text).subgoals] == heads


@pytest.mark.parametrize("text", ["go to the room the samovar is in", "the chair the cat sleeps on",
                                  "there's the samovar, could you find it?", "the garage for the gramophone",
                                  "the ivory kettle in same room as the samovar"])
def test_an_article_after_a_function_word_or_before_an_object_relative_splits_nothing(text):
    """Only an article straight after a noun's words starts a second item: not after 'as', 'for', "there's",
    nor where the second noun phrase is an object relative ('the room the samovar is in')."""
    assert len(parse_instruction(text).subgoals) == 1


# ----------------------------------------------------------------------------------------------------
# Round 16 (developed on set O after its fresh runs): brackets after an anchor, axis after each number, "stood"


def _anchors(text: str) -> list[tuple]:
    return [(s.target.head, [(r.type, r.anchor.head, r.anchor.attributes, [(q.type, q.anchor.head) for q in r.anchor.relations])
                             for r in s.target.relations]) for s in parse_instruction(text).subgoals]


@pytest.mark.parametrize("text, expected", [
    ("the samovar by the hatstand (the one near the door), then the loom",
     [("samovar", [("by", "hatstand", (), [("near", "door")])]), ("loom", [])]),
    ("the samovar next to the shelves (the ones a few steps from the loom)",
     [("samovar", [("next_to", "shelves", (), [("near", "loom")])])]),
    ("the samovar by the hatstand (the oak one)", [("samovar", [("by", "hatstand", ("oak",), [])])]),
    ("the fern (the one by the window)", [("fern", [("by", "window", (), [])])]),   # no anchor before: the goal's
    ("the samovar by the hatstand (teal), then the loom", [("samovar", [("by", "hatstand", ("teal",), [])]),
                                                           ("loom", [])]),
    ("the samovar (teal) by the hatstand", [("samovar", [("by", "hatstand", (), [])])]),
    # the anchor's noun said again in the bracket, after words that say nothing or straight away
    ("the samovar by the hatstand (to be precise, the oak hatstand near the door); the loom",
     [("samovar", [("by", "hatstand", ("oak",), [("near", "door")])]), ("loom", [])]),
    ("the samovar by the hatstand (the hatstand by the door)", [("samovar", [("by", "hatstand", (), [("by", "door")])])]),
])
def test_brackets_straight_after_an_anchor_describe_the_anchor(text, expected):
    assert _anchors(text) == expected


@pytest.mark.parametrize("text, expected", [
    ("the samovar by the hatstand - the one near the door - and the loom",
     [("samovar", [("by", "hatstand", (), [("near", "door")])]), ("loom", [])]),
    ("the samovar next to the shelves, the ones a few steps from the loom; the kettle",
     [("samovar", [("next_to", "shelves", (), [("near", "loom")])]), ("kettle", [])]),
    # the same words as a new goal: led by an order word, or with a word of its own, or after a goal with no anchor
    ("the samovar by the hatstand, then the one near the door",
     [("samovar", [("by", "hatstand", (), [])]), ("samovar", [("near", "door", (), [])])]),
    ("the red samovar by the hatstand, the blue one near the door",
     [("samovar", [("by", "hatstand", (), [])]), ("samovar", [("near", "door", (), [])])]),
    ("the fern - the one by the window -", [("fern", [("by", "window", (), [])])]),
])
def test_the_one_with_only_a_relation_after_an_anchor_describes_the_anchor(text, expected):
    assert _anchors(text) == expected


@pytest.mark.parametrize("det", ["the", "whichever", "any"])
@pytest.mark.parametrize("holds", ["holds", "that has", "which also contains", "housing", "with"])
def test_a_room_picked_out_by_what_it_holds_is_the_same_room(det, holds):
    (sg,) = parse_instruction(f"the teal samovar in {det} room {holds} the loom").subgoals
    assert (sg.target.head, sg.room, [(r.type, r.anchor.head) for r in sg.target.relations]) == (
        "samovar", None, [("in_room_with", "loom")])


@settings(max_examples=40, deadline=None)
@given(quantified=st.sampled_from(["pick up every one", "so long as each one is checked", "and the last one",
                                   "just the one", "tick off every one in the book"]),
       sep=st.sampled_from([". ", ", ", "; "]), n=st.integers(1, 3))
def test_every_one_and_the_last_one_name_no_goal_of_their_own(quantified, sep, n):
    """'every one', 'each one', 'the last one': the goals said elsewhere, counted or put in order; an elided
    phrase with words of its own is still a goal."""
    nouns = ["samovar", "hatstand", "loom"][:n]
    text = "visit " + ", then ".join(f"the {w}" for w in nouns) + sep + quantified
    assert [s.target.head for s in parse_instruction(text).subgoals] == nouns
    assert [s.target.head for s in parse_instruction(f"the red samovar{sep}the blue one").subgoals] == [
        "samovar", "samovar"]


@pytest.mark.parametrize("text, xy", [("the samovar at 11.8 m on x and 4.4 m on y", (11.8, 4.4)),
                                      ("the samovar 3 metres along the x axis and 2 metres along the y axis", (3.0, 2.0)),
                                      ("the samovar at 7.9 along and 8.5 up", (7.9, 8.5)),
                                      ("the samovar at 2 across, 3 up", (2.0, 3.0))])
def test_each_number_followed_by_its_axis(text, xy):
    (sg,) = parse_instruction(text).subgoals
    assert sg.target.head == "samovar" and (sg.location.x, sg.location.y) == xy


def test_stood_before_a_relation_is_no_part_of_the_name():
    assert _anchors("the samovar stood by the hatstand") == [("samovar", [("by", "hatstand", (), [])])]


@settings(max_examples=60, deadline=None)
@given(st.from_regex(r"[bdfglmnprstvz][aeiou][bdfglmnprstvz]{1,2}", fullmatch=True), st.sampled_from(["ed", "ing"]),
       st.sampled_from(["next to", "beside", "by", "near", "under"]))
def test_a_participle_no_lexicon_knows_leads_a_relation(stem, suffix, rel):
    """'the sofa snuggled next to the lamp', 'the sofa hovering by the lamp': a participle between a noun and its
    relation is a relative-clause word like 'sitting', whatever the verb."""
    verb = stem + suffix
    assume(verb not in L.CLOSED_CLASS and not any(verb in p.split() for p in (*L.STATE_PHRASES, *L.RELATION_PHRASES)))
    sgs = parse_instruction(f"Go to the sofa {verb} {rel} the lamp, then the fridge.").subgoals
    assert [s.target.head for s in sgs] == ["sofa", "fridge"]
    assert [r.anchor.head for r in sgs[0].target.relations] == ["lamp"]


@pytest.mark.parametrize("text,head,state", [
    ("Go to the daybed beside the easel.", "daybed", None),  # a name that ends like a participle
    ("Go to the olive daybed beside the easel.", "daybed", None),
    ("Go to the painting above the fireplace.", "painting", None),
    ("Go to the lamp switched on next to the sofa.", "lamp", "switched on"),  # a state, not a clause word
])
def test_names_and_states_that_end_like_participles_stay_what_they_are(text, head, state):
    (sg,) = parse_instruction(text).subgoals
    assert sg.target.head == head and len(sg.target.relations) == 1
    assert (state in sg.target.attributes) if state else True


_READINGS = {"temperature": "temperature_c", "temp": "temperature_c", "NDVI": "ndvi", "humidity": "humidity_pct"}


@settings(max_examples=60, deadline=None)
@given(reading=st.sampled_from(sorted(_READINGS)), lead=st.sampled_from(["whose", "with a", "with its"]),
       verb=st.sampled_from(["", "is ", "comes out ", "reads "]),
       way=st.sampled_from([("higher", "max"), ("greater", "max"), ("lower", "min"), ("less", "min")]),
       others=st.sampled_from(["any other", "any other's", "all the others", "all the rest", "every other one",
                               "everything else", "the rest"]))
def test_a_reading_above_or_below_every_other_is_a_superlative(reading, lead, verb, way, others):
    """'whose NDVI is lower than any other', 'with a temp higher than all the rest': the least or the most, read
    as a superlative (no number is missing), and the next goal keeps its own words."""
    text = f"Go to the samovar, {lead} {reading} {verb}{way[0]} than {others}, then the hatstand."
    sgs = parse_instruction(text).subgoals
    assert [s.target.head for s in sgs] == ["samovar", "hatstand"]
    assert sgs[0].sensors == (SensorConstraint(_READINGS[reading], way[1]),) and sgs[1].sensors == ()


@pytest.mark.parametrize("text, sensor", [
    ("the samovar whose temperature beats all the others", ("temperature_c", "max")),
    ("the fern that leads every other on NDVI", ("ndvi", "max")),
    ("the fern whose NDVI trails all the rest", ("ndvi", "min")),
    ("the samovar that is warmer than all the others", ("temperature_c", "max")),
    ("the samovar (lowest temp of the lot)", ("temperature_c", "min")),
    ("the samovar with the highest temperature of any", ("temperature_c", "max")),
    ("the samovar whose thermometer reading is the lowest", ("temperature_c", "min")),
])
def test_outdoing_verbs_and_superlative_tails(text, sensor):
    (sg,) = parse_instruction(text).subgoals
    assert sg.target.head == text.split()[1] and sg.sensors == (SensorConstraint(*sensor),)


def test_a_comparison_with_a_named_group_keeps_its_words():
    """'lower than any other shelf' says nothing of a sensor: no reading is named and no comparative of one."""
    (sg,) = parse_instruction("the lamp that is lower than any other shelf").subgoals
    assert sg.target.head == "lamp" and sg.sensors == ()


@pytest.mark.parametrize("text, value", [("the fern whose NDVI is higher than nought point four", ("gt", 0.4)),
                                         ("the fern (ndvi: 0.4)", ("approx", 0.4)),
                                         ("the fern (NDVI score: 0.24 give or take)", ("approx", 0.24)),
                                         ("the samovar (temperature ≈ 22)", ("approx", 22.0)),
                                         ("the samovar whose temperature is nigh on 35", ("approx", 35.0))])
def test_more_ways_to_write_a_reading(text, value):
    (sg,) = parse_instruction(text).subgoals
    assert [(c.comparator, c.value) for c in sg.sensors] == [value]


@pytest.mark.parametrize("text, xy", [("the samovar at map reference x = 9.2, y = 0.1", (9.2, 0.1)),
                                      ("the samovar at grid ref 3.5, 2.0", (3.5, 2.0)),
                                      ("the samovar (x/y fix: 6.4, 0.4)", (6.4, 0.4)),
                                      ("the samovar (coords: 1, 2)", (1.0, 2.0))])
def test_a_labelled_pair_is_a_coordinate_hint(text, xy):
    (sg,) = parse_instruction(text).subgoals
    assert sg.target.head == "samovar" and (sg.location.x, sg.location.y) == xy and sg.target.relations == ()


@pytest.mark.parametrize("phrase", ["within a few paces of", "within a short stroll of", "within easy reach of",
                                    "handy for", "close at hand to"])
def test_distances_said_as_effort_are_near(phrase):
    (sg,) = parse_instruction(f"the samovar {phrase} the hatstand").subgoals
    assert [(r.type, r.anchor.head) for r in sg.target.relations] == [("near", "hatstand")]


@pytest.mark.parametrize("text, bound", [("the samovar whose temperature never sinks beneath 20 degrees", ("ge", 20.0)),
                                         ("the samovar whose temperature doesn't climb above 40", ("le", 40.0)),
                                         ("the fern whose NDVI won't dip below 0.5", ("ge", 0.5)),
                                         ("the fern whose NDVI never goes past 0.5", ("le", 0.5))])
def test_a_reading_that_never_passes_a_bound_stays_on_its_side(text, bound):
    (sg,) = parse_instruction(text).subgoals
    assert [(c.comparator, c.value) for c in sg.sensors] == [bound]


@pytest.mark.parametrize("lead", ["through", "along", "right there", "down"])
def test_an_adverb_before_a_room_leaves_the_room(lead):
    (sg,) = parse_instruction(f"the samovar {lead} in the scullery").subgoals
    assert (sg.target.head, sg.room) == ("samovar", "scullery")


def test_at_the_last_opens_a_goal_and_axes_may_read_their_numbers():
    sgs = parse_instruction("go first unto the samovar by the loom; and at the last repair unto the hatstand where "
                            "x reads 11.6 and y reads 4.8").subgoals
    assert [s.target.head for s in sgs] == ["samovar", "hatstand"]
    assert (sgs[1].location.x, sgs[1].location.y) == (11.6, 4.8) and sgs[1].target.relations == ()
    (sg,) = parse_instruction("the samovar at the spot whose x is 6.6 and whose y is 2.5").subgoals
    assert (sg.location.x, sg.location.y) == (6.6, 2.5)


@pytest.mark.parametrize("text, sensor", [
    ("the fern for which the NDVI is just about 0·63", ("ndvi", "approx", 0.63)),
    ("the samovar the temperature of which never sinks beneath 20 degrees", ("temperature_c", "ge", 20.0)),
    ("the samovar whose temperature is nigh on minus 23 on the Celsius scale", ("temperature_c", "approx", -23.0)),
    ("the fern whose vegetation index (NDVI) is in excess of .8", ("ndvi", "gt", 0.8)),
])
def test_readings_in_relative_clauses_and_other_typography(text, sensor):
    (sg,) = parse_instruction(text).subgoals
    assert sg.target.head == text.split()[1] and [(c.reading, c.comparator, c.value) for c in sg.sensors] == [sensor]


@pytest.mark.parametrize("text, rel", [("the samovar in a room together with the loom", "in_room_with"),
                                       ("the samovar in one room with the loom", "in_room_with"),
                                       ("the samovar bearing the loom", "with"),
                                       ("the samovar, carrying the loom", "with"),
                                       ("the samovar shoulder to shoulder with the loom", "next_to"),
                                       ("the samovar, immediately adjoining the loom", "next_to")])
def test_more_relation_phrases(text, rel):
    (sg,) = parse_instruction(text).subgoals
    assert (sg.target.head, sg.room, [(r.type, r.anchor.head) for r in sg.target.relations]) == (
        "samovar", None, [(rel, "loom")])


@settings(max_examples=40, deadline=None)
@given(a=st.sampled_from(sorted(L.COLOURS)), b=st.sampled_from(sorted(L.MATERIALS)),
       nxt=st.sampled_from(["thereafter the hatstand", "then the hatstand", "and the hatstand"]))
def test_describing_words_joined_by_and_describe_one_object(a, b, nxt):
    """'the typewriter, the retro and teal one, kept in the library': 'and' between describing words before a noun
    joins them; between states after a copula it still lists them."""
    sgs = parse_instruction(f"the samovar, the {a} and {b} one, kept in the scullery, {nxt}").subgoals
    assert [s.target.head for s in sgs] == ["samovar", "hatstand"]
    assert set(sgs[0].target.attributes) == {a, b} and sgs[0].room == "scullery"
    (sg,) = parse_instruction("the samovar that is open and full").subgoals
    assert set(sg.target.attributes) == {"open", "full"}


@pytest.mark.parametrize("text", ["the samovar (room: scullery), then the hatstand",
                                  "the samovar that is lacquered (room: scullery), then the hatstand",
                                  "the samovar [location - the scullery], then the hatstand"])
def test_a_labelled_room_field(text):
    sgs = parse_instruction(text).subgoals
    assert [(s.target.head, s.room) for s in sgs] == [("samovar", "scullery"), ("hatstand", None)]


@pytest.mark.parametrize("text, xy", [("the samovar pegged at x: 4.2, y: 9.4", (4.2, 9.4)),
                                      ("the samovar, at co-ords (10.4, 8.0)", (10.4, 8.0)),
                                      ("the samovar, at the spot marked x 11.7 and y 11.4", (11.7, 11.4))])
def test_more_ways_to_lead_a_coordinate_hint(text, xy):
    (sg,) = parse_instruction(text).subgoals
    assert sg.target.head == "samovar" and (sg.location.x, sg.location.y) == xy and sg.target.relations == ()


def test_itself_in_a_bracket_after_an_anchor_is_the_anchor():
    (sg,) = parse_instruction("the samovar near the loom (itself bearing the hatstand)").subgoals
    assert sg.target.head == "samovar" and [r.anchor.head for r in sg.target.relations] == ["loom"]
    assert [(r.type, r.anchor.head) for r in sg.target.relations[0].anchor.relations] == [("with", "hatstand")]


@pytest.mark.parametrize("remark", ["view each one only once the one before it has gone",
                                    "each only after the one called before it", "never ahead of the previous one"])
def test_the_one_before_it_names_no_goal(remark):
    """'the one before it' is another goal named by its place in the order: no goal takes the last goal's noun
    from it (the remark's other words are left to the tagger)."""
    sgs = parse_instruction(f"Go to the samovar, then the hatstand. {remark.capitalize()}.").subgoals
    assert [s.target.head for s in sgs][:2] == ["samovar", "hatstand"]
    assert not any("hatstand" in s.target.head or s.target.head.startswith("one") for s in sgs[2:])


@pytest.mark.parametrize("text, sensor", [("the most luxuriant fern", ("ndvi", "max", None)),
                                          ("the most shrivelled fern", ("ndvi", "min", None)),
                                          ("the samovar showing a temperature that is 40 at the lowest",
                                           ("temperature_c", "ge", 40.0))])
def test_more_words_for_plant_health_and_bounds(text, sensor):
    (sg,) = parse_instruction(text).subgoals
    assert [(c.reading, c.comparator, c.value) for c in sg.sensors] == [sensor]


def test_a_room_part_of_the_house_and_a_look():
    sgs = parse_instruction("the samovar in the scullery part of the house, then the hatstand, teal to look at, in the "
                            "den, and the loom within striking distance of the cot").subgoals
    assert [(s.target.head, s.room, s.target.attributes) for s in sgs] == [
        ("samovar", "scullery", ()), ("hatstand", "den", ("teal",)), ("loom", None, ())]
    assert [(r.type, r.anchor.head) for r in sgs[2].target.relations] == [("near", "cot")]


@settings(max_examples=40, deadline=None)
@given(words=st.lists(st.sampled_from(sorted(L.COLOURS | {"lacquered", "retro"})), min_size=1, max_size=2, unique=True))
def test_bare_describing_words_after_a_comma_describe_the_goal_before(words):
    """'the bicycle, cream, then the fern': no noun follows the words, so they are the bicycle's; 'the big, red
    chair' still describes the chair that follows."""
    sgs = parse_instruction(f"the samovar, {', '.join(words)}, then the hatstand").subgoals
    assert [s.target.head for s in sgs] == ["samovar", "hatstand"]
    assert set(sgs[0].target.attributes) == set(words) and sgs[1].target.attributes == ()
    sgs = parse_instruction("the samovar, then the big, red hatstand").subgoals
    assert sgs[0].target.attributes == () and set(sgs[1].target.attributes) == {"big", "red"}


@pytest.mark.parametrize("text", ["the samovar described as teal, in the scullery", "the samovar (tagged teal) in the "
                                  "scullery", "the samovar labelled as teal in the scullery"])
def test_a_label_of_describing_words_is_a_state(text):
    (sg,) = parse_instruction(text).subgoals
    assert (sg.target.head, sg.target.attributes, sg.room) == ("samovar", ("teal",), "scullery")


def test_a_telegram_stop_ends_a_clause():
    """'STOP' in capitals is a telegram's full stop: the room and the anchor end there. A 'stop' in lower case is a
    word like any other ('first stop: the samovar')."""
    chain = parse_instruction("Kindly call at the samovar in the scullery STOP thence to the loom near the cot STOP "
                              "thence to the hatstand STOP in sequence STOP")
    sgs = chain.subgoals
    assert chain.order == "strict" and [(s.target.head, s.room) for s in sgs] == [
        ("samovar", "scullery"), ("loom", None), ("hatstand", None)]
    assert [(r.type, r.anchor.head) for r in sgs[1].target.relations] == [("near", "cot")]
    assert [s.target.head for s in parse_instruction("first stop: the samovar, then the loom").subgoals] == [
        "samovar", "loom"]


def test_a_modal_or_a_subject_makes_the_unknown_word_after_it_a_verb():
    """'must muster at the loom': a modal (or 'we', 'you') names who acts, so the unknown word between it and the
    preposition is a verb, and the list after it splits as it does after any verb."""
    chain = parse_instruction("Must muster at the samovar near the cot, the loom in the scullery, and the hatstand.")
    assert [(s.target.head, s.room) for s in chain.subgoals] == [
        ("samovar", None), ("loom", "scullery"), ("hatstand", None)]
    assert [(r.type, r.anchor.head) for r in chain.subgoals[0].target.relations] == [("near", "cot")]
    assert [s.target.head for s in parse_instruction("Then off you trot to the samovar.").subgoals] == ["samovar"]


def test_order_words_after_a_clause_lead_the_next_goal():
    """'...the kiln that is lit; and last of all, the loom': 'last of all' says where the loom comes, so it is no
    part of the kiln's clause, and the kiln's text (which the learned readers read) ends at 'lit'."""
    sgs = parse_instruction("First the kiln that is lit; and last of all, the loom by the cot.").subgoals
    assert [(s.target.head, s.target.attributes) for s in sgs] == [("kiln", ("lit",)), ("loom", ())]
    assert sgs[0].text == "first the kiln that is lit"
    assert parse_instruction("the bin that is lilac and closed").subgoals[0].target.attributes == ("lilac", "closed")


def test_a_reading_after_an_unknown_verb_stays_with_its_goal():
    """'the kiln boasting the top air temperature reading': a noun phrase of a reading names no goal of its own,
    so the goal's span (which the sensor reader reads) keeps it."""
    sgs = parse_instruction("Go to the kiln boasting the top air temperature reading, then the loom.").subgoals
    assert len(sgs) == 2 and sgs[1].target.head == "loom"
    assert sgs[0].text.endswith("the top air temperature reading") and sgs[0].target.head.startswith("kiln")


def test_who_is_expected_at_a_place_is_no_goal():
    """'your excellency is expected at the loom': a few words, 'is' or 'are' and a word of attendance before a
    preposition say who is to go there; the goal is the loom. A goal said to be somewhere stays the goal ('the
    samovar is kept in the scullery')."""
    sgs = parse_instruction("Your Excellency is expected at the loom near the cot; the guests are awaited at the "
                            "warmest samovar.").subgoals
    assert [s.target.head for s in sgs] == ["loom", "samovar"]
    assert [(r.type, r.anchor.head) for r in sgs[0].target.relations] == [("near", "cot")]
    assert [s.target.head for s in parse_instruction("the samovar is kept in the scullery, then the loom").subgoals] == [
        "samovar", "loom"]


def test_a_one_word_sentence_is_no_goal_where_the_goals_have_determiners():
    """'...ring out to the samovar. Stand.': a sentence of one word with no determiner, where the instruction's goals
    have theirs, is a command or a sign-off. A list that drops its determiners drops them for every goal, and its
    one-word items stay goals."""
    assert [s.target.head for s in parse_instruction("Look to! Ring out to the samovar by the loom. Stand.").subgoals] == [
        "samovar"]
    assert [s.target.head for s in parse_instruction("samovar. loom. hatstand.").subgoals] == ["samovar", "loom", "hatstand"]
    assert [s.target.head for s in parse_instruction("Go to the samovar, then the loom and hatstand.").subgoals] == [
        "samovar", "loom", "hatstand"]


def test_an_instrument_read_off_names_the_reading():
    """'the samovar giving the highest reading on the thermometer', 'reading over 40 degrees on the thermometer':
    the instrument read off is the reading it gives (lexicon 'thermometer reading'), neither a goal nor an anchor;
    a verb of giving a reading ('giving', 'producing', 'logging') is no part of the noun."""
    sg, = parse_instruction("Go to the samovar in the scullery giving the highest reading on the thermometer.").subgoals
    assert (sg.target.head, sg.room, sg.target.relations) == ("samovar", "scullery", ())
    assert [(c.reading, c.comparator) for c in sg.sensors] == [("temperature_c", "max")]
    sg, = parse_instruction("Go to the loom reading over 40 degrees Celsius on the thermometer.").subgoals
    assert (sg.target.head, sg.target.relations) == ("loom", ())
    assert [(c.reading, c.comparator, c.value) for c in sg.sensors] == [("temperature_c", "gt", 40.0)]
    for verb in ("producing", "logging", "putting out", "giving off"):
        sg, = parse_instruction(f"Go to the samovar {verb} a temperature of 60 degrees.").subgoals
        assert sg.target.head == "samovar" and [c.value for c in sg.sensors] == [60.0]
    assert [s.target.head for s in parse_instruction("Check the hygrometer, then the loom.").subgoals] == [
        "hygrometer", "loom"]


def test_what_a_verb_ends_on_is_the_goal():
    """'...; and finish on the wheelbarrow': after a verb that leads a segment, 'on the X' is the goal, not a
    relation of the goal before; 'the lamp on the table' keeps its anchor."""
    sgs = parse_instruction("Pot the samovar (scullery); and finish on the loom in the attic.").subgoals
    assert [(s.target.head, s.room, s.target.relations) for s in sgs] == [("samovar", "scullery", ()),
                                                                          ("loom", "attic", ())]
    sg, = parse_instruction("Go to the samovar on the dresser.").subgoals
    assert [(r.type, r.anchor.head) for r in sg.target.relations] == [("on", "dresser")]


def test_a_labelled_reading_with_an_extreme_is_a_superlative():
    """'the fern (NDVI: the lowest going)', 'the samovar, temperature: highest': a reading given as a labelled field
    with an extreme is that reading's superlative; 'going' adds nothing ('the highest temperature going')."""
    for text in ("Go to the fern (NDVI: the lowest going), then the loom.", "Go to the fern, ndvi: lowest; then the loom."):
        sgs = parse_instruction(text).subgoals
        assert [s.target.head for s in sgs] == ["fern", "loom"]
        assert [(c.reading, c.comparator) for c in sgs[0].sensors] == [("ndvi", "min")]
    sg, = parse_instruction("Go to the samovar with the highest temperature going.").subgoals
    assert sg.target.head == "samovar" and [c.comparator for c in sg.sensors] == ["max"]
    sg, = parse_instruction("Go to the samovar (temperature: 40 degrees or more).").subgoals
    assert [(c.comparator, c.value) for c in sg.sensors] == [("ge", 40.0)]


@pytest.mark.parametrize("preamble", ["Big table, this one, and it all goes out together.", "THE GRAND TOUR",
                                      "Greetings from the seaside! Dear robot, could you do a round for us?",
                                      "The journey, in two stages:", "Morning all"])
@pytest.mark.parametrize("mark", ["•", "-", "1.", "(a)", "[ ]"])
def test_a_lists_preamble_names_no_goal(preamble, mark):
    """The lines before a list of marked items name the list, greet or set the scene: no goal, whatever its
    nouns ('big table', 'the journey'); a verb that sends the robot somewhere keeps its goal; without a list of
    two or more items, nothing changes."""
    items = "\n".join(f"{mark} the {h}" for h in ("samovar", "loom"))
    heads = [s.target.head for s in parse_instruction(f"{preamble}\n{items}").subgoals]
    assert heads == ["samovar", "loom"]
    heads = [s.target.head for s in parse_instruction(f"Please visit the kiln first, then:\n{items}").subgoals]
    assert heads == ["kiln", "samovar", "loom"]
    assert [s.target.head for s in parse_instruction(f"{preamble}\n{mark} the samovar").subgoals][-1] == "samovar"
