"""Held-out phrasings of set P: goal, sensor, coordinate and instruction templates for the `unseen` split.

Written before parser round 16 was measured and before any run of this set, by an author who never read the parser
(nor its lexicon, tagger, readings or grounding code, nor the evaluation code); set O, the held-out set before it,
moved to `unseen_dev12`. Same four functions, arguments and meanings as the other template sets. The style is four
people who send a home robot round a house in the layout and words of their own trade:

- an estate agent's viewing schedule: a header with the address, time slots ("10:05  the ..."), "Start: / Then: /
  Finish:" bullets or a chatty walk-through ("begin at ..., carry on through to ..., and wrap up at ..."), a
  sign-off with the agent's name and firm and now and then an aside about the clients; a fixed order as "the route
  is fixed", "please follow it exactly as laid out", "keep to that route"; a free one as "no set route, whatever
  flows best on the day", "the route's up to you", "in whichever sequence suits the layout";
- a film director's shot list or stage blocking: "SHOT LIST - SC. 12", numbered shots with shot types ("3. CLOSE-UP
  - the ..."), "ROBOT enters and crosses to ... Beat. ROBOT moves to ... ROBOT ends at ... Lights down."; fixed as
  "Shooting order: as numbered. Do not reshuffle.", "Blocking is locked: hit the marks in this exact sequence";
  free as "Shoot order: flexible", "it's a montage, so any order works - improvise the path";
- a lab technician's protocol: an SOP code, numbered steps and sub-steps ("2.3  Proceed to the ..."), lettered
  sampling points, "End of procedure."; fixed as "complete steps sequentially", "Sequence critical: perform in
  numerical order"; free as "sequence non-critical", "order of visits is not critical", "randomise if convenient";
- an Australian sports coach calling a drill: shouting, capitals, "Righto", "mate", "ya", stations ("Station 2 -
  the ..."), "GO GO GO"; fixed as "same order every rep", "in number order - no skipping", "stick to that order or
  it's laps"; free as "any order ya like", "mix it up, I don't care which ya hit first", "free-for-all".

Goals: attributes before the noun, in brackets after it ("the bean bag (teal, corduroy)"), between dashes, or as "a
teal corduroy one"; states before the noun ("the open toy chest", "the switched-on lamp"), or after it as "still
open", "currently switched off", "(status: empty)"; the room as "in the X", "out in the X", "through in the X",
"(room: X)" or "[X]", always before any relation; relations in new words ("within reach of", "in close proximity
to", "right up next to", "snug next to", "positioned beside", "hard by", "atop", "set on", "in under", "tucked
beneath", "mounted above", "housed in", "featuring", "complete with", "in the room that also holds", "in whichever
room has", "out in front of", "in behind", "over the way from", "off to the left of"); an anchor with relations of
its own takes them between dashes ("the credenza - the one featuring the record player -") or after "itself".
Readings: "gone past", "beyond", "sitting above", "or over", "not below", "no less than", "hasn't reached", "yet to
hit", "tops", "hasn't gone past", "not over", "capped at", "or thereabouts", "close on", "in the neighbourhood of",
"circa", "ballpark"; units "°C", "C", "deg.", "degrees", "%", "percent", "per cent"; numbers as digits, decimals,
".6" and words; superlatives "the hottest-running", "the most poorly", "the steamiest", "the clammiest", "with the
lowest temp going", "that tops the humidity readings", "at the bottom of the NDVI readings". Coordinates: "at
easting 3.5, northing 2", "at x-coord 3.5 and y-coord 2", "at x 3.5 by y 2", "at 3.5 m east, 2 m north", "at the
mark 3.5 across, 2 deep", sometimes in brackets; always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.phrasings import number_words
from ragnav_jax.language.phrasings_dev8 import is_plural, split_attributes
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "close by", "within reach of", "in close proximity to", "not far off"),
    "next_to": ("next to", "immediately next to", "right up next to", "snug next to"),
    "beside": ("beside", "positioned beside", "placed beside", "just there beside"),
    "by": ("by", "hard by", "down by", "positioned by"),
    "on": ("on", "atop", "set on", "sitting atop"),
    "under": ("under", "beneath", "in under", "tucked beneath"),
    "above": ("above", "just above", "mounted above", "up above"),
    "in": ("in", "inside", "within", "housed in"),
    "with": ("with", "featuring", "complete with", "that has"),
    "in_room_with": ("in the same room as", "in the room that also holds", "in whichever room has",
                     "in the room where you'll find"),
    "in_front_of": ("in front of", "just in front of", "out in front of", "standing in front of"),
    "behind": ("behind", "in behind", "tucked in behind", "just behind"),
    "opposite": ("opposite", "across from", "facing", "over the way from"),
    "left_of": ("to the left of", "off to the left of", "on the left of", "just left of"),
    "right_of": ("to the right of", "off to the right of", "on the right of", "just right of"),
}
# after "itself" / "the one": words that read as a predicate
_WITH_AFTER = ("with", "featuring", "complete with")


def _rel_words(rng, r: Relation, plural: bool, after: str = "") -> str:
    if r.type == "with" and after:
        return _pick(rng, _WITH_AFTER if after == "one" else _WITH_AFTER[1:])
    w = _pick(rng, REL_WORDS[r.type])
    return "that have" if plural and w == "that has" else w


def _states_before(states: list[str]) -> str:
    return ", ".join(s.replace(" ", "-") for s in states)


def _anchor(rng, t: Target, last: bool) -> str:
    """An anchor: 'the open credenza', 'the lamp (switched off)', and its own relations after dashes or 'itself':
    'the credenza - the one featuring the record player -', 'the shelves, themselves above the desk,'. When the
    anchor closes the goal (`last`) the closing mark is dropped."""
    _, states = split_attributes(t)
    if states and (t.relations or rng.uniform() < 0.7):
        s = f"the {_states_before(states)} {t.phrase}"
    elif states:
        s = f"the {t.phrase} ({' and '.join(states)})"
    else:
        s = f"the {t.phrase}"
    if not t.relations:
        return s
    plural = is_plural(t.head)
    if rng.uniform() < 0.55:
        inner = " and ".join(f"{_rel_words(rng, r, plural, 'one')} {_anchor(rng, r.anchor, False)}" for r in t.relations)
        return f"{s} — {'the ones' if plural else 'the one'} {inner}" + ("" if last else " —")
    inner = " and ".join(f"{_rel_words(rng, r, plural, 'itself')} {_anchor(rng, r.anchor, False)}" for r in t.relations)
    return f"{s}, {'themselves' if plural else 'itself'} {inner}" + ("" if last else ",")


def _relations(rng, t: Target) -> str:
    plural = is_plural(t.head)
    n = len(t.relations)
    parts = [f"{_rel_words(rng, r, plural)} {_anchor(rng, r.anchor, i == n - 1)}" for i, r in enumerate(t.relations)]
    out = parts[0] if parts else ""
    for p in parts[1:]:
        join = _pick(rng, (" and ", " and also ", ", plus "))
        out += (" " + join.lstrip(", ") if out.endswith(("—", ",")) else join) + p
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "out in the {}", "through in the {}", "(room: {})", "[{}]")


def render_goal_heldout(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set P writes it: 'the teal corduroy bean bag out in the nursery', 'the bean bag (teal, corduroy)
    [nursery]', 'the toy chest, still open,', 'the hottest-running kiln through in the craft room', 'the guitar at
    easting 3.5, northing 2', 'the lamp snug next to the credenza - the one featuring the record player'. The room
    comes before any relation; relations come last."""
    t = sg.target
    pre, states = split_attributes(t)
    plural = is_plural(t.head)
    head_words = t.phrase[len(t.phrase) - len(t.head):] if t.phrase.endswith(t.head) else t.head
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "before", "bracket", "dashes", "one"))
    state_style = None
    if states:
        opts = ["still", "currently", "status"]
        if not prefix and len(states) == 1 and attr_style != "one":
            opts += ["before", "before"]
        if attr_style == "bracket":
            opts.remove("status")
        state_style = _pick(rng, opts)
    out = "the " + (prefix + " " if prefix else "")
    if state_style == "before":
        out += _states_before(states) + " "
    out += t.phrase if attr_style == "before" else head_words
    if attr_style == "bracket":
        out += f" ({', '.join(pre)})"
    elif attr_style == "dashes":
        out += f" — {' and '.join(pre)} —"
    elif attr_style == "one":
        out += f", {'' if plural else 'a '}{' '.join(pre)} {'ones' if plural else 'one'},"
    if state_style in ("still", "currently"):
        out += f", {state_style} {' and '.join(states)},"
    elif state_style == "status":
        out += f" (status: {' and '.join(states)})"
    if hint:
        out += " " + (f"({hint[3:]})" if hint.startswith("at ") and rng.uniform() < 0.3 else hint)
    rooms = _ROOMS[:4] if attr_style == "bracket" or state_style == "status" else _ROOMS
    room = _pick(rng, rooms).format(sg.room) if sg.room else ""
    if tail:
        if room and rng.uniform() < 0.5:
            out += f" {room}, {tail}"
        else:  # a bracketed room closes the goal without a comma
            out += f" {tail}" + ((", " if room[:1].isalpha() else " ") + room if room else "")
    elif room:
        out += " " + room
    if t.relations:
        out += " " + _relations(rng, t)
    out = " ".join(out.replace(",,", ",").replace(", ,", ",").split())
    while out.endswith((",", "—")):
        out = out[:-1].rstrip()
    return out


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

_TEMP = {
    "gt": ("that's gone past {n}", "reading beyond {n}", "with a temp past {n}", "that's warmer than {n}",
           "sitting above {n}"),
    "ge": ("reading {n} or over", "that's not below {n}", "with a temperature of no less than {n}",
           "that's hit {n} or more"),
    "lt": ("that hasn't reached {n}", "that's yet to hit {n}", "reading less than {n}", "sitting below {n}",
           "that's cooler than {n}"),
    "le": ("reading {n} tops", "that hasn't gone past {n}", "that's not over {n}", "with the temperature capped at {n}"),
    "approx": ("at {n} or thereabouts", "reading close on {n}", "with a temperature in the neighbourhood of {n}",
               "at circa {n}", "reading ballpark {n}"),
}
_NAMED_TEMP = ("with a temp past", "with a temperature of", "with the temperature capped", "with a temperature in")
_HUM = {
    "gt": ("with humidity past {n}", "that's more humid than {n}", "with the humidity reading beyond {n}",
           "sitting above {n} humidity"),
    "ge": ("with humidity of {n} or over", "with humidity not below {n}", "with no less than {n} humidity"),
    "lt": ("with humidity that hasn't reached {n}", "with less than {n} humidity", "that's drier than {n}",
           "sitting below {n} humidity"),
    "le": ("with humidity of {n} tops", "with humidity capped at {n}", "with humidity that's not over {n}"),
    "approx": ("with humidity of {n} or thereabouts", "with humidity close on {n}",
               "with humidity in the neighbourhood of {n}", "at circa {n} humidity"),
}
_NDVI = {
    "gt": ("with an NDVI past {n}", "scoring beyond {n} on NDVI", "with an NDVI reading above {n}"),
    "ge": ("with an NDVI of {n} or over", "with an NDVI not below {n}", "scoring no less than {n} on NDVI"),
    "lt": ("with an NDVI that hasn't reached {n}", "with an NDVI of less than {n}", "scoring below {n} on NDVI"),
    "le": ("with an NDVI of {n} tops", "with an NDVI capped at {n}", "with an NDVI that's not over {n}"),
    "approx": ("with an NDVI of {n} or thereabouts", "with an NDVI close on {n}", "with an NDVI of circa {n}",
               "with a vegetation index in the neighbourhood of {n}"),
}
_OTHER = {  # any other reading: named, no unit
    "gt": ("with a {r} reading past {n}",), "ge": ("with a {r} reading of {n} or over",),
    "lt": ("with a {r} reading that hasn't reached {n}",), "le": ("with a {r} reading of {n} tops",),
    "approx": ("with a {r} reading of {n} or thereabouts",),
}
_T_UNITS = ("°C", " °C", " C", " deg.", " degrees", " degrees C")
_H_UNITS = ("%", " %", " percent", " per cent")
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "hottest", "hottest-running"),
    ("temperature_c", "min"): ("coldest", "coolest", "coldest-running"),
    ("ndvi", "max"): ("healthiest", "greenest", "most vigorous"),
    ("ndvi", "min"): ("least healthy", "most poorly", "least vigorous"),
    ("humidity_pct", "max"): ("most humid", "dampest", "steamiest", "clammiest"),
    ("humidity_pct", "min"): ("driest", "least humid", "least clammy"),
}
_SUPER_TAIL = {
    ("temperature_c", "max"): ("with the highest temp going", "that tops the temperature readings",
                               "that's reading warmest of all"),
    ("temperature_c", "min"): ("with the lowest temp going", "at the bottom of the temperature readings",
                               "that's reading coolest of all"),
    ("ndvi", "max"): ("with the highest NDVI going", "that tops the NDVI readings", "with the best vegetation index of all"),
    ("ndvi", "min"): ("with the lowest NDVI going", "at the bottom of the NDVI readings",
                      "with the poorest vegetation index of all"),
    ("humidity_pct", "max"): ("with the highest humidity going", "that tops the humidity readings",
                              "that's reading dampest of all"),
    ("humidity_pct", "min"): ("with the lowest humidity going", "at the bottom of the humidity readings",
                              "that's reading driest of all"),
}


def _number(rng, reading: str, value: float) -> tuple[str, float]:
    """(the number as written, its value): digits, a decimal, '.6', words for whole numbers, 'minus' for negatives."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    if reading == "ndvi":
        u = rng.uniform()
        if u < 0.25:
            return f"{v:.2f}", v
        if u < 0.45 and txt.startswith("0."):
            return txt[1:], v
        return txt, v
    if v == int(v):
        u = rng.uniform()
        if u < 0.2 and abs(v) < 100:
            return number_words(int(v)), v
        if u < 0.3:
            return f"{v:.1f}", v
        if v < 0 and u < 0.45:
            return f"minus {txt[1:]}", v
    return txt, v


def render_sensor_heldout(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('hottest-running', 'most poorly', 'clammiest') or a tail ('with the
    lowest temp going', 'that tops the humidity readings', 'at the bottom of the NDVI readings'); thresholds after
    the noun ('that hasn't gone past 60 °C', 'reading 40 % or over', 'with an NDVI close on .65', 'at circa
    twenty-one degrees')."""
    rd = c.reading
    if c.is_superlative:
        adj, tails = _SUPER_ADJ.get((rd, c.comparator)), _SUPER_TAIL.get((rd, c.comparator))
        if adj is None:
            name = rd.replace("_", " ")
            return "", f"with the {'highest' if c.comparator == 'max' else 'lowest'} {name} reading going", c
        if rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, tails), c
    n, value = _number(rng, rd, c.value)
    if rd == "ndvi":
        return "", _pick(rng, _NDVI[c.comparator]).format(n=n), SensorConstraint(rd, c.comparator, value, "")
    if rd == "temperature_c":
        form = _pick(rng, _TEMP[c.comparator])
        if form.startswith(_NAMED_TEMP) and rng.uniform() < 0.25:  # the reading is named: the unit may go
            return "", form.format(n=n), SensorConstraint(rd, c.comparator, value, "")
        u = _pick(rng, (" degrees", " degrees C")) if n[-1].isalpha() else _pick(rng, _T_UNITS)
        return "", form.format(n=n + u), SensorConstraint(rd, c.comparator, value, "c")
    if rd == "humidity_pct":
        u = _pick(rng, (" percent", " per cent")) if n[-1].isalpha() else _pick(rng, _H_UNITS)
        return "", _pick(rng, _HUM[c.comparator]).format(n=n + u), SensorConstraint(rd, c.comparator, value, "%")
    text = _pick(rng, _OTHER[c.comparator]).format(r=rd.replace("_", " "), n=n)
    return "", text, SensorConstraint(rd, c.comparator, value, "")


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_heldout(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at easting 3.5, northing 2', 'at x-coord 3.5 and
    y-coord 2', 'at x 3.5 by y 2', and, never for a negative number, 'at 3.5 m east, 2 m north' and 'at the mark
    3.5 across, 2 deep'."""
    forms = [f"at easting {x}, northing {y}", f"at x-coord {x} and y-coord {y}", f"at x {x} by y {y}"]
    if not x.startswith("-") and not y.startswith("-"):
        forms += [f"at {x} m east, {y} m north", f"at the mark {x} across, {y} deep"]
    return _pick(rng, forms)


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _bare(goal: str) -> str:
    return goal[4:] if goal.startswith("the ") else goal


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _listed(rng, res: list[str]) -> str:
    """Goals in a running sentence: commas, or semicolons where a goal has commas of its own."""
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


_STREETS = ("Marlowe Crescent", "Ashgrove Road", "Kestrel Lane", "Orchard Rise", "Tanners Walk")
_AGENTS = ("Jo", "Daniel", "Sunita", "Marcus", "Bea")
_FIRMS = ("Harcourt & Finch Residential", "Lowe Lettings", "Bramley Estates", "Castle & Quay Property")
_ASIDES = ("Clients are a young family, very keen on storage.", "Vendors are out until lunchtime.",
           "Mind the cat, she likes to slip out.", "Second viewing for these clients, so they know the layout.", "")


def _viewing(rng, res: list[str], order: str) -> str:
    """An estate agent's viewing schedule: address, time slots or bullets, a sign-off, sometimes an aside."""
    street, agent, firm = _pick(rng, _STREETS), _pick(rng, _AGENTS), _pick(rng, _FIRMS)
    sign = _pick(rng, (f"Thanks!\n{agent} — {firm}", f"Kind regards,\n{agent} ({firm})", f"Cheers, {agent}"))
    aside = _pick(rng, _ASIDES)
    aside = f"{aside}\n" if aside else ""
    if len(res) == 1:
        return _pick(rng, (f"Hi robot, before the clients arrive could you check on {res[0]} for me? {sign}",
                           f"Viewing prep, {street}: just the one feature to look at today, {res[0]}.\n{sign}"))
    num = int(rng.integers(2, 90))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            h, m, step = int(_pick(rng, (9, 10, 11, 14))), 0, int(_pick(rng, (5, 10, 15)))
            lines = []
            for r in res:
                lines.append(f"{h}:{m:02d}  {_cap(r)}")
                m += step
                h, m = h + m // 60, m % 60
            foot = _pick(rng, ("Please keep to the timings above; the route is fixed.",
                               "The route is fixed: the vendors have asked for it done in exactly this sequence."))
            return f"VIEWING SCHEDULE – {num} {street}\n" + "\n".join(lines) + f"\n{foot}\n{aside}{sign}"
        if k == 1:
            body = f"• Start: {res[0]}\n" + "".join(f"• Then: {r}\n" for r in res[1:-1]) + f"• Finish: {res[-1]}"
            return f"Route for the {street} viewing (please follow it exactly as laid out):\n{body}\n{aside}{sign}"
        s = f"Hi robot, walk-through for the {street} viewing please. Begin at {res[0]}"
        s += "".join(f", carry on through to {r}" for r in res[1:-1])
        s += f", and wrap up at {res[-1]}. Keep to that route, it's the one the vendors asked for. "
        return s + aside.replace("\n", " ") + sign
    k = int(rng.integers(3))
    if k == 0:
        body = "\n".join(f"★ {_cap(_bare(r))}" for r in res)
        return (f"Features to show at {num} {street} (no set route, whatever flows best on the day):\n{body}\n"
                f"{aside}{sign}")
    if k == 1:
        body = "\n".join(f"– {r}" for r in res)
        return f"Could you check over the following before the clients arrive? The route's up to you.\n{body}\n{sign}"
    return (f"Highlights to point out at {street}: {_listed(rng, res)}. Take them in whichever sequence suits the "
            f"layout. {aside.replace(chr(10), ' ')}{sign}")


_SHOTS = ("WIDE", "MID", "CLOSE-UP", "TRACKING", "INSERT", "OVER-THE-SHOULDER")
_SCENES = ("THE LONG WALK", "HOMECOMING", "NIGHT SHIFT", "THE INSPECTION")


def _shots(rng, res: list[str], order: str) -> str:
    """A film director's shot list, or the stage directions of one scene."""
    title = _pick(rng, _SCENES)
    if len(res) == 1:
        return _pick(rng, (f"ROBOT crosses to {res[0]}. Hold for a beat. Lights down.",
                           f"INSERT – {res[0]}. That's the only shot we need today, folks."))
    if order == "strict":
        if rng.uniform() < 0.5:
            sc = int(rng.integers(3, 60))
            lines = [f"{i + 1}. {_pick(rng, _SHOTS)} – {r}" for i, r in enumerate(res)]
            foot = _pick(rng, ("Shooting order: as numbered. Do not reshuffle.",
                               "We shoot these in script order, no exceptions."))
            return f"SHOT LIST – SC. {sc} “{title}” (INT. HOUSE – DAY)\n" + "\n".join(lines) + f"\n{foot}"
        s = f"ROBOT enters and crosses to {res[0]}. Beat."
        s += "".join(f" ROBOT {_pick(rng, ('moves to', 'heads to', 'drifts over to'))} {r}. Beat." for r in res[1:-1])
        s += f" ROBOT ends at {res[-1]}. Lights down."
        return s + " (Blocking is locked: hit the marks in this exact sequence.)"
    if rng.uniform() < 0.5:
        lines = [f"- {_pick(rng, _SHOTS)}: {r}" for r in res]
        return (f"SHOT LIST – B-ROLL, “{title}”\n" + "\n".join(lines)
                + "\nShoot order: flexible. Grab them in whatever order the light allows.")
    return (f"ROBOT wanders the set, stopping at {_listed(rng, res)}. "
            "(Director's note: it's a montage, so any order works. Improvise the path.)")


def _protocol(rng, res: list[str], order: str) -> str:
    """A lab technician's protocol: SOP code, numbered steps and sub-steps, lettered sampling points."""
    if len(res) == 1:
        return f"Procedure: proceed to {res[0]}. Log the arrival time.\nEnd of procedure."
    code = f"EV-{int(rng.integers(100, 999))}"
    verb = lambda: _pick(rng, ("Proceed to", "Locate", "Go to", "Attend to"))  # noqa: E731
    if order == "strict":
        if rng.uniform() < 0.5:
            sec = int(rng.integers(2, 6))
            lines = [f"{sec}.{i + 1}  {verb()} {r}." for i, r in enumerate(res)]
            return (f"SOP {code}: environmental sampling round\n{sec}. Procedure (complete steps sequentially; do not "
                    f"start a step until the previous one is signed off)\n" + "\n".join(lines) + "\nEnd of procedure.")
        lines = [f"{i + 1}. {verb()} {r}." for i, r in enumerate(res)]
        return "Method\n" + "\n".join(lines) + "\nSequence critical: perform in numerical order."
    letters = "abcdefgh"
    if rng.uniform() < 0.5:
        lines = [f"({letters[i]}) {r}" for i, r in enumerate(res)]
        return ("Sampling points (sequence non-critical):\n" + "\n".join(lines)
                + "\nVisit all points; the order of visits is not critical.")
    lines = [f"• {r}" for r in res]
    return (f"SOP {code}: the sampling points below may be visited in any order (randomise if convenient).\n"
            + "\n".join(lines))


def _coach(rng, res: list[str], order: str) -> str:
    """An Australian coach calling a drill: shouted, sometimes all in capitals."""
    if len(res) == 1:
        s = _pick(rng, (f"Oi! Sprint to {res[0]}! GO!", f"Righto, one rep: get to {res[0]} and touch it. Go go go!"))
    elif order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            s = (f"RIGHT, LISTEN UP! Shuttle drill. Sprint to {res[0]}" + "".join(f", then {r}" for r in res[1:])
                 + ". Same order every rep, no cutting corners! GO!")
        elif k == 1:
            s = "Station drill, people!\n" + "\n".join(f"Station {i + 1} – {r}" for i, r in enumerate(res))
            s += "\nWork through 'em in number order – no skipping, I'm watching!"
        else:
            s = f"Righto team, here's the go: hit {res[0]} first"
            s += "".join(f", then get yourselves to {r}" for r in res[1:-1])
            s += f", and finish at {res[-1]}. Stick to that order or it's laps, mate!"
    elif rng.uniform() < 0.5:
        s = f"Scatter drill! Tag {_listed(rng, res)}. Any order ya like, just get 'em all tagged! Go go go!"
    else:
        s = f"Righto, free-for-all: {_listed(rng, res)}. Mix it up, I don't care which ya hit first!"
    return s.upper() if rng.uniform() < 0.3 else s


def render_instruction_heldout(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (an estate agent's viewing schedule, a film
    director's shot list or blocking, a lab technician's protocol, an Australian coach calling a drill). Goals stay
    in visiting order; strict texts say the order is fixed ('the route is fixed', 'as numbered', 'complete steps
    sequentially', 'same order every rep'), free ones say it is open ('no set route', 'any order works', 'sequence
    non-critical', 'any order ya like')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip("—").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_viewing, _shots, _protocol, _coach)[who](rng, res, order)
