"""Deterministic, open-vocabulary instruction parser: free text -> TaskChain.

    chain = parse_instruction("First go to the sink next to the table with the monitor, then the fern "
                              "near (3.5, 2.0) with an NDVI above 0.6.")

The parser knows function words only (lexicon.py): it has no list of object categories, so any noun
phrase can be a goal. It works in passes over the lower-cased text:

1. number words before units or after comparators become digits ("about sixty-five degrees", "minus
   ten"); "before anything else" becomes "first";
2. coordinate hints ("(3.5, 2.0)", "x=3.5, y=2", "at about 3.5, 2", "(3.5 m | 2 m)", "with an x coordinate
   of 3.5 and a y coordinate of 2") and sensor phrases ("NDVI above 0.6", "about 55 deg C", "under 0.2",
   "warmest", "with the lowest NDVI", "no lower than 55 °C", "whose humidity exceeds 70 percent") are cut
   out into placeholders, so their commas and numbers cannot confuse the later passes; half-written
   numbers left behind are errors;
3. free-order phrases ("in any order", "in whatever order is quickest", "the order is your call") set the
   order and are removed;
4. the text is split at punctuation, brackets and connectors (then, and, after that, followed by...);
5. each segment loses its politeness and verb ("I'd love it if you could pop over to") and is read as a
   noun phrase (modifiers + head) followed by relations ("near", "next to", "on", "with", "in the room
   with"...), nested right-branching, and attributes written after a noun ("that is switched on", "which
   is red", "that's open", "made of oak", "which is ajar"), which describe the nearest noun; "in <room
   word>" is a room constraint; "on" is a state after a copula with no noun after it ("which is on"),
   a relation before a noun ("that is on the table");
6. segments with no noun (", about 60 degrees,", "near the sofa", ", which is on,") join the previous
   goal, and so do appositions ("the heater, the black one," or "the fern (the one by the window)")
   unless they clash with it ("the red chair, the blue one" lists two chairs); "X after Y" and "X, but
   first Y" swap; pronoun anchors ("next to it") refer to the previous goal;
7. clauses go on after "and" with the noun their relative pronoun described ("the bin that is lilac and
   closed", "the desk which is oak and has a lamp on it or beside it"); a clause with no subject ("standing
   by the door", "it's next to the sofa") describes the goal; sentence-initial subordinate clauses either
   name a goal that comes first ("once you've reached the kiln, ...") or only sequence ("when you've
   finished there, ..."); framing that ends in "you" + a modal ("all I need is for you to") is dropped.
   Descriptive words written after a noun join its phrase ("the sofa which is red": "red sofa"); states
   do not.

Anything it cannot read raises ParseError (a UserError) saying what was missing; nothing else escapes.
"""

from __future__ import annotations

import dataclasses
import math
import re
import unicodedata

from ragnav_jax.language import lexicon as L
from ragnav_jax.language.readings import UNIT_CODES, UNIT_READING, to_canonical
from ragnav_jax.language.time_words import cut_times
from ragnav_jax.language.types import (
    Location,
    ParseError,
    Relation,
    SensorConstraint,
    Subgoal,
    Target,
    TaskChain,
    TimeConstraint,
    derive_dependencies,
)

MAX_CHARS = 2000
MAX_SUBGOALS = 64

# ----------------------------------------------------------------------------------------------------
# Regular expressions (built once from the lexicon)


def _alt(phrases) -> str:
    """Regex alternation of phrases, longest first, with word boundaries around alphabetic ends.

    Written as a character trie ("(?:a(?:bove\\b|t(?:\\s+least\\b|\\b))|...)"): where several phrases match at
    one place they are prefixes of each other and the longest is tried first, as in a plain alternation
    sorted by length, but a place where none can start is left after one character instead of one try per
    phrase (the comparator alternation has about a hundred).
    """
    trie: dict = {}
    for p in set(phrases):
        node = trie
        for ch in p:
            node = node.setdefault(ch, {})
        node[""] = p

    def emit(node: dict, root: bool = False) -> str:
        alts = []
        for ch in sorted(k for k in node if k):
            e = r"\s+" if ch == " " else re.escape(ch)
            alts.append((r"\b" if root and ch.isalnum() else "") + e + emit(node[ch]))
        if "" in node:  # the end of a phrase: tried after every longer one
            alts.append(r"\b" if node[""][-1].isalnum() else "")
        return alts[0] if len(alts) == 1 and not root else "(?:" + "|".join(alts) + ")"

    return emit(trie, root=True)


NUM = r"(?<![\w.])[-+]?(?:\d+(?:\.\d+)?|\.\d+)(?![\d.]?\d)"
_NUM_END = r"(?!\.\d)"
READ_ALT = _alt(L.READING_NAMES)
CMP_ALT = _alt(L.COMPARATOR_PHRASES)
EXT_ALT = _alt(L.EXTREME_WORDS)
# instruments read off: "thermometer reading" (lexicon.READING_NAMES) -> "thermometer"
_INSTRUMENTS = "|".join(sorted(k.removesuffix(" reading") for k in L.READING_NAMES if k.endswith(" reading")
                               and " " not in k.removesuffix(" reading")))
UNIT = (
    r"(?:°\s*[cf]\b|°|degrees?(?:\s+(?:celsius|centigrade|fahrenheit|c|f)\b)?"
    r"|degs?\b\.?(?:\s*(?:celsius|centigrade|fahrenheit|c|f)\b)?|celsius\b|centigrade\b"
    r"|fahrenheit\b|c\b|f\b|%|percent\b|per\s+cent\b"
    r"|ppm\b|parts\s+per\s+million\b|db\b|dba\b|decibels?\b|lux\b|lx\b|kw\b|kilowatts?\b|w\b|watts?\b"
    r"|kg\b|kilos?\b|kilograms?\b|hpa\b|mbar\b|millibars?\b)"
)
_POST_ALT = _alt(L.COMPARATOR_POSTFIX)
POST = rf"(?:\s*(?P<post>{_POST_ALT}))?"  # "55 degrees or more", "0.14 or thereabouts"
NOT_LENGTH = (
    r"(?!\s*(?:m|cm|mm|km|meters?|metres?|feet|foot|ft|steps?|minutes?|mins?|seconds?|secs?|hours?|inch(?:es)?"
    r"|people|persons?|chairs?|times?|x)\b)"
)

_NW_ALT = "|".join(sorted(list(L.NUMBER_WORDS) + ["hundred", "point"], key=len, reverse=True))
_NW_SEQ = rf"(?:(?:a\s+)?(?:{_NW_ALT})(?:(?:\s+|-)(?:and\s+)?(?:{_NW_ALT}))*)"
_NW_AFTER_CMP = re.compile(
    rf"(?P<pre>{CMP_ALT}\s+|{_alt(L.COMPARATIVES)}\s+than\s+|{READ_ALT}\s+(?:(?:of|is|at|reading|value|score)\s+)?)"
    rf"(?P<nw>\b{_NW_SEQ}\b)"
)
_MINUS = re.compile(rf"\b(?:minus|negative)\s+(?=\d|\.\d|(?:{_NW_ALT})\b)")  # "minus five degrees"
_NW_BEFORE_UNIT = re.compile(rf"\b(?P<nw>{_NW_SEQ})(?=\s*(?:degrees?\b|degs?\b|°|percent\b|per\s+cent\b|%))")

_COORDS = r"(?:coordinates?|coords?|co-ordinates?|co-ords?)"
_LOC_LEAD = (
    r"(?:(?:\b(?:which|that)\s+is\s+|\bthat's\s+)?(?:\b(?:located|positioned|situated|placed|found|sitting|standing|set"
    r"|sat|lying|resting|kept|parked|stationed|pegged|pinned|plotted|marked|logged|fixed)\s+)?"
    r"\b(?:at|near|around|by|close\s+to|close\s+by|next\s+to|in\s+the\s+(?:vicinity|neighbou?rhood)\s+of"
    r"|not\s+far\s+from)\s+)?"
    r"(?:\b(?:about|around|roughly|approximately|approx\.?|near)\s+)?(?:\bthe\s+)?"
    r"(?:\b(?:map|grid|floor|floor\s+plan)\s+)?"
    rf"(?:\b(?:{_COORDS}|position|point|location|spot|reference|ref)\s+"
    r"(?:(?:marked|labell?ed)\s+)?)?(?:\bof\s+)?"
)
_METRES = r"(?:\s*(?:m|meters?|metres?)\b)?"  # "(3.5 m, 2 m)"
_PAIR_PAREN = (
    # a label may open the bracket: "(coords: 3.5, 2)", "(x/y fix: 6.4, 0.4)"
    r"[(\[]\s*(?:(?:[a-z]+(?:/[a-z]+)?\s+){0,2}[a-z]+(?:/[a-z]+)?\s*:\s*)?"
    rf"(?:x\s*[=:]?\s*)?(?P<x1>{NUM}){_METRES}\s*[,;|/]?\s*(?:y\s*[=:]?\s*)?(?P<y1>{NUM}){_METRES}\s*[)\]]"
)
# "x=", "x: ", "x coordinate of ", "x reads "
_AXIS = r"(?:[\s-]*(?:coordinate|coord|position|value)s?)?\s*(?:=|:|is|of|reads|equals)?\s*"
_PAIR_XY = (
    rf"\bx{_AXIS}(?P<x2>{NUM}){_NUM_END}{_METRES}\s*(?:,|;|/|\||and|,\s*and)?\s*(?:(?:the|an?|whose|its)\s+)?"
    rf"y{_AXIS}(?P<y2>{NUM}){_NUM_END}{_METRES}"
)
# each number followed by its axis: "11.8 m on x and 4.4 m on y", "7.9 along and 8.5 up" (across a plan, then up it)
_PAIR_NUM_AXIS = (
    rf"(?P<x4>{NUM}){_NUM_END}{_METRES}\s+(?:(?:on|along|for|in)\s+(?:the\s+)?x(?:[\s-]*axis)?\b|along\b|across\b)"
    rf"\s*(?:,|;|and|,\s*and)?\s*(?P<y4>{NUM}){_NUM_END}{_METRES}\s+(?:(?:on|along|for|in|up)\s+(?:the\s+)?y(?:[\s-]*axis)?\b"
    r"|up\b)"
)
_LOC1 = re.compile(_LOC_LEAD + rf"(?:{_PAIR_PAREN}|{_PAIR_XY}|{_PAIR_NUM_AXIS})")
_LOC2 = re.compile(
    rf"(?:\b(?:located|positioned|situated|placed)\s+)?(?:\b(?:at|{_COORDS}|position|point|location)\s+"
    rf"|\b(?:around|near|roughly|about|approximately)\s+(?={NUM}\s*/)"
    # a bare pair after a word of place: "the bean bag by 2.4, 6.2", "near 3, 4" (no unit: "near 20, 21 °C" is a reading)
    rf"|\b(?:by|near|around|roughly|about|approximately|close\s+to|next\s+to)\s+(?={NUM}{_NUM_END}\s*,\s*{NUM}{_NUM_END}"
    rf"(?!\s*{UNIT})))"
    rf"(?:(?:the\s+)?(?:map|grid)\s+(?:{_COORDS}|position|point|location|reference|ref)\s+)?"
    rf"(?:(?:about|around|roughly|approximately)\s+)?(?:(?:the\s+)?(?:{_COORDS}|position|point)\s+)?"
    rf"(?P<x3>{NUM}){_NUM_END}{_METRES}(?:\s*[,/|]\s*|\s+(?={NUM}{_NUM_END}(?!\s*(?:{UNIT}|[-+]?\.?\d))))"
    rf"(?P<y3>{NUM}){_NUM_END}{_METRES}"
)

_S_LEAD = r"(?:\b(?:with|having|that\s+has|which\s+has|whose|where)\s+(?:(?:an?|the|its|their)\s+)?)?"
_SENS_A = re.compile(
    _S_LEAD + rf"(?:\b(?:current|measured)\s+)?(?P<rd>{READ_ALT})(?:\s+(?:reading|value|level|score|measurement))?"
    r"(?:\s*:|\s+(?:is|of|reads|reading|at|that\s+is|which\s+is|measuring|measures|showing|shows|registering))?"
    rf"\s*(?:(?P<cmp>{CMP_ALT})\s*)?(?P<num>{NUM}){_NUM_END}\s*(?P<unit>{UNIT})?" + POST
)
_SENS_B = re.compile(
    r"(?:\b(?:with|having|at|of|showing|reading)\s+(?:an?\s+)?)?"
    rf"(?:(?P<cmp>{CMP_ALT})\s*)?(?P<num>{NUM}){_NUM_END}\s*(?P<unit>{UNIT})?" + POST + rf"\s*(?P<rd>{READ_ALT})"
    + POST.replace("?P<post>", "?P<post2>")  # ".48 NDVI or so"
)
_SENS_RANGE = re.compile(
    _S_LEAD + rf"(?:(?P<rd>{READ_ALT})(?:\s+(?:reading|value|level|score|measurement))?\s+(?:(?:is|of|reading)\s+)?)?"
    rf"\bbetween\s+(?P<lo>{NUM}){_NUM_END}\s*(?P<u1>{UNIT})?\s*(?:and|to|-)\s*(?P<hi>{NUM}){_NUM_END}\s*(?P<unit>{UNIT})?"
)
_DECIMAL_COMMA = re.compile(r"(?P<k>⟪[a-z]+⟫)\s*(?P<rest>,\d+)")
_COMPARATIVE = re.compile(
    rf"(?:\b(?P<neg>no|not|never|not\s+any)\s+)?\b(?P<adj>{_alt(L.COMPARATIVES)})\s+than\s+(?P<num>{NUM}){_NUM_END}"
    rf"\s*(?P<unit>{UNIT})?"
)
# A verb left between a noun and its cut-out sensor phrase: "the samovar running (hotter than 60 C)".
_VERB_BEFORE_SENSOR = re.compile(
    r"\b(?:(?:that|which|who)\s+)?(?:(?:is|are)\s+)?(?:currently\s+)?"
    r"(?:running|runs|reading|reads|showing|shows|measuring|measures|registering|registers|sitting|sits|operating"
    r"|operates|kept|set|heated|cooled|holding|holds|staying|stays|scoring|scores|rated|rating|hovering|hovers"
    r"|sitting|sits|exhibiting|exhibits|displaying|displays|recording|records|show|exhibit|display|record|register|read"
    r"|drawing|draws|using|uses|consuming|consumes|pulling|pulls|weighing|weighs|giving(?:\s+off)?|gives(?:\s+off)?"
    r"|producing|produces|putting\s+out|puts\s+out|returning|returns|emitting|emits|generating|generates|outputting"
    r"|outputs|logging|logs)(?:\s+(?:at|to|around))?(?:\s+(?:the|an?))?\s+(?=(?P<k>⟪[a-z]+⟫))"
)
_SENS_C = re.compile(
    r"(?:\b(?:at|of|with|reading|showing|measuring|registering)\s+)?"
    rf"(?:(?P<cmp>{CMP_ALT})\s*(?P<num>{NUM}){_NUM_END}{NOT_LENGTH}\s*(?P<unit>{UNIT})?" + POST
    + rf"|(?P<num2>{NUM}){_NUM_END}\s*(?P<unit2>{UNIT})" + POST.replace("?P<post>", "?P<post2>") + ")"
)
# "the lowest temp of the lot", "the warmest of all": a superlative's group said again
_OF_ALL = r"(?:\s+(?:out\s+)?of\s+(?:the\s+lot|the\s+bunch|any|all(?:\s+of\s+them)?|them\s+all|everything)\b)?"
_SUPER_READ = re.compile(
    r"(?:\b(?:with|having|that\s+has|which\s+has|showing|of)\s+)?(?:\b(?:the|its)\s+)?"
    rf"(?P<ext>{EXT_ALT})(?:\s+|-)(?P<rd>{READ_ALT})(?:\s+(?:sensor\s+)?(?:reading|value|level|score|measurement))?\b"
    + _OF_ALL
)
_SUPER_READ2 = re.compile(
    rf"\b(?:whose|where\s+the|with\s+(?:the|an?|its))\s+(?P<rd>{READ_ALT})"
    rf"(?:\s+(?:sensor\s+)?(?:reading|value|level|score|measurement))?\s+is\s+(?:the\s+)?(?P<ext>{EXT_ALT})\b" + _OF_ALL
)
# "whose NDVI is lower than any other", "beats all the others": outdoing every other one is a superlative ("warmer
# than all the rest" is rewritten as "warmest" by _CANONICAL)
_ALL_OTHERS = (
    r"(?:(?:that|those)\s+of\s+)?(?:(?:any|every|each|all)\s+(?:of\s+)?(?:the\s+)?(?:others?|rest|remaining)"
    r"(?:\s+ones?)?|(?:all\s+)?the\s+(?:others|rest)|all\s+others|(?:every|any)(?:thing|one)\s+else)(?:'s\b|'(?!\w)|\b)"
)
_READ_NOUN = rf"(?P<rd>{READ_ALT})(?:\s+(?:sensor\s+)?(?:reading|value|level|score|measurement))?"
_SUPER_THAN = re.compile(
    _S_LEAD + r"(?:(?:that|which)\s+(?:is|are)\s+|that's\s+)?"
    rf"(?:{_READ_NOUN}\s+(?:(?:is|reads|sits|runs|stands|shows|registers|measures|comes\s+(?:in|out|up))\s+)?"
    rf"(?P<cmp>{_alt(L.OUTDO_COMPARATIVES)})\s+than"
    rf"|{_READ_NOUN.replace('?P<rd>', '?P<rd2>')}\s+(?P<verb>{_alt(L.OUTDO_VERBS)})"
    rf"|(?P<verb2>{_alt(L.OUTDO_VERBS)}))\s+{_ALL_OTHERS}"
    rf"(?(verb2)\s+(?:on|in|for)\s+(?:the\s+)?{_READ_NOUN.replace('?P<rd>', '?P<rd3>')}\b)"
)
_SUPER_ADJ = re.compile(
    rf"(?:\b(?P<sup>{_alt(L.SUPERLATIVES)})|\b(?P<ml>most|least)\s+(?P<adj>{_alt(L.GRADABLE)}))" + _OF_ALL
)

# Leftovers that mean a number was meant but could not be read.
# (a comparator word before a determiner is a preposition: "the battery under the desk")
_BAD_AFTER_READING = re.compile(
    rf"(?P<all>{READ_ALT}\s+(?:is\s+|of\s+)?{CMP_ALT}\s+(?!(?:the|an?|my|your|our|his|her|its|their|this|that|these|those)\b)"
    r"(?P<bad>[^\s⟪⟫]+))")
_BAD_BEFORE_UNIT = re.compile(r"(?P<all>(?P<bad>[^\s⟪⟫]+)\s*(?:\bdegrees?\b|°|\bpercent\b))")
_BAD_PAREN = re.compile(r"[(\[][^()\[\]]*\d[^()\[\]]*[)\]]")
_BAD_XY = re.compile(r"\b[xy]\s*[=:]\s*\S*")
_MULTIDOT = re.compile(r"\d+\.\d+\.\d")
# "the sofa or the armchair, whichever is closer", "either the kettle or the toaster": a choice of objects.
_ALTERNATIVES = re.compile(
    r"\bwhichever\s+(?:one\s+|of\s+(?:the\s+)?(?:two|them|those|these)\s+)?(?:is|'s|are)\s+(?:closer|nearer|closest|nearest"
    r"|quicker|easier|more\s+convenient)\b(?!\s+(?:one\s+)?(?:first|to\s+start|to\s+begin))|\beither\s+(?:the|a|an|my|your)\s+[^,;.]*?\bor\s+(?:the|a|an|my|your)\b"
)

_FREE = re.compile(
    r"\b(?:in|by|following|using)\s+(?:any|whatever|whichever|an?\s+(?:efficient|optimal|sensible|good|smart)|"
    r"the\s+(?:best|most\s+efficient|quickest|fastest|shortest|optimal|cheapest|most\s+convenient|smartest))"
    r"\s+(?:order|sequence)(?:\s+(?:is|you\s+(?:like|want|prefer|choose|wish|think\s+best)|that\s+is|works?|seems?"
    r"|makes\s+sense)(?:\s+(?:quickest|fastest|shortest|best|most\s+efficient|efficient|optimal|for\s+you|fine|easier|easiest"
    r"|simplest|simpler|better|quicker|more\s+convenient|most\s+convenient|ok|okay|good|suits\s+you|suit\s+you"
    r"|cheapest|closest|easiest))?)*"
    r"|\b(?:the\s+)?order\s+(?:does\s+not|doesn't|do\s+not|don't|is\s+not|isn't)\s+(?:matter|important)"
    # "the dog bed and the boot rack, whichever is closer first": an order by distance
    r"|\bwhichever(?:\s+one)?\s+(?:is|'s)\s+(?:closer|nearer|closest|nearest)\s+(?:one\s+)?(?:first|to\s+start|to\s+begin)\b"
    r"|\b(?:the\s+)?(?:closest|nearest)\s+(?:one\s+)?first\b"
    r"|\b(?:in\s+)?no\s+particular\s+order|\bany\s+order\s+(?:is\s+fine|works|will\s+do)"
    r"|\bwhichever\s+(?:order|way)\s+is\s+(?:quickest|fastest|shortest|best|closest|easiest)"
    r"|\b(?:the\s+)?(?:visiting\s+)?order\s+is\s+up\s+to\s+you|\bin\s+any\s+sequence"
    r"|\b(?:taking|via|using|along|by)\s+the\s+(?:shortest|quickest|fastest)\s+(?:route|path|way)"
    r"|\bas\s+(?:efficiently|quickly)\s+as\s+possible"
    r"|\b(?:i\s+)?(?:do\s+not|don't)\s+care\s+(?:about|for)\s+the\s+order"
    r"|\bwhichever\s+order\s+(?:you\s+(?:like|want|prefer)|is\s+(?:quickest|fastest|shortest|best|easiest))"
    # "the order is your call", "the sequence is entirely up to you", "the order is flexible"
    r"|\b(?:the\s+)?(?:visiting\s+)?(?:order|sequence)\s+(?:is|'s)\s+(?:entirely\s+|completely\s+|totally\s+|really\s+)?"
    r"(?:your\s+(?:call|choice|decision)|up\s+to\s+you|yours\s+to\s+(?:choose|decide|pick)|flexible|free|irrelevant"
    r"|unimportant|open)"
    r"|\b(?:the\s+)?(?:visiting\s+)?(?:order|sequence)\s+(?:does\s+not|doesn't|do\s+not|don't|is\s+not|isn't)\s+"
    r"(?:matter|important|relevant)"
    # "you can pick the order", "feel free to choose the order", "choose the order yourself"
    r"|\b(?:you\s+(?:(?:can|may|could|get\s+to|are\s+free\s+to|should)\s+)?|feel\s+free\s+to\s+)?"
    r"(?:choose|pick|decide(?:\s+on)?|set)\s+(?:the|your\s+own)\s+(?:order|sequence)(?:\s+yourself)?"
    r"|\b(?:in\s+)?(?:any|whatever|whichever)\s+(?:order|sequence)\s+(?:you\s+see\s+fit|suits\s+you)"
    r"|\b(?:in\s+)?(?:an?\s+)?(?:order|sequence)\s+of\s+your\s+(?:choice|choosing)"
    r"|\b(?:i\s+)?(?:do\s+not|don't)\s+mind\s+(?:the|which|what)\s+(?:order|sequence)"
    r"|\b(?:in\s+)?no\s+(?:specific|set|fixed|required|special)\s+(?:order|sequence)"
    # "which one comes first doesn't matter", "it does not matter which you visit first"
    r"|\b(?:which|what)\s+(?:one|ones|of\s+(?:them|these)|goes|comes|you\s+(?:visit|do|see|check))\b[^.;:,!?⟪]{0,30}?"
    r"\b(?:does\s+not|doesn't|do\s+not|don't|won't|will\s+not)\s+matter\b"
    r"|\b(?:it\s+)?(?:doesn't|does\s+not)\s+matter\s+the\s+(?:order|sequence)\b"
    # "whichever way round you like", "order them however you like", "any order will do", "you decide the order"
    r"|\b(?:in\s+)?(?:whichever|whatever|any)\s+way\s+(?:round|around)(?:\s+you\s+(?:like|want|prefer|choose|wish|fancy))?"
    r"|\b(?:order|sequence|arrange)\s+(?:them|these|those|it|things|the\s+(?:visits|stops))\s+(?:however|as|any\s+way|whichever\s+way"
    r"|in\s+any\s+way)(?:\s+you\s+(?:like|want|prefer|see\s+fit|wish|fancy|choose))?"
    r"|\bany\s+(?:order|sequence)\s+(?:will\s+do|is\s+(?:fine|ok|okay|good)|works)"
    r"|\b(?:you|u)\s+(?:decide|choose|pick)\s+(?:on\s+)?the\s+(?:order|sequence)"
    r"|\b(?:there\s+is|there's)\s+no\s+(?:required|fixed|set|particular|specific|special|preferred)\s+(?:order|sequence)(?:\s+here)?"
    r"|\b(?:i'm|i\s+am)\s+not\s+(?:fussed|bothered|worried|picky|particular|fussy)\s+(?:about|with)\s+(?:the\s+)?(?:order|sequence)"
    r"|\b(?:feel\s+free|you're\s+free|you\s+are\s+free)\s+to\s+(?:shuffle|change|rearrange|reorder|swap|pick|choose|decide|set)"
    r"\s+(?:the|their|your\s+own)\s+(?:order|sequence)"
    r"|\bno\s+need\s+to\s+(?:stick\s+to|follow|keep\s+to)\s+(?:the|this|my)\s+(?:order|sequence)(?:\s+(?:i've|i\s+have)"
    r"\s+(?:listed|given|written|put)\s+(?:them|these|it)\s+in)?"
    r"|\b(?:either|any|each)\s+(?:one\s+)?(?:of\s+them\s+)?(?:can|could|may)\s+(?:come|go|be\s+done)\s+first"
    r"|\b(?:it\s+)?(?:makes|make)\s+no\s+difference\s+(?:which|what|in\s+which)\b[^.;:!?⟪]*"
    r"|\b(?:it\s+)?(?:doesn't|does\s+not)\s+make\s+(?:a|any)\s+difference\s+(?:which|what)\b[^.;:!?⟪]*"
    r"|\b(?:in\s+)?no\s+(?:prescribed|predetermined|mandated)\s+(?:order|sequence)"
    r"|\bno\s+particular\s+(?:order|sequence)\s+is\s+(?:required|needed|necessary|prescribed|expected)"
    r"|\b(?:the\s+)?(?:order|sequence)(?:\s+of\s+(?:the\s+)?(?:visits|tasks|stops|inspections|checks))?\s+(?:is|being)\s+"
    r"(?:not\s+(?:prescribed|fixed|important|required|specified|mandated)"
    r"|immaterial|unimportant|irrelevant|at\s+the\s+robot's\s+discretion|left\s+to\s+the\s+robot)"
    r"|\b(?:the\s+)?order\s+in\s+which\s+this\s+is\s+done\s+is\s+(?:immaterial|unimportant|irrelevant|not\s+important)"
    r"|\bin\s+(?:an?\s+)?(?:order|sequence)\s+of\s+(?:its|their|the\s+robot's)\s+(?:own\s+)?(?:choice|choosing)"
    r"|\bin\s+whatever\s+(?:order|sequence)\s+the\s+robot\s+(?:considers|finds|deems|judges)\s+(?:most\s+)?[a-z]+"
    r"|\bat\s+the\s+robot's\s+discretion"
    r"|\b(?:the\s+)?(?:order|sequence)(?:\s+is|'s)\s+(?:entirely\s+|totally\s+|completely\s+)?(?:flexible|not\s+important"
    r"|unimportant|up\s+to\s+you|your\s+(?:call|choice))"
    # "- any order", "(any order)", "whatever order works for you", "no particular order", "doesn't matter what order"
    r"|\b(?:in\s+)?(?:any|whatever|whichever|no\s+(?:particular|specific|special|set|fixed|required))\s+(?:order|sequence)"
    r"(?:\s+(?:works|is\s+[a-z]+|you\s+(?:like|want|prefer|choose|fancy)|(?:works\s+)?(?:best\s+)?for\s+you"
    r"|will\s+do|you\s+go\s+in|please))*"
    r"|\b(?:it\s+)?(?:doesn't|does\s+not|don't|do\s+not)\s+matter\s+(?:what|which|in\s+what|in\s+which)\s+(?:order|sequence)"
    r"(?:\s+you\s+(?:go\s+in|do\s+(?:them|it)(?:\s+in)?|take))?"
    r"|\b(?:i\s+)?(?:don't|do\s+not)\s+(?:mind|care)\s+(?:which|what|about\s+the)\s+(?:order|sequence)"
    r"(?:\s+you\s+(?:take|do|visit|see|check)\s+(?:them|these|those)(?:\s+in)?)?"
    r"|\b(?:i\s+)?(?:don't|do\s+not)\s+(?:mind|care)\s+(?:which|what)\s+(?:one\s+)?(?:you\s+)?(?:do|visit|see|check|go\s+to|take)"
    r"\s+first\b"
    r"|\bany\s+(?:order|sequence)(?:'s|\s+is)\s+(?:fine|ok|okay|good)\b"
    r"|\b(?:it\s+)?(?:does\s+not|doesn't|won't|will\s+not)\s+matter\s+(?:which|what|in\s+which)\b[^.;:!?⟪]*"
)
# Order phrases that only confirm the strict default: "in exactly this order", "in the order given", "one by one".
_STRICT = re.compile(
    r"\b(?:(?:strictly|exactly|precisely)\s+)?(?:in\s+)?(?:(?:exactly|precisely|strictly|just)\s+)?(?:this|that|the\s+(?:same|given|listed|stated|following"
    r"|above|written))\s+(?:(?:exact|very|same|precise)\s+)?(?:order|sequence)\b"
    r"(?:\s+(?:as\s+)?(?:given|listed|written|stated|above|below))?"
    r"|\bin\s+the\s+(?:exact\s+)?(?:order|sequence)\s+(?:given|listed|written|stated|shown|above|below|i\s+(?:gave|listed))"
    r"|\b(?:to\s+be\s+carried\s+out\s+)?in\s+the\s+(?:order|sequence)\s+(?:given|listed|indicated|specified|stated)"
    r"|\b(?:please\s+)?(?:keep|follow|stick\s+to)\s+(?:to\s+)?(?:this|that|the|my)\s+(?:order|sequence)\b"
    r"|\bin\s+(?:strict\s+)?(?:order|sequence)\s*(?=[,.;:!?]|$)|\bone\s+after\s+(?:the\s+)?(?:other|another)\b|\bone\s+by\s+one\b"
)
# "Before anything else, X": X comes first (not "X before Y").
_FIRST_OF_ALL = re.compile(r"\bbefore\s+(?:you\s+do\s+)?(?:anything|everything|all)\s+else\b")

_CONNECTORS = (
    "and then", "and finally", "and lastly", "and after that", "then", "after that", "afterwards", "afterward",
    "after this", "followed by", "and", "finally", "lastly", "as well as", "plus", "but first", "before that",
    "before", "after", "subsequently",
)
_SPLIT = re.compile(
    r"(?P<c>[,;:!?()\[\]]|\.(?!\d)|\s&\s|\s-+\s|" + _alt(_CONNECTORS)[3:-1] + r"|\bnext\b(?!\s+to\b))"
)
PAIR = "⟪pair⟫"  # "both boilers": the goal is asked for twice, as two objects
_TOKEN = re.compile(r"⟪[a-z]+⟫|[^\W_]+(?:['\-][^\W_]+)*")
SWAP_BACK = ("after", "but first", "before that")  # "X after Y": Y comes first
# "every one", "each one": a count of goals said elsewhere; "the last one": their order, neither a goal of its own
_QUANTIFIERS = frozenset({"every", "each", "any", "no"})
_SEQUENCE_WORDS = frozenset({"first", "next", "last", "final", "only", "just", "same", "very", "single"})
APPOSITION = ("(", "[")  # "the desk (the oak one)": the bracketed phrase describes the previous goal
LIST_SEPARATORS = (",", ")", "]", "-")  # "-": a spaced hyphen or a dash  # "the heater, the black one,": an apposition unless it clashes


def _phrase_tuples(phrases) -> list[tuple[str, ...]]:
    return sorted({tuple(p.split()) for p in phrases}, key=len, reverse=True)


def _by_first_word(table: dict[str, str]) -> dict[str, list[tuple[tuple[str, ...], str]]]:
    """{'next to': 'next_to', ...} -> {'next': [(('next', 'to'), 'next_to')], ...}, longest first per word."""
    out: dict[str, list[tuple[tuple[str, ...], str]]] = {}
    for k, v in sorted(table.items(), key=lambda kv: -len(kv[0].split())):
        out.setdefault(k.split()[0], []).append((tuple(k.split()), v))
    return out


_RELS = _by_first_word(L.RELATION_PHRASES)
_ROOM_PREPS = frozenset({"in", "inside", "within", "into", "inside of"})
_DANGLING = frozenset(
    "that which who is are that's which's whose where reads shows measures measuring reading showing currently "
    "located placed situated but giving producing returning emitting generating outputting logging".split()
)

# ----------------------------------------------------------------------------------------------------
# Numbers


def _to_float(s: str, what: str) -> float:
    try:
        v = float(s)
    except ValueError:
        raise ParseError(f"could not read the number '{s}' in {what}") from None
    if not math.isfinite(v):
        raise ParseError(f"the number '{s}' in {what} is too large")
    return v


def words_to_number(text: str) -> float | None:
    """'sixty five' -> 65.0, 'a hundred and twenty' -> 120.0, 'zero point six' -> 0.6; None if unreadable."""
    words = [w for w in re.split(r"[\s-]+", text.strip()) if w and w not in ("and", "a")]
    if not words:
        return None
    if "point" in words:
        k = words.index("point")
        whole = words_to_number(" ".join(words[:k])) if k else 0.0
        digits = words[k + 1 :]
        if whole is None or not digits or any(L.NUMBER_WORDS.get(d, 99) > 9 for d in digits):
            return None
        return float(f"{int(whole)}." + "".join(str(L.NUMBER_WORDS[d]) for d in digits))
    total, current = 0, 0
    for w in words:
        if w == "hundred":
            current = max(current, 1) * 100
        elif w in L.NUMBER_WORDS:
            v = L.NUMBER_WORDS[w]
            if current % 10 != 0 and v < 10 or (current % 100 != 0 and v >= 10):
                return None  # "five six", "twenty thirty"
            current += v
        else:
            return None
    return float(total + current)


def _number_words(s: str) -> str:
    def repl(m: re.Match) -> str:
        v = words_to_number(m.group("nw"))
        if v is None:
            return m.group(0)
        num = f"{v:g}"
        return (m.group("pre") if "pre" in m.groupdict() and m.group("pre") else "") + num

    s = _MINUS.sub("-", s)
    s = _NW_AFTER_CMP.sub(repl, s)
    return _NW_BEFORE_UNIT.sub(repl, s)


# ----------------------------------------------------------------------------------------------------
# Canonical forms: surface variants of English that carry no meaning of their own for the task chain are
# rewritten before anything is read. Each rule is a general construction, not a template's wording.


def _digits(words: str) -> str:
    """'five point two' -> '5.2' (unchanged when the words are no number)."""
    v = words_to_number(words)
    return words if v is None else f"{v:g}"


_ORD_ALT = "|".join(L.ORDINAL_WORDS)
# (reading, sign) -> a superlative that says it ("warmest"): "hotter than any other" is the hottest.
_SUPER_OF_SIGN = {v: k for k, v in reversed(list(L.SUPERLATIVES.items()))}
_PRON_OBJ = r"(?:that\s+one|this\s+one|that\s+spot|that\s+place|it|there|them|that|this)"


def _heading(m: re.Match) -> str:
    """'Task list (in the order given):' -> '(in the order given) ;': the heading goes, an order it states stays."""
    h = m.group(0)
    return h[h.find("(") : h.rfind(")") + 1] + " ;" if "(" in h else " "


def _list_marker(m: re.Match) -> str:
    """'1) ', '(2) ': a list position unless it closes a bracket opened before it ('(3, 4) then')."""
    before = m.string[: m.start()]
    return m.group(0) if before.count("(") > before.count(")") else "; "


_POINTER = (r"\s*(?:(?:please\s+)?(?:go|head|drive|get)\s+(?:over\s+)?(?:to\s+(?:that|it|this)(?:\s+one)?|there)"
            r"\s*[.!]?)?")  # "go to that one", "head over to it", "go there"


_CANONICAL: tuple[tuple[re.Pattern, str], ...] = tuple((re.compile(rx), rep) for rx, rep in (
    # A heading naming the kind of text: "Maintenance request:", "Task list (in the order given):", "Note for
    # the robot:", "Care round:".
    (r"^(?:[a-z]+\s+){0,3}?(?:request|note|notes|list|round|task|tasks|instructions?|memo|reminder|job|jobs|errands?|agenda"
     r"|plan|route|checklist|itinerary)(?:\s+for\s+(?:the\s+)?robot)?(?:\s*\([^()]*\))?\s*:", _heading),
    # Greetings and closing courtesies: "hi,", "ok so", "quick one:", ", thanks", "cheers", "pls".
    (r"^(?:(?:hi|hey|hello|ok|okay|right|so|alright|well|um+|uh+|er+|quick\s+one|robot)(?:\s+(?:there|robot|buddy|so|then)"
     r")?\s*[,:!.]?\s+)+", ""),
    # Chat shorthand and words typed without apostrophes: "rn", "plz", "u", "idc", "doesnt", "im".
    (r"\b(?:rn|asap|lol|thx|ty|tysm|kthx|ta)\b", " "),
    (r"\b(?:thanks|thank\s+you)(?:\s+(?:so|very)\s+much|\s+a\s+lot)?\s+(?:for\s+(?:your|the|all\s+your|all\s+the)\s+help"
     r"|in\s+advance)\b\s*[.!,]?", " . "),
    # Note-taking abbreviations: "pls chk", "nr" (near), "w/" (with), "pos." (position), "rm" (room), "+" between
    # goals; and prepositions said the way second-language writers often do: "near of", "close of", "on the top of".
    (r"\bchk\b", "check"),
    (r"\bnr\b(?=\s+(?:the|a|an|my|your|our|\d|\())", "near"),
    (r"(?<![\w/])w/\s*(?=[a-z])(?!o\b)", "with "),
    (r"\bpos\.?(?=\s*[(\[]?\s*[-+]?\.?\d)", "position "),
    (r"\b(?P<r>[a-z]+)\s+rm\b", lambda m: m.group("r") + ("" if m.group("r") in L.ROOM_WORDS else " room")),
    # A symbol standing alone between words that the parser gives no meaning to ("+", "|", "~", ">", "#", "✓",
    # "⇒") separates two items: it never joins their words into one name. Symbols that mean something keep it:
    # "&", "@", "/", "*", "-", "=" (is), units, brackets and stops; a comparator or sign before a number ("> 20").
    (rf"(?<=[^\W_])\s+(?![&@/*'\"`°%=≈-])[^\w\s(),;:!?.\[\]'\"`⟪⟫]+\s+(?=(?!(?:{_NW_ALT})\b)[^\W\d_])", " , "),
    (r"\b(?P<p>near|close)\s+of\b", lambda m: "near" if m.group("p") == "near" else "close to"),
    (r"\bopposite\s+of\b", "opposite"),
    (r"\bon\s+the\s+top\s+of\b", "on top of"),
    (r",\s*after\s+(?=(?:go|visit|check|head|drive)\b)", ", then "),
    # Texting: "go 2 the kettle", "thn", "n then", "b4".
    (r"\b(?P<v>go|get|head|come|drive|move|roll|nip|pop|back)\s+2\b(?!\s*(?:[.,/]\s*\d|°|%|degrees?\b|m\b))", r"\g<v> to"),
    (r"\bthn\b", "then"),
    (r"(?<=[a-z)])\s+n\s+(?=(?:then|the|a|an|also)\b)", " and "),
    (r"\bb4\b", "before"),
    (r"\bnxt\b", "next"),
    (r"\b(?:plz|pls|plez|pleaseee*)\b", "please"),
    (r"\b(?:u|ya)\b(?!-)", "you"),
    (r"\bur\b", "your"),
    (r"\bidc\b", "i don't care"),
    (r"\bidm\b", "i don't mind"),
    (r"\b(?P<w>does|do|is|are|was|were|has|have|can|won|wouldn|shouldn|didn)nt\b",
     lambda m: {"won": "won't", "can": "can't"}.get(m.group("w"), m.group("w") + "n't")),
    (r"\bim\b", "i'm"),
    (r"^(?:yo|oi|hey+)\b,?\s*", ""),
    # Asking as a favour: "would you be a dear and", "be an angel and", "be so kind as to".
    (r"\bbe\s+(?:a\s+(?:dear|love|darling|star|gem|sweetheart)|an\s+angel)\s+and\s+", " "),
    # A state or a room in brackets straight after a noun is that noun's: "the freezer (open)" is the open
    # freezer, even as an anchor ("the bin by the freezer (open)"); "the kettle (kitchen)" is in the kitchen.
    (rf"\bthe\s+(?P<np>(?:(?!(?:the|a|an|and|of|with|to|by|in|on|near|next|beside|that|which|at|from)\b)[\w'-]+\s+){{0,3}}?"
     rf"[\w'-]+)\s*\(\s*(?P<st>{_alt(L.STATE_PHRASES)})\s*\)",
     lambda m: "the " + re.sub(r"^((?:[\w-]+\s+)*?[\w-]+'s\s+)?", lambda p: (p.group(0) or "") + m.group("st") + " ",
                               m.group("np"), count=1)),
    (rf"(?<=[a-z])\s*\(\s*(?:in\s+the\s+)?(?P<r>(?:[a-z]+\s+)?(?:{'|'.join(sorted(L.ROOM_WORDS))}|[a-z]*room))\s*\)",
     r" in the \g<r>"),
    # Hurry: "quick please", "asap", "as soon as you can", "when you get a chance".
    (r"(?:^|(?<=[.!?;,]\s)|(?<=[.!?;,]))\s*(?:quick(?:ly)?|fast|soon|now)(?:\s+(?:please|if\s+you\s+can))?\s*(?=[.!?]|$)", " "),
    (r",?\s*\b(?:as\s+soon\s+as\s+(?:you\s+can|possible)|when\s+you\s+(?:get\s+a\s+(?:chance|moment|sec)|can))\b", " "),
    # "at -23 degrees, give or take": the tolerance goes with the number.
    (r",\s*(?=(?:give\s+or\s+take|or\s+so|or\s+thereabouts)\b)", " "),
    # A score on a reading: "scoring more than 0.6 on ndvi" is an ndvi above 0.6; "the worst ndvi score" the lowest.
    (rf"\b(?:scoring|scores?|rated|rating|measuring)\s+(?P<c>(?:[a-z]+\s+){{0,3}}?)(?P<n>{NUM})\s+(?:on|for|in)\s+(?:the\s+)?"
     rf"(?P<r>{READ_ALT})\b", r"with \g<r> \g<c>\g<n>"),
    (rf"\b(?P<q>best|worst|top|bottom)\s+(?P<r>{READ_ALT})(?:\s+(?:score|reading|value|level))?\b",
     lambda m: ("highest " if m.group("q") in ("best", "top") else "lowest ") + m.group("r")),
    # Lists said with "also": "the kettle. also the lamp", "the kettle, and also the lamp".
    (r"(?:(?<=[.;,!?]\s)|(?<=^)|\band\s+)also\s+(?=(?:the|a|an|my|your|our)\b)", "and "),
    # A reflexive in an anchor's clause adds nothing: "the shelf that is itself near the lectern".
    (r"\b(?P<v>is|are|'s|sits|stands)\s+(?:itself|themselves)\b", r"\g<v>"),
    (r"(?:[,;-]\s*|\s+)\b(?:(?:many\s+)?thanks|thank\s+you|thx|ta|cheers|pls|plz|please)(?:\s+(?:a\s+lot|so\s+much|very\s+much|again"
     r"|robot|buddy))?\s*(?=[.!?]|$)", ""),
    (r"\b(?:um+|uh+|er+|erm+)\b,?", " "),
    (rf"\b(?:minus|negative)\s+(?P<nw>{_NW_SEQ})\b", lambda m: "-" + _digits(m.group("nw"))),
    # Spoken fillers: "you know", "like" before a verb or after "and", "so then".
    (r",?\s*\byou\s+know\b,?", " "),
    (r"\b(?:and\s+)?like\s+(?=(?:go|get|take|stop|head|check|look|find|visit|swing|pop|drop|make|grab|roll|nip|move|see|and)\b)",
     lambda m: "and " if m.group(0).startswith("and") else ""),
    (r"\bso\s+(?=then\b)", " "),
    (r"(?<=[a-z])\s+so\s+(?=(?:go|get|take|stop|head|check|look|find|visit|swing|pop|drop|make|grab|roll|nip|move|see)\b)",
     " then "),
    # "after you visit the kiln go to the loom": a leading subordinate clause said without a comma.
    (r"(?:^|(?<=[.;!?]\s))(?:after|once|when)\s+(?:you\s+)?(?:have\s+|'ve\s+)?(?P<c1>(?:visit|go\s+to|check|see|find|reach|look"
     r"\s+at|stop\s+at|get\s+to|head\s+to|swing\s+by|drop\s+by|inspect|locate|are\s+done\s+with|finish\s+with)[^,.;:!?]+?)"
     r"\s+(?P<v>(?:go|visit|check|look|find|head|get|swing|stop|take|pop|drop|move|walk|drive|navigate|proceed|inspect|locate"
     r"|approach|reach|see|roll|nip|hop|travel)\b)", r"\g<c1>, then \g<v>"),
    # An apposition said without a comma: "the kiln the one that's on", "the plant the one in the den".
    (r"(?P<np>\bthe\s+(?:[\w'-]+\s+){0,3}?(?!and\b|then\b|or\b|to\b|at\b|of\b|by\b|in\b|on\b|is\b|are\b)[\w'-]+)\s+"
     r"(?=the\s+one\b(?!\s+of\b))", r"\g<np>, "),
    # Steps said without punctuation: "step one go to the sofa step two ...".
    (r"\bstep\s+(?:\d{1,2}|one|two|three|four|five|six|seven|eight|nine|ten)\b\s*[:.)-]?\s*", "; "),
    (r"(?:(?<=^)|(?<=[\s:;,]))(?:\(?\d{1,2}\)|\([a-h]\))(?=\s*[a-z])", _list_marker),
    (r"(?:(?<=^)|(?<=[:;!?])|(?<=[:;.!?]\s))(?<![xy]:\s)(?<![xy]:)\d{1,2}\.(?=\s+[a-z])", "; "),  # "in this order: 1. go to ... 2. find ..."
    # Remarks that ask for nothing: "Any irregularities should be noted in the log.", "No further action is
    # required.", purpose clauses ("so that a check can be carried out", "(for the maintenance log)").
    (r"(?:^|(?<=[.!?;]\s)|(?<=[.!?;]))\s*(?:any\s+(?:irregularities|issues|problems|findings)|no\s+further\s+action"
     r"|that\s+is\s+all|that's\s+all|thank\s+you|many\s+thanks|please\s+report\s+back)\b[^.!?]*[.!?]?", " "),
    (r",?\s*\b(?:(?<!\bor\s)so\s+that(?!')|in\s+order\s+to|in\s+order\s+that|so\s+as\s+to|for\s+the\s+purpose\s+of|with\s+a\s+view\s+to"
     r"|as\s+part\s+of)\b[^,;.()⟪]*", " "),
    (r"\((?:for|this|no|as|purely|just)\b[^()]*\)", " "),
    (r",?\s*\bfor\s+(?:inspection|checking|maintenance|safety|a\s+(?:check|look|visual\s+check|routine\s+inspection))"
     r"(?:\s+purposes)?(?=\s*(?:[,;.!?)]|$))", " "),
    (r"\bnormali[sz]ed\s+difference\s+vegetation\s+index\s*(?:\(\s*ndvi\s*\))?", "ndvi"),
    # The robot as the subject of a formal request: "the robot should first proceed to", "it is requested that
    # the robot visit", "it is to examine", "X is to be inspected".
    (r"\bit\s+is\s+(?:requested|asked|required)\s+that\s+(?:the\s+)?robot\s+", " "),
    (r"\b(?:the\s+)?robot\s+(?:considers|finds|deems|judges|thinks)\s+(?:to\s+be\s+)?(?:most\s+|best\s+)?[a-z]+\b", " "),
    (r"\b(?:the\s+)?robot\s+(?:should|must|shall|will|is\s+to|is\s+(?:requested|asked|required|expected)\s+to|needs\s+to|has\s+to"
     r"|ought\s+to|may|can)\s+", " "),
    (r"\b(?:it|they)\s+(?:should|must|shall|will|is\s+to|are\s+to|needs\s+to|has\s+to|ought\s+to|may|can)\s+(?:then\s+)?", " "),
    (r"\bit\s+is\s+(?:then\s+)?to\s+", " "),
    (r"\(?\s*\bto\s+be\s+(?:carried\s+out|done|completed|performed)\b\s*\)?", " "),
    (r"\b(?:is|are)\s+to\s+be\s+(?:examined|inspected|visited|checked|attended\s+to|located|approached|looked\s+at|verified|seen"
     r"|reported\s+to)\b", " "),
    (r"\b(?:is|are)\s+to\s+be\s+found\b", "is"),
    (r"\b(?P<c>and|which|that)\s+(?:is|are)\s+the\s+ones?\s+(?=with\b)",  # "and is the one with the lamp"
     lambda m: "and " if m.group("c") == "and" else ""),
    (r"\b(?:recorded|measured|registered|current)\s+(?=temperature|humidity|relative|ndvi|reading)", ""),
    (r"\bin\s+the\s+(?:same\s+)?room\s+where\s+(?P<np>(?:the|a|an)\s+[^,;.()⟪]+?)\s+(?:is|are|stands?|sits?|lives?|lies?)\b"
     r"(?!\s+(?:next|near|by|beside|on|in|under|close|not|right|opposite|behind|above))", r"in the room containing \g<np>"),
    (r"\b(?:the\s+)?(?:position|location|point|coordinates)\s+(?:given|specified|indicated)\s+by\s+", " "),
    (r"\bupon\s+completion\s+of\s+(?:the\s+|its\s+)?(?:visit|inspection|check|trip)\s+(?:to|of)\b", "visit"),
    (r"\bprior\s+to\s+(?=[a-z]+ing\b)", "before "),
    (r"\bupon\s+completion(?:\s+of\s+(?:this|that|which))?\b,?", " then "),
    (r"\b(?:which|that)\s+is\s+to\s+be\s+found\b", "which is"),
    (r"\bdo\s+(?:them|these|those|this|that|it|it\s+all|all\s+of\s+them)(?=\s+(?:in|any|whatever|whichever)\b|\s*[.,;!?]|\s*$)", " "),
    # "has on or near it the lamp": with the lamp; "... has the lamp on or near it": the pronoun adds nothing.
    (r"\b(?:has|have)\s+on\s+or\s+(?:near|next\s+to|beside|by|close\s+to)\s+(?:it|them)\s+", "with "),
    (r"\s+on\s+or\s+(?:near|next\s+to|beside|by|close\s+to)\s+(?:it|them)\b", " "),
    # "whichever shelves stand near the sofa": the verb of a nested anchor's clause.
    (r"\b(?P<w>whichever\s+(?:[a-z'-]+\s+){0,3}?)(?:stands?|sits?|lies?|rests?)\s+(?=(?:right\s+|just\s+|directly\s+)?"
     r"(?:next|near|close|by|beside|on|under|in|inside|not|behind|opposite|across|facing|to|above|below)\b)", r"\g<w>is "),
    # Asides that ask for nothing: "and while you're at it, the loom", "whilst you're there, the lamp".
    (r",?\s*\b(?:and\s+)?(?:while|whilst)\s+(?:you're|you\s+are)\s+(?:at\s+it|there|over\s+there|passing)\b\s*,?", " and "),
    # A term of address: "now dear, first go to", "ok love, the kiln", "thanks mate".
    # Said after "now", "ok", ... or followed by a comma, so "honey jar" and "love seat" stay names.
    (r"(?:(?<=^)|(?<=[.!?;,:]\s)|(?<=[.!?;,:]))\s*(?:(?:now|ok|okay|right|so|well)\s+(?:my\s+)?(?:dear|darling|sweetie|"
     r"sweetheart|honey|love|mate|pal|buddy)\b\s*,?|(?:my\s+)?(?:dear|darling|sweetie|sweetheart|honey|love|mate|pal|buddy)"
     r"\s*,)\s*", " "),
    # A request that introduces a list names nothing: "please could the robot attend the following:", "could you
    # send the robot to:", "the robot needs to visit:".
    (r"(?:(?<=^)|(?<=[.;!?]\s)|(?<=[.;!?]))[^.;:!?()]*?\b(?:the\s+following(?:\s+[a-z]+)?|to|visit|attend|check|see\s+to"
     r"|check\s+on|inspect)\s*:", " ; "),
    # "the sofa from the living room": in it (not "far from", "away from", "across from").
    (rf"(?<!far\s)(?<!away\s)(?<!way\s)(?<!across\s)(?<!distance\s)(?<!steps\s)(?<!step\s)(?<!walk\s)(?<!throw\s)"
     rf"(?<!metres\s)(?<!meters\s)(?<!feet\s)(?<!apart\s)(?<!m\s)\bfrom\s+the\s+(?P<r>(?:[a-z]+\s+)?(?:{'|'.join(sorted(L.ROOM_WORDS))}"
     r"|[a-z]*room))\b", r"in the \g<r>"),
    # "@" is "at": "the kiln @ (3, 4)", "the loom @ 2.5, 7".
    (r"\s*@\s*", " at "),
    # "x3.5 y2": an axis written against its number.
    (r"\b(?P<a>[xy])(?=[-+]?\d)", r"\g<a> "),
    # A spaced slash between items is a list: "the kiln / the loom / the lamp"; between numbers or before an
    # axis it is part of a coordinate pair ("3.5 / 2", "x 3.5 / y 2").
    (r"(?<![\d\s])\s+/\s+(?![-+.]?\d|[xy]\b)", " ; "),
    # "the desk that's got a lamp on it": has.
    (r"\b(?P<w>that|which|who)(?:'s|\s+has|\s+have|'ve)\s+got\b", r"\g<w> has"),
    # List markers: "1) the kiln 2) the loom", "1/ the kiln", "stop 2: the loom", "(a) the kiln", bullets; the
    # numbers are positions in a list, not values.
    (r"(?:(?<=^)|(?<=[\s:;]))(?:(?:\(?\d{1,2}\)|\(?[a-h]\)|\d{1,2}[./]|#\d{1,2}:?)(?=\s*(?:the|a|an|my|your|our)\b)|[•·*▪►‣]"
     r"|(?:stop|step|goal|stage|leg|destination|item|target|waypoint|no\.?|number)\s+(?:#\s*)?(?:\d{1,2}|one|two|three|four"
     r"|five|six|seven|eight|nine|ten)\s*[:.)-]|(?:1st|2nd|3rd|[4-9]th)\s*[:.)-])\s*",
     "; "),
    (rf"(?:(?<=^)|(?<=[\s;.]))(?:the\s+)?(?:{_ORD_ALT})\s+(?:stop|destination|goal|target|leg|waypoint|port\s+of\s+call)"
     r"\s*:", "; "),
    (r"\b(?P<w>next|first)\s+(?:up|off)\b", r"\g<w>"),
    # "check both boilers", "both of the air purifiers", "the two lamps": two goals of that name (the marker
    # is read by _parse_segment); "both the kiln and the loom" lists two goals already
    (r"(?<!\bof\s)\b(?:both\s+(?:of\s+)?(?:the\s+|these\s+|those\s+)?|the\s+two\s+)(?P<np>(?:[a-z][\w'-]*\s+){0,2}?[a-z][\w-]*?[^s'\s]s)\b"
     r"(?!\s*(?:and|or|'s)\b)", lambda m: f"the ⟪pair⟫ {_singular_np(m.group('np'))}"),
    (r"\b(?:both|each\s+of|all\s+of)\s+(?=the\b)", ""),  # "visit both the kiln and the loom"
    (r"\b(?P<o>order|sequence)'s\b", r"\g<o> is"),
    (r"\b(?:suits|suit)\s+you\b", "you like"),
    (r"^just\s+(?:the\s+)?one\s+(?:stop|thing|place|task|errand|job)(?:\s+(?:this\s+time|today|for\s+now))?\s*[:,.-]", " "),
    (r"\bpay\s+(?P<np>the\s+[^,;.()⟪]+?)\s+a\s+(?:quick\s+|short\s+|brief\s+)?visit\b", r"visit \g<np>"),
    # "save the kiln for the end", "leave the loom until last": the goal comes last (written last, as is usual).
    (r"\b(?:save|leave|keep)\s+(?P<np>the\s+(?:[^.;()⟪]|\.(?=\d))+?),?\s+(?:for|until|till|to)\s+(?:the\s+)?(?:very\s+)?(?:end|last|finish)\b",
     r"finally visit \g<np>"),
    # "the one with the lowest reading out of every lamp in the den": the lamp with the lowest reading in the den.
    (r"\bthe\s+one\s+(?P<mid>[^,;.()⟪]*?)\s+(?:(?:out\s+of|among|amongst)\s+(?P<q>every|each|all(?:\s+the)?|the)"
     r"|of\s+(?P<q2>every|each|all(?:\s+the)?))\s+"
     r"(?P<np>(?:[a-z'-]+\s+){0,2}?[a-z'-]+?)(?=\s+(?:in|inside|on|at|near|by|over|down)\b|\s*[,;.!?]|\s+-\s|\s*$)",
     lambda m: f"the {m.group('np') if (m.group('q') or m.group('q2')) in ('every', 'each') else _singular(m.group('np'))} "
               f"{m.group('mid')}"),
    # "the nearest lamp to the sofa" is the lamp nearest to the sofa; "the nearest lamp" (to the robot) names
    # a lamp: which one is left to retrieval and planning (the chain has no distance-to-robot constraint).
    (r"\bthe\s+(?:nearest|closest)\s+(?P<np>[a-z][\w'-]*(?:\s+[a-z][\w'-]*){0,2}?)\s+to\s+(?=(?:the|a|an|my|your)\b)",
     r"the \g<np> nearest to "),
    (r"\bthe\s+(?:nearest|closest)\s+(?!to\b|one\b|of\b)(?=[a-z])", "the "),
    # Light verbs: "take a (quick) look at", "have a peek inside", "make a detour to", "pay a visit to".
    (r"\b(?:take|have|give|get|taking|having|giving|getting|grab)\s+(?:a|an)\s+(?:(?:quick|brief|little|close|closer|good"
     r"|proper)\s+)?(?:look|peek|glance|peep|gander|squint|glimpse)\s+(?:at|in|inside|into|over)\b"
     r"|\b(?:make|making|pay|paying|do|doing)\s+(?:a|an)\s+(?:(?:quick|brief|little|short)\s+)?(?:stop|trip|detour|visit"
     r"|stopover|run|dash)\s+(?:at|to|by|in|over\s+to)\b"
     r"|\b(?:make|making)\s+(?:a\s+)?(?:bee-?line|b-line)\s+(?:for|to|towards)\b", "visit"),  # "next up, ...", "first off, ..."
    (r"\s+on\s+the\s+(?:map|floor\s*plan|plan|grid)\b", " "),  # "at (3, 4) on the map"
    # "(x, y) = (3, 4)", "x/y = 3/4", "{x: 3, y: 4}", "3 (x) and 4 (y)", "whose coordinates are (3, 4)".
    (r"\(\s*x\s*,\s*y\s*\)\s*(?:=|:)\s*(?=[(\[])", " "),
    (r"\b(?P<a>[xy])\s+(?:equals|is\s+equal\s+to|is)\s+", r"\g<a> = "),  # "x equals 3.5"
    (rf"(?P<x>{NUM}|{_NW_SEQ})\s+comma\s+(?P<y>{NUM}|{_NW_SEQ})\b",  # spoken pairs: "three point five comma two"
     lambda m: f"({_digits(m.group('x'))}, {_digits(m.group('y'))})"),
    (rf"\bcoordinates?\s+(?P<x>{NUM}|{_NW_SEQ})\s+and\s+(?P<y>{NUM}|{_NW_SEQ})\b",
     lambda m: f"({_digits(m.group('x'))}, {_digits(m.group('y'))})"),
    (rf"(?P<pre>\b[xy]\s*(?:(?:value\s+)?of\s+|=\s*|:\s*|is\s+|\s))(?P<nw>{_NW_SEQ})\b(?![-\w])",
     lambda m: m.group("pre") + _digits(m.group("nw"))),
    (rf"\b(?:with|having)\s+an?\s+x\s+(?:value\s+)?of\s+(?P<x>{NUM})\s*,?\s*(?:and\s+)?an?\s+y\s+(?:value\s+)?of\s+"
     rf"(?P<y>{NUM})", r"at (\g<x>, \g<y>)"),
    (rf"\bx\s*/\s*y\s*(?:=|:)\s*(?P<x>{NUM})\s*/\s*(?P<y>{NUM})", r"(\g<x>, \g<y>)"),
    (r"\{(?P<in>[^{}]*\d[^{}]*)\}", r"(\g<in>)"),
    (rf"(?P<x>{NUM})\s*\(\s*x\s*\)\s*(?:,\s*and|,|and)?\s*(?P<y>{NUM})\s*\(\s*y\s*\)", r"(\g<x>, \g<y>)"),
    (r"\b(?:whose|with\s+(?:the|its))\s+(?:map\s+|grid\s+)?(?:coordinates|coords|position|location)\s+(?:are|is)\s+", " at "),
    # Arrows and similar marks of a sequence: "the kiln -> the loom".
    (r"\s*(?:→|⟶|➔|➜|➝|=>|->|»|>>)\s*", " then "),
    # "the kiln currently switched on": a time adverb before a state after a noun is its copula.
    (rf"(?<![\w'])(?P<cop>(?:is|are|'s|stays?|remains?|be)\s+)?(?:currently|presently|right\s+now|at\s+the\s+moment"
     rf"|now)\s+(?={_alt(L.STATE_PHRASES)})", lambda m: m.group("cop") or "that is "),
    # Order said outright: "order matters here:", "exactly as listed"; "X, but not until you've been to Y".
    (r"\b(?:the\s+)?order\s+(?:matters|is\s+important|counts)(?:\s+(?:here|for\s+this))?\b", " "),
    (r"\b(?:exactly\s+|just\s+)?as\s+(?:listed|given|written)\b|\bkeeping\s+to\s+(?:this|that|the\s+given)\s+order\b", " "),
    (r"\bbut\s+not\s+(?:until|before)\s+(?:you've|you\s+have|you're|you\s+are)\s+(?:been\s+to|visited|seen|checked|reached"
     r"|done|finished\s+with|stopped\s+at|gone\s+to)\b", "but first"),
    (r"\b(?:and\s+)?only\s+(?:then|after\s+that|afterwards)\b", " then "),
    (r"^mind\s+(?=[a-z]+ing\b)", "would you mind "),  # "mind scooting over to ...?"
    # Where things are kept: "the kettle that we keep in the kitchen", "that you'll find in", "which lives in".
    (r"\b(?:that|which)\s+(?:we've\s+got|we\s+have|we\s+keep|we've|you'll\s+find|you\s+will\s+find|you\s+can\s+find"
     r"|i\s+keep|i\s+have|i've\s+got|you'll\s+see|you\s+can\s+see)\s+(?=in|inside|on|by|near|next|over|up|down|at)\b",
     "that is "),
    (r"\b(?:that\s+|which\s+)?you\s+(?:can|could|will|'ll|might)\s+(?:find|see|spot)(?=\s+(?:in|inside|on|at|there|here"
     r"|anywhere|around|over|upstairs|downstairs)\b|\s*[,.;!?]|\s*$)", " "),
    # Rooms of other objects: "in the room where you'll find X", "in whichever room X is in", "in the room X is in".
    (r"\bin\s+the\s+(?:same\s+)?room\s+where\s+(?:you'll|you\s+will|you\s+can|we|you)\s+(?:find|see|keep|have)\b",
     "in the room containing"),
    (r"\bin\s+(?:whichever|the|what(?:ever)?)\s+room\s+(?:that\s+)?(?P<np>(?:the|a|an)\s+[^,;.()⟪]+?)\s+(?:is|are|sits|sit"
     r"|lives|live|stands|stand)\s+in\b", r"in the room containing \g<np>"),
    # "X that the Y is on or near", "X that either supports or stands near the Y": Y is on X or beside it.
    (r"\b(?:that|which)\s+(?P<np>(?:the|a|an)\s+[^,;.()⟪]+?)\s+(?:is|are|sits|sit|rests|rest|stands|stand)\s+on\s+or\s+"
     r"(?:(?:stands?|sits?|is|are)\s+)?(?:near|close\s+to|next\s+to|beside|by)\b", r"with \g<np>"),
    (r"\b(?P<w>that|which|and)\s+(?:either\s+)?(?:supports?|holds?|has|have|carries|carry)\s+or\s+(?:stands?|sits?|is|are)\s+"
     r"(?:near|next\s+to|beside|by|close\s+to)\b", lambda m: "and has" if m.group("w") == "and" else "with"),
    (r"\bgo\s+ahead\s+and\b", " "),
    # "to the sofa's left": to the left of the sofa.
    (r"\bto\s+(?P<np>(?:the|a|an)\s+(?:(?!that\b|which\b|who\b|it\b)[^,;.()⟪'\s]+\s+){0,3}?(?!that\b|which\b|who\b|it\b)"
     r"[^,;.()⟪'\s]+)'s\s+(?P<side>left|right)(?:-hand\s+side|\s+side)?\b",
     r"to the \g<side> of \g<np>"),
    # Readings and thresholds in other words: "temp", "RH", "NDVI index", "below the 0.3 mark", "18 degrees below zero".
    (r"\bvegetation\s+index\s*\(\s*ndvi\s*\)|\bndvi\s+(?:index|value|reading|score)\s*(?=\(|[<>≤≥~≈=])|\bndvi\s+index\b", "ndvi"),
    (r"\btemp\b\.?", "temperature"),
    (r"\brh\b", "humidity"),
    (r"\bdeg\s*c\b", "°c"),
    (rf"\bthe\s+(?P<n>{NUM}|{_NW_SEQ})(?:\s*-?\s*(?P<u>%|°\s*c|c|degrees?|degree|percent|per\s+cent))?\s+mark\b",
     lambda m: m.group("n") + (" " + ("degrees" if m.group("u") and m.group("u").startswith("degree") else m.group("u"))
                               if m.group("u") else "")),
    (rf"(?P<n>{NUM})\s*(?P<u>degrees?(?:\s+(?:celsius|c))?|°\s*c?)\s+below\s+(?:zero|freezing)", r"-\g<n> \g<u>"),
    (r"\b(?P<n>\d+|[a-z]+(?:-[a-z]+)?)-ish\b", r"about \g<n>"),
    # "whichever heater in the garage is warmest": the warmest heater in the garage.
    (rf"\bwhichever\s+(?P<np>(?:(?!whichever\b|is\b|are\b|and\b)[^,;.()⟪])+?)\s+(?:is|are)\s+(?:the\s+)?"
     rf"(?P<sup>{_alt(L.SUPERLATIVES)})\b",
     r"the \g<sup> \g<np>"),
    # "colder than any other one in there", "warmer than all the others": a superlative.
    (rf"\b(?P<cmp>{_alt(L.COMPARATIVES)})\s+than\s+{_ALL_OTHERS}(?:\s+(?:in\s+there|there|here|in\s+here))?",
     lambda m: _SUPER_OF_SIGN[L.COMPARATIVES[re.sub(r"\s+", " ", m.group("cmp"))]]),
    # "the retro and teal one", "the lacquered and charcoal drums": "and" between describing words before a noun
    (rf"(?P<pre>\b(?:the|an?)\s+(?:(?:{_alt(L.MODIFIER_WORDS)})\s+)*)(?P<a>{_alt(L.MODIFIER_WORDS)})\s+and\s+"
     rf"(?=(?:{_alt(L.MODIFIER_WORDS)})\b)", r"\g<pre>\g<a> "),
    # "once the one before it has gone", "the one ahead of it": another goal, named by its place in the order
    (r"\bthe\s+(?:one|ones)\s+(?:[a-z]+ed\s+)?(?:(?:just|right|immediately)\s+)?"
     r"(?:before|after|ahead\s+of|preceding|following)\s+(?:it|them|this|that)\b", "it"),
    (r"\bthe\s+(?:previous|preceding)\s+(?:one|ones)\b", "it"),
    # "the cello (itself sporting the music stand)": a reflexive opening a bracket or an apposition is "the one"
    (r"(?<=[(\[,])\s*(?:itself|themselves)\b", " the one"),
    # "the crib described as charcoal", "the daybed (tagged wool)": a label of describing words is a state
    (rf"\b(?:(?:described|listed|catalogued|logged|labell?ed|tagged|marked|given)\s+as|tagged|labell?ed)\s+"
     rf"(?P<a>(?:{_alt(L.MODIFIER_WORDS)})(?:\s+(?:and\s+)?(?:{_alt(L.MODIFIER_WORDS)}))*)\b", r"which is \g<a>"),
    # "the workshop part of the house": the room; "lacquered to look at": what it looks like
    (r"\b(?P<r>in\s+the\s+[a-z][a-z -]*?)\s+(?:part|end|side|bit)\s+of\s+the\s+(?:house|home|flat|building)\b",
     r"\g<r>"),
    (rf"\b(?P<a>{_alt(L.MODIFIER_WORDS)})\s+to\s+look\s+at\b", r"\g<a>"),
    # A room given as a labelled field: "(room: music room)", "[location - the pantry]"
    (r"[(\[]\s*(?:room|location)\s*[:=-]\s*(?:the\s+)?(?P<r>[a-z][a-z' -]*?)\s*[)\]]", r" in the \g<r> "),
    # A reading's name and its abbreviation in brackets: "vegetation index (NDVI)", "relative humidity (RH)"
    (rf"\b(?P<rd>{READ_ALT})\s*[(\[](?:{READ_ALT})[)\]]", r"\g<rd>"),
    # Relative clauses on a reading: "the plant for which the NDVI is 0.6", "the heater the temperature of which".
    (rf"\b(?:for|in|on)\s+which\s+the\s+(?=(?:{READ_ALT})\b)", "whose "),
    (rf"\bthe\s+(?P<rd>{READ_ALT})\s+of\s+which\b", r"whose \g<rd>"),
    # "-23 on the Celsius scale": the scale is the unit
    (r"(?:\s+degrees)?\s+on\s+the\s+(?P<u>celsius|centigrade|fahrenheit)\s+scale\b", r" degrees \g<u>"),
    # "down in the pantry", "through in the laundry room", "right there in the pantry"
    (r"\b(?:down|over|up|out|back|round|through|along|right\s+there|just\s+there)\s+(?=in\s+the\b|inside\s+the\b)",
     ""),
    (r"\b(?:once|when|after)\s+(?:you're|you\s+are|you've|you\s+have|you)\s+(?:done|finished|through)(?:\s+(?:with\s+"
     r"(?:that|it|this|that\s+one)|there|here))?\b", " then "),
    # Time adverbs say when a state holds, and it holds now: "which is open at the moment".
    (r"\b(?:at\s+the\s+moment|at\s+present|right\s+now|just\s+now|as\s+of\s+now|for\s+now|at\s+this\s+time"
     r"|currently|presently)\b", " "),
    # Apposition markers: "(i.e. the red one)", "- namely the oak one -", ", specifically the big one".
    (r"(?:(?<=[(\[,])|(?<=\s-))\s*(?:i\.?\s?e\.?|namely|specifically|that\s+is\s+to\s+say|in\s+other\s+words|to\s+be\s+(?:precise"
     r"|exact|specific)|more\s+precisely|precisely|viz\.?)(?:\s*,)?\s+", " "),
    # "with the kettle (either) on it or beside it": the pronoun relations only restate "with".
    (r"(?P<c1>\s*,)?\s*(?:either\s+)?(?:on(?:\s+top\s+of)?|beside|next\s+to|near|by|alongside)\s+(?:it|them)\s+or\s+"
     r"(?:on(?:\s+top\s+of)?|beside|next\s+to|near|by|alongside)\s+(?:it|them)\b(?P<c2>\s*,)?",
     lambda m: "," if m.group("c2") and not m.group("c1") else " "),
    # "the kiln set next to the loom", "that's set on the shelf": "set" before a place is a participle, except
    # in the nouns English makes with it ("the drum set beside the sofa").
    (r"\b(?<!drum\s)(?<!chess\s)(?<!tea\s)(?<!train\s)(?<!tool\s)(?<!lego\s)(?<!box\s)(?<!gym\s)(?<!play\s)(?<!paint\s)"
     r"(?<!dinner\s)(?<!radio\s)(?<!tv\s)set\s+(?=(?:next|beside|on|by|near|under|in|behind|opposite|against|close|atop"
     r"|inside|alongside|above|below|beneath|underneath|up\s+(?:on|by|near|against))\b)", "located "),
    # "the coolest-running kiln": the superlative of how it runs is the superlative.
    (rf"\b(?P<sup>{_alt(L.SUPERLATIVES)})-(?:running|reading|measuring|looking|operating)\b", r"\g<sup>"),
    # "whatever is at (9.5, 8.1)", "whatever sits by the door": a goal named by its place alone (a generic head).
    (r"\bwhatever(?:'s|\s+is|\s+sits|\s+stands|\s+lies)\s+(?=(?:at|near|by|around|on|in|next\s+to|close\s+to)\b)",
     "the thing "),
    # "there's a record player on the credenza - go to it": the object a sentence introduces is the goal.
    (r"\b(?:there's|there\s+is|there\s+should\s+be|you'll\s+find|you\s+will\s+find)\s+(?:a|an|one)\s+(?=[a-z])", "the "),
    # "the highest reading on the thermometer", "above 30 degrees on the thermometer": the instrument that gives a
    # reading names the reading (lexicon.READING_NAMES: "thermometer reading"), not a goal or an anchor.
    (rf"\b(?P<e>{EXT_ALT})\s+(?:reading|measurement|value)\s+(?:on|from|off|according\s+to)\s+(?:the|its|a)\s+"
     rf"(?P<i>{_INSTRUMENTS})\b", r"\g<e> \g<i> reading"),
    (rf"(?P<u>{UNIT})\s+(?:(?:as\s+)?(?:shown|read|measured)\s+)?(?:on|by|from|according\s+to)\s+(?:the|its|a)\s+"
     rf"(?:{_INSTRUMENTS})\b", r"\g<u>"),
    # A reading given as a labelled field with an extreme, "(ndvi: the lowest going)", "temperature = highest": the
    # superlative of that reading ("going", "around", "there is": the extreme of what there is).
    (rf"\b(?P<rd>{READ_ALT})(?:\s+(?:reading|value|level|score))?\s*[:=]\s*(?:the\s+)?(?P<e>{EXT_ALT})\b"
     r"(?:\s+(?:going|around|there\s+is|to\s+be\s+had|to\s+be\s+found|on\s+offer))?", r"the \g<e> \g<rd>"),
    (rf"\b(?P<e>{EXT_ALT})\s+(?P<rd>{READ_ALT})(?:\s+(?:reading|value|level|score))?\s+(?:going|around|there\s+is"
     r"|to\s+be\s+had|to\s+be\s+found|on\s+offer)\b", r"\g<e> \g<rd>"),
    # "need a reading from the water cooler", "take a measurement off the kiln": the object read is the goal.
    (r"\b(?:an?|the|some|another)\s+(?:(?:temperature|humidity|quick|fresh|new)\s+)?(?:reading|readings|measurement"
     r"|measurements)\s+(?:from|of|off|on|at)\s+(?=(?:the|a|an|my|our|that|this)\b)", ""),
    # "which machine in the break room is hottest? go there.": a superlative said of the question's noun phrase.
    (rf"(?:^|(?<=[.!?;]\s))which\s+(?P<np>(?:[a-z][\w'-]*\s+){{0,6}}?[a-z][\w'-]*)\s+(?:is|are)\s+(?:the\s+)?"
     rf"(?P<sup>{_alt(L.SUPERLATIVES)})(?:\s+(?:one|of\s+(?:them|all|the\s+lot)))?\s*\?{_POINTER}",
     r"the \g<sup> \g<np>. "),
    # "which tumble dryer is running? go to that one.": the question names the goal; the pointer adds nothing.
    (r"(?:^|(?<=[.!?;]\s))which\s+(?P<np>(?:[a-z][\w'-]*\s+){0,3}?[a-z][\w'-]*)\s+(?P<v>is|are)\s+(?P<rest>[^?.!;]+)\?"
     + _POINTER, r"the \g<np> that \g<v> \g<rest>. "),
    # "the crib with the mustard finish", "the chair in a tweed fabric": a property noun after its value names no
    # object; the value is the goal's attribute.
    (r"\b(?:with|in|having)\s+(?:a|an|the|its|their)\s+(?P<w>(?:(?!(?:and|or|then)\b)[a-z][\w-]*\s+)?(?!(?:and|or|then)\b)[a-z][\w-]*)\s+(?:finish|colou?r|shade|hue"
     r"|tone|paint|paintwork|fabric|material|upholstery|texture|pattern|style|look|trim|veneer|coating)\b"
     r"(?!\s+(?:with|at|by|up|off|the|a|an|to|of)\b)", r"that is \g<w>"),
    (r"\bhaving\s+(?=(?:the|a|an)\b)", "with "),  # "the desk having the lamp": "having" before a noun is "with"
    # A participle or subordinate clause about the previous goal only sequences: "having reached that one,",
    # "once you've looked at it,", "after dropping by there,".
    # A clause that names a new goal is no such clause: "after that the bin by it" is a goal.
    (rf"\b(?:having|once|when|after(?!\s+(?:that|this)\s+(?:the|a|an)\b)|upon)\b(?:(?!\bthe\b)[^,.;:!?⟪()]){{0,40}}?"
     rf"\b{_PRON_OBJ}\s*(?=[,.;:!?]|$)", " then "),
    # "make the kiln your first stop, the loom your second": the ordinal says what the order says already.
    (rf"\b(?:as\s+)?your\s+(?:very\s+)?(?:{_ORD_ALT})(?:\s+(?:stop|destination|goal|target|one|port\s+of\s+call))?\b",
     " "),
    # "in the room that also holds the easel": the room of another object.
    (r"\bin\s+the\s+(?:same\s+)?room\s+(?:that|which|where)\s+(?:also\s+)?(?:has|holds|contains|houses|includes|features"
     r"|there\s+is|there's)\b", "in the room containing"),
    (r"\bin\s+the\s+(?:same\s+)?room\s+(?:that|which)\s+(?:also\s+)?(?:has|holds|contains|houses)\s+(?=the\b)",
     "in the room containing "),
    # "that would be great", "it'd be lovely": a closing courtesy.
    (r"(?:[,;]\s*)?\b(?:that|it|this)\s*(?:would|'d|will|'ll)\s+(?:really\s+)?be\s+(?:great|lovely|ideal|perfect|helpful"
     r"|wonderful|fantastic|brilliant|appreciated|much\s+appreciated|nice|awesome|super|amazing|good)\b", " "),
    # Coordinates written along the axes: "7.4 m along the x-axis and 2.9 m along the y-axis (from the origin)".
    (rf"(?P<x>{NUM})\s*(?:m|metres?|meters?)?\s+along\s+the\s+x(?:-|\s)?axis\s*,?\s*(?:and\s+)?(?P<y>{NUM})\s*"
     r"(?:m|metres?|meters?)?\s+along\s+the\s+y(?:-|\s)?axis(?:\s+(?:from|of|measured\s+from)\s+the\s+origin)?",
     r"at (\g<x>, \g<y>)"),
    # A superlative's scope: "the warmest among those in the den", "the coldest of them all in the den".
    (r"\s*\b(?:among|amongst|of|out\s+of)\s+(?:all\s+)?(?:those|these|them|the\s+ones)(?:\s+(?:that\s+are|which\s+are|that\s+is|which\s+is"
     r"|located|positioned|found|kept|standing|sitting|situated|placed))*(?=\s+(?:in|inside|within|over\s+in)\b)", " "),
    (r"\bthe\s+\(\s*x\s*,\s*y\s*\)\s+(?:position|coordinates?|point|location|spot)\s+(?=[(\[])", " "),
    (r"\b(?:the\s+)?(?:point|spot|position|location|place)\s+(?:with|where|whose)\s+(?=x\b)", " "),
    (r"\b(?P<axis>[xy])\s*(?:≈|~|≃|=~)\s*", r"\g<axis>="),
))


def _singular(word: str) -> str:
    """'plants' -> 'plant', 'batteries' -> 'battery', 'benches' -> 'bench' (the noun after 'of the')."""
    if word.endswith("ies") and len(word) > 4:
        return word[:-3] + "y"
    if re.search(r"(?:ch|sh|x|z|ss)es$", word):
        return word[:-2]
    return word[:-1] if word.endswith("s") and not word.endswith("ss") else word


# "the healthiest of the plants", "the most humid of all the rooms' dehumidifiers": a superlative over a plural
# noun phrase names one of them ("the healthiest plant").
_SUPER_OF = re.compile(
    rf"\b(?P<sup>{_alt(L.SUPERLATIVES)}|(?:most|least)\s+{_alt(L.GRADABLE)}|(?:{_alt(L.EXTREME_WORDS)})(?:\s+|-){READ_ALT})"
    r"(?:\s+(?:one|ones))?\s+(?:out\s+)?of\s+(?:all\s+)?(?:(?:the|those|these|your|my|our)\s+)?"
    r"(?P<np>(?:[a-z][\w'-]*\s+){0,3}?[a-z][\w-]*?s)\b(?!\s*(?:of|'s)\b)"
)

# "the healthier of the two peace lilies": a comparative over a group picks its extreme, the healthiest lily.
_SUPER_FOR = {v: k for k, v in reversed(L.SUPERLATIVES.items())}
_COMPARATIVE_OF = re.compile(
    rf"\bthe\s+(?P<cmp>{_alt(w for w in L.COMPARATIVES if L.COMPARATIVES[w] in _SUPER_FOR)})\s+(?:one\s+)?of\s+"
    r"(?:the|those|these|your|my|our)\s+(?:(?:two|three|four|2|3|4|pair\s+of)\s+)?"
    r"(?P<np>(?:[a-z][\w'-]*\s+){0,3}?[a-z][\w-]*?s)\b(?!\s*(?:of|'s)\b)"
)


def _singular_np(np_: str) -> str:
    return " ".join([*np_.split()[:-1], _singular(np_.split()[-1])])


def _canonical(s: str) -> str:
    for rx, rep in _CANONICAL:
        s = rx.sub(rep, s)
    s = _COMPARATIVE_OF.sub(lambda m: f"the {_SUPER_FOR[L.COMPARATIVES[m.group('cmp')]]} {_singular_np(m.group('np'))}", s)
    s = _SUPER_OF.sub(lambda m: f"{m.group('sup')} {_singular_np(m.group('np'))}", s)
    return re.sub(r"\s+", " ", s).strip()


# ----------------------------------------------------------------------------------------------------
# Placeholders: coordinates and sensor phrases are cut out before splitting.


def _key(i: int) -> str:
    letters = ""
    i += 1
    while i:
        i, r = divmod(i - 1, 26)
        letters = chr(97 + r) + letters
    return f"⟪{letters}⟫"


@dataclasses.dataclass
class _Marks:
    locations: dict[str, Location] = dataclasses.field(default_factory=dict)
    sensors: dict[str, tuple[SensorConstraint, ...]] = dataclasses.field(default_factory=dict)
    text: dict[str, str] = dataclasses.field(default_factory=dict)
    times: dict[str, TimeConstraint] = dataclasses.field(default_factory=dict)

    def add(self, original: str, location: Location | None = None,
            sensor: SensorConstraint | tuple[SensorConstraint, ...] | None = None,
            time: TimeConstraint | None = None) -> str:
        k = _key(len(self.text))
        self.text[k] = original.strip()
        if location is not None:
            self.locations[k] = location
        if time is not None:
            self.times[k] = time
        if sensor is not None:
            self.sensors[k] = sensor if isinstance(sensor, tuple) else (sensor,)
        return f" {k} "

    def restore(self, s: str) -> str:
        out = re.sub(r"⟪[a-z]+⟫", lambda m: self.text.get(m.group(0), ""), s)
        return re.sub(r"\s+", " ", out).strip(" ,;:.")


def _unit_code(unit: str | None) -> str:
    """The unit code (readings.UNIT_CODES) of a UNIT match; degree forms ("°", "degrees F") are Celsius unless
    they say Fahrenheit."""
    if not unit:
        return ""
    u = re.sub(r"\s+", " ", unit)
    if u in UNIT_CODES and u not in ("c", "f"):
        return UNIT_CODES[u]
    if u.endswith("f") or "fahrenheit" in u:
        return "f"
    return "c"


def _sensor(reading: str | None, comparator: str, num: str | None, unit: str | None, span: str) -> SensorConstraint:
    code = _unit_code(unit)
    value = None if num is None else _to_float(num, f"'{span.strip()}'")
    if reading is None:
        if code in UNIT_READING:
            reading = UNIT_READING[code]
        elif code == "%":  # a percentage no reading names is a humidity (battery levels are said so)
            reading = "humidity_pct"
        else:
            reading = "ndvi" if value is not None and abs(value) <= 1.0 else "temperature_c"
    if value is not None and UNIT_READING.get(code) == reading:  # 98.6 F is 37 C, 1.5 kW is 1500 W
        value = round(to_canonical(value, code), 4)
    return SensorConstraint(reading, comparator, value, code)


def _cmp_code(cmp: str | None, post: str | None) -> str:
    if post:
        return L.COMPARATOR_POSTFIX[re.sub(r"\s+", " ", post)]
    if not cmp:
        return "approx"
    return L.COMPARATOR_PHRASES[re.sub(r"\s+", " ", cmp)]


def _cut(s: str, marks: _Marks) -> str:
    def loc(m: re.Match) -> str:
        g = m.groupdict()
        x = g.get("x1") or g.get("x2") or g.get("x3") or g.get("x4")
        y = g.get("y1") or g.get("y2") or g.get("y3") or g.get("y4")
        what = f"the coordinates '{m.group(0).strip()}'"
        return marks.add(m.group(0), location=Location(_to_float(x, what), _to_float(y, what)))

    s = _LOC1.sub(loc, s)
    s = _LOC2.sub(loc, s)

    def with_reading(m: re.Match) -> str:
        rd = L.READING_NAMES[re.sub(r"\s+", " ", m.group("rd"))]
        post = m.group("post") or m.groupdict().get("post2")
        c = _sensor(rd, _cmp_code(m.group("cmp"), post), m.group("num"), m.group("unit"), m.group(0))
        return marks.add(m.group(0), sensor=c)

    def comparative(m: re.Match) -> str:
        rd, sign = L.COMPARATIVES[re.sub(r"\s+", " ", m.group("adj"))]
        if m.group("neg"):  # "no warmer than 30 degrees": at most 30
            code = "le" if sign > 0 else "ge"
        else:
            code = "gt" if sign > 0 else "lt"
        c = _sensor(rd, code, m.group("num"), m.group("unit"), m.group(0))
        return marks.add(m.group(0), sensor=c)

    def superlative_reading(m: re.Match) -> str:
        rd = L.READING_NAMES[re.sub(r"\s+", " ", m.group("rd"))]
        sign = L.EXTREME_WORDS[m.group("ext")]
        return marks.add(m.group(0), sensor=SensorConstraint(rd, "max" if sign > 0 else "min"))

    def outdoes(m: re.Match) -> str:
        rd = L.READING_NAMES[re.sub(r"\s+", " ", m.group("rd") or m.group("rd2") or m.group("rd3"))]
        sign = L.OUTDO_COMPARATIVES[m.group("cmp")] if m.group("cmp") else L.OUTDO_VERBS[
            re.sub(r"\s+", " ", m.group("verb") or m.group("verb2"))]
        return marks.add(m.group(0), sensor=SensorConstraint(rd, "max" if sign > 0 else "min"))

    def superlative_adj(m: re.Match) -> str:
        if m.group("sup"):
            rd, sign = L.SUPERLATIVES[m.group("sup")]
        else:
            rd, sign = L.GRADABLE[m.group("adj")]
            sign = sign if m.group("ml") == "most" else -sign
        return marks.add(m.group(0), sensor=SensorConstraint(rd, "max" if sign > 0 else "min"))

    def bare(m: re.Match) -> str:
        if m.group("num2") is not None:
            c = _sensor(None, _cmp_code(None, m.group("post2")), m.group("num2"), m.group("unit2"), m.group(0))
        else:
            c = _sensor(None, _cmp_code(m.group("cmp"), m.group("post")), m.group("num"), m.group("unit"), m.group(0))
        return marks.add(m.group(0), sensor=c)

    def between(m: re.Match) -> str:
        rd = L.READING_NAMES[re.sub(r"\s+", " ", m.group("rd"))] if m.group("rd") else None
        unit = m.group("unit") or m.group("u1")
        lo = _sensor(rd, "ge", m.group("lo"), unit, m.group(0))
        hi = _sensor(lo.reading, "le", m.group("hi"), unit, m.group(0))
        if lo.value > hi.value:
            lo, hi = dataclasses.replace(lo, value=hi.value), dataclasses.replace(hi, value=lo.value)
        return marks.add(m.group(0), sensor=(lo, hi))

    s = _SENS_RANGE.sub(between, s)
    s = _SUPER_THAN.sub(outdoes, s)
    s = _SUPER_READ2.sub(superlative_reading, s)
    s = _SUPER_READ.sub(superlative_reading, s)
    s = _COMPARATIVE.sub(comparative, s)
    s = _SENS_A.sub(with_reading, s)
    s = _SENS_B.sub(with_reading, s)
    s = _SENS_C.sub(bare, s)
    s = _SUPER_ADJ.sub(superlative_adj, s)
    s = _VERB_BEFORE_SENSOR.sub(lambda m: "" if m.group("k") in marks.sensors else m.group(0), s)

    # What is left of a number-bearing phrase could not be read.
    for rx, what in ((_BAD_AFTER_READING, "a sensor value"), (_BAD_BEFORE_UNIT, "a sensor value")):
        m = rx.search(s)
        if m:
            raise ParseError(f"could not read {what}: '{marks.restore(m.group('all'))}' (write a number, e.g. 'NDVI above 0.6' or 'about 55 degrees')")
    m = _DECIMAL_COMMA.search(s)
    if m and m.group("k") in marks.sensors:
        raise ParseError(f"could not read the number in '{marks.text[m.group('k')]}{m.group('rest')}' "
                         "(write decimals with a point, e.g. 0.6)")
    m = _BAD_PAREN.search(s)
    if m:
        raise ParseError(f"could not read the coordinates '{m.group(0)}' (write them like (3.5, 2.0) or x=3.5, y=2)")
    m = _BAD_XY.search(s)
    if m:
        raise ParseError(f"could not read the coordinates '{m.group(0).strip()}' (write them like x=3.5, y=2)")
    return s


# ----------------------------------------------------------------------------------------------------
# Segments


@dataclasses.dataclass
class _Node:
    """A noun phrase under construction: words plus relations to anchor nodes.

    states: attributes written after the noun ("that is switched on", "which is red", "made of oak").
    """

    words: list[str]
    relations: list[tuple[str, _Node]] = dataclasses.field(default_factory=list)
    states: list[str] = dataclasses.field(default_factory=list)

    @property
    def pronoun(self) -> bool:
        return bool(self.words) and all(w in L.PRONOUN_ANCHORS for w in self.words)

    def add_states(self, attrs) -> None:
        self.states += [a for a in attrs if a not in self.states]

    def target(self, antecedent: Target | None, depth: int = 0) -> Target:
        if self.pronoun and antecedent is not None:
            base = dataclasses.replace(antecedent, relations=())
        else:
            attrs, head = split_noun_phrase(self.words)
            # The phrase is the noun phrase with its descriptive words in front and without its states: "red
            # sofa" for "the sofa which is red", "lamp" for "the lamp that is on" (as the generator writes it).
            pre = [a for a in self.states if a not in _STATE_ATTRS and a not in attrs]
            n = len(head.split())  # states before the noun leave the phrase too: "the open bureau" -> "bureau"
            words = [w for w in self.words[: len(self.words) - n] if w.replace("-", " ") not in L.STATE_PHRASES]
            base = Target(" ".join(pre + words + self.words[len(self.words) - n :]), head,
                          attrs + tuple(a for a in self.states if a not in attrs))
            if len(base.phrase) > 200 or len(head) > 100 or any(len(a) > 60 for a in base.attributes):
                raise ParseError(f"could not read '{base.phrase[:80]}...' as one object: name it in fewer words")
        # A pronoun anchor refers to the previous goal; inside a nested phrase ("the desk, which has a lamp
        # on it") or with no previous goal it refers to the phrase itself, and adds nothing.
        rels = tuple(Relation(t, n.target(antecedent, depth + 1)) for t, n in self.relations
                     if not (n.pronoun and (antecedent is None or depth > 0)))
        return dataclasses.replace(base, relations=base.relations + rels)


@dataclasses.dataclass
class _Piece:
    node: _Node | None  # None: the segment names no goal of its own
    room: str | None = None
    locations: list[Location] = dataclasses.field(default_factory=list)
    sensors: list[SensorConstraint] = dataclasses.field(default_factory=list)
    relations: list[tuple[str, _Node]] = dataclasses.field(default_factory=list)
    attrs_only: list[str] = dataclasses.field(default_factory=list)  # "the big," describes the next goal
    attrs_after: list[str] = dataclasses.field(default_factory=list)  # ", which is on," describes the previous one
    connector: str = ""
    texts: list[str] = dataclasses.field(default_factory=list)
    ellipsis: bool = False  # "the coldest one": the head is the previous goal's
    led: bool = False  # a verb or politeness phrase opened the segment ("visit the blue one")
    det: bool = False  # the segment (after any verb) opens with a determiner ("the iron", not "red chair")
    clause: _Node | None = None  # the noun the segment's last relative clause describes ("the bin that is full")
    pair: bool = False  # "both boilers": two goals of that description
    into: bool = False  # "head into the flour store and ...": a place the robot enters
    time: TimeConstraint | None = None  # "the mug you saw first" (time_words.py)

    @property
    def empty(self) -> bool:
        return not (self.room or self.locations or self.sensors or self.relations or self.attrs_only or self.attrs_after
                    or self.time)


def _state_name(word: str) -> str:
    """'switched-on' -> 'switched on' (a hyphenated state is the same attribute); other words unchanged."""
    spaced = word.replace("-", " ")
    return L.STATE_PHRASES[spaced] if "-" in word and spaced in L.PARTICIPLE_STATES else word


def split_noun_phrase(words: list[str] | tuple[str, ...]) -> tuple[tuple[str, ...], str]:
    """('grey', 'fabric', 'coffee', 'table') -> (('grey', 'fabric'), 'coffee table').

    Leading descriptive words are attributes (an intensifier joins its colour: 'dark green'; a hyphenated
    state is spaced: 'switched-on' -> 'switched on'); the rest is the head, which keeps at least the last
    word, so unseen compounds stay whole.
    """
    words = list(words)
    k = 0
    while k < len(words) - 1 and L.is_modifier(words[k], words[k + 1]):
        k += 1
    attrs: list[str] = []
    for w in words[:k]:
        if attrs and attrs[-1] in L.INTENSIFIERS:
            attrs[-1] = f"{attrs[-1]} {w}"
        else:
            attrs.append(_state_name(w))
    return tuple(attrs), " ".join(words[k:])


def _phrase_index(phrases, at_start: bool) -> dict[str, list[tuple[str, ...]]]:
    """Phrases keyed by their first (at_start) or last word, longest first within a key."""
    out: dict[str, list[tuple[str, ...]]] = {}
    for p in _phrase_tuples(phrases):
        out.setdefault(p[0] if at_start else p[-1], []).append(p)
    return out


_LEADS = _phrase_index(L.LEAD_PHRASES, True)
_VERBS = _phrase_index(L.VERBS, True)
_TRAILS = _phrase_index(L.TRAILING_FILLERS, False)


def _strip_phrases(tokens: list[str], index: dict, at_start: bool = True) -> tuple[list[str], bool]:
    if not tokens:
        return tokens, False
    for p in index.get(tokens[0] if at_start else tokens[-1], ()):
        n = len(p)
        if len(tokens) >= n and (tuple(tokens[:n]) if at_start else tuple(tokens[-n:])) == p:
            rel = _relation_at(tokens, 0) if at_start else None
            if rel is not None and rel[1] > n:  # ", next to the sofa" is a relation, not "next" + "to the sofa"
                return tokens, False
            return (tokens[n:] if at_start else tokens[:-n]), True
    return tokens, False


_MODAL_AFTER_YOU = frozenset("to could would can will might may should must".split())
_INTRO_PREPS = frozenset("to towards toward into onto for past at".split())


def _verb_tail(tokens: list[str]) -> list[str]:
    """Drops the particles and preposition after a verb: "over to", "in at", "yourself to"."""
    while tokens and tokens[0] in L.VERB_PARTICLES:
        tokens = tokens[1:]
    if len(tokens) > 2 and tokens[0] in ("in", "off", "by") and tokens[1] in L.VERB_PREPOSITIONS:
        tokens = tokens[1:]  # "drop in at", "stop off at", "stop by at"
    if tokens and tokens[0] in L.VERB_PREPOSITIONS and len(tokens) > 1:
        tokens = tokens[1:]
    return tokens


def _plain_word(w: str) -> bool:
    """A word that can be a verb the lexicon does not know (not a determiner, modifier, relation, room or number)."""
    return (w.isalpha() and w not in L.DETERMINERS and not L.is_modifier(w) and w not in _RELS
            and w not in L.ROOM_WORDS and w not in L.NUMBER_WORDS)


def _strip_framing(tokens: list[str]) -> list[str]:
    """'all i need is for you to <verb> ...', 'it'd be wonderful if you could <verb> ...': any framing that ends in
    'you' and a modal or 'to' with nothing named before it (no determiner) is dropped."""
    for k in range(min(len(tokens) - 2, 10)):
        w = tokens[k]
        if w in L.DETERMINERS or w.startswith("⟪"):
            return tokens
        if (w == "you" and tokens[k + 1] in _MODAL_AFTER_YOU) or w in ("you'd", "you'll"):
            return tokens[k + (1 if w != "you" else 2):]
    return tokens


def _subordinate_lead(tokens: list[str]) -> int:
    """Length of a subordinate clause's opening before its object: "once you've reached [the kiln]", "when we
    get to [the loom]", "you have inspected [the lathe]" (after "after"); 0 if there is none."""
    j = 1 if tokens and tokens[0] in L.SUBORDINATORS else 0
    if j and tokens[0] == "as" and tokens[1:3] == ["soon", "as"]:
        j = 3
    if j >= len(tokens) or tokens[j] not in L.SUBJECT_PRONOUNS:
        return 0
    rest, known = _strip_phrases(tokens[j + 1 :], _VERBS)
    if known:  # a verb the lexicon knows, which may hold a determiner: "before you make a stop at the kiln"
        return len(tokens) - len(_verb_tail(rest))
    for k in range(j + 2, min(j + 8, len(tokens) - 1)):
        if tokens[k] in ("a", "an") and k + 3 < len(tokens) and tokens[k + 2] in L.VERB_PREPOSITIONS:
            continue  # "once you've made a stop at [the kiln]", "after you take a look at [the loom]"
        if tokens[k] in L.DETERMINERS:
            return k if all(w.replace("'", "").isalpha() for w in tokens[j + 1 : k]) else 0
    return 0


def _attendance(tokens: list[str]) -> int:
    """Length of an opening that says who is to attend a place ("your excellency is expected at [the bureau]", "the
    guests are awaited at [the harp]"): at most three words, "is" or "are", an attendance word
    (`lexicon.ATTENDANCE`) and a preposition before a determiner; 0 if there is none."""
    for j in range(1, min(4, len(tokens) - 3) + 1):
        if (tokens[j] in ("is", "are") and tokens[j + 1] in L.ATTENDANCE and tokens[j + 2] in _INTRO_PREPS
                and tokens[j + 3] in L.DETERMINERS and all(w.isalpha() for w in tokens[:j])):
            return j + 3
    return 0


def _strip_leaders(tokens: list[str]) -> tuple[list[str], bool]:
    """Drops politeness, verbs and order words in front and fillers behind; also says whether any led."""
    n0 = len(tokens)
    tokens = _strip_framing(tokens)
    changed, ing = True, False
    while changed and tokens:
        sub = _subordinate_lead(tokens) or _attendance(tokens)
        if sub:  # "once you've reached the kiln", "your excellency is expected at the kiln": the kiln is the goal
            tokens, changed = tokens[sub:], True
            continue
        before = tokens
        tokens, changed = _strip_phrases(tokens, _LEADS)
        if changed:
            # "begin by tracking down the kiln", "would you mind popping over to": an -ing verb follows
            ing = before[len(before) - len(tokens) - 1] in L.ING_LEADS
            continue
        tokens, changed = _strip_phrases(tokens, _VERBS)
        if changed:
            tokens, ing = _verb_tail(tokens), False
            continue
        if ing and len(tokens) > 1 and tokens[0].endswith("ing") and _plain_word(tokens[0]):
            tokens, changed, ing = _verb_tail(tokens[1:]), True, False
            continue
        if tokens and tokens[0] in ("to", "towards", "toward") and (len(tokens) > 1 or n0 > len(tokens)):
            tokens, changed = tokens[1:], True  # "drive to (3, 4)": the verb's place was cut out
        elif len(tokens) > 2 and tokens[0] in L.VERB_PARTICLES and tokens[1] in ("to", "towards", "toward"):
            tokens, changed = tokens[2:], True  # "then over to the loom"
    # An unknown verb before a determiner ("photograph the fridge", "scurry over to the fridge"): drop it.
    for k in range(1, min(5, len(tokens) - 1) if _boundary_at(tokens, 0) is None else 0):
        if tokens[k] in ("a", "an") and k + 3 < len(tokens) and tokens[k + 2] in L.VERB_PREPOSITIONS:
            continue  # a light verb: "take a look at [the kiln]", "pay a visit to [the loom]"
        if tokens[k] in ("the", "a", "an", "my", "our", "your", "this", "these", "those", "all", "each", "both"):
            before = tokens[:k]
            if before[0] in L.DETERMINERS:
                break
            if k < 4 and all(w.isalpha() and not L.is_modifier(w) and _relation_at(before, i) is None
                             for i, w in enumerate(before)):
                tokens = tokens[k:]
            elif (_plain_word(before[0]) and before[-1] in _INTRO_PREPS
                  and (all(w in L.VERB_PARTICLES for w in before[1:-1])
                       or (len(before) == 4 and before[1] in ("a", "an") and _plain_word(before[2]))
                       or (any(w in L.MODALS or w in L.SUBJECT_PRONOUNS for w in before[:-1])
                           and all(_plain_word(w) or w in L.VERB_PARTICLES for w in before[1:-1])))):
                # "scurry over to [the kiln]", "take a look at [the kiln]"; a modal or a subject names a doer,
                # so what follows it is a verb: "must call at [the kiln]", "down we go to [the loom]"
                tokens = tokens[k:]
            break
    led = len(tokens) < n0
    changed = True
    while changed and tokens:
        tokens, changed = _strip_phrases(tokens, _TRAILS, at_start=False)
    return tokens, led


def _relation_at(tokens: list[str], i: int) -> tuple[str, int] | None:
    """(relation type, tokens used) when a relation phrase starts at tokens[i]."""
    for phrase, rtype in _RELS.get(tokens[i], ()) if i < len(tokens) else ():
        n = len(phrase)
        if tuple(tokens[i : i + n]) == phrase:
            return rtype, n
    return None


# A participle the lexicon does not know, standing between a noun and its relation ("the shelf unit snuggled next
# to the drums", "the lamp hovering by the sofa"): a relative-clause word like "sitting" or "placed", unless it
# begins a state ("switched on"), is a word the lexicon gives another role, or follows no noun (a name ending
# like a participle: "the daybed beside the easel", "the olive daybed", "the painting above the fire").
_PARTICIPLE = re.compile(r"[a-z]{3,}(?:ed|ing)")
_NO_LEADER = frozenset(w for p in L.STATE_PHRASES for w in p.split()) | frozenset(p.split()[0] for p in L.RELATION_PHRASES)


def _leader(tokens: list[str], j: int) -> bool:
    """tokens[j] may stand between a noun and its relation (`lexicon.RELATIVE_LEADERS`, or an unknown participle
    after a noun)."""
    tok = tokens[j]
    if tok in L.RELATIVE_LEADERS:
        return True
    if _PARTICIPLE.fullmatch(tok) is None or tok in _NO_LEADER or tok in L.CLOSED_CLASS or j == 0:
        return False
    prev = tokens[j - 1]
    return (prev.isalpha() and prev not in L.CLOSED_CLASS and not L.is_modifier(prev)
            and _PARTICIPLE.fullmatch(prev) is None)


def _boundary_at(tokens: list[str], i: int) -> tuple[str, int, bool] | None:
    """A relation starting at i, possibly after relative-clause words: (type, tokens used, is_room_prep)."""
    j = i
    while j < len(tokens) and _leader(tokens, j) and j - i < 4:
        r = _relation_at(tokens, j)
        if r is not None:
            break
        j += 1
    r = _relation_at(tokens, j)
    if r is None:
        return None
    return r[0], j - i + r[1], tokens[j] in _ROOM_PREPS and r[1] <= 2


_STATES = _by_first_word(L.STATE_PHRASES)
# A verb that closes a clause around its subject: "in the room where the kiln (that is lit) is".
_CLOSING_VERBS = frozenset("is are was were sits stands lies stays".split())
_CLAUSE_END = frozenset("and or but yet not".split()) | L.RELATIVE_PRONOUNS | L.RELATIVE_CONTRACTED


def _np_end(tokens: list[str], k: int) -> bool:
    """Nothing more of this noun phrase follows tokens[k-1]: the end, a conjunction, a relation or a clause."""
    return (k >= len(tokens) or tokens[k] in _CLAUSE_END or _boundary_at(tokens, k) is not None
            or (k == len(tokens) - 1 and tokens[k] in _CLOSING_VERBS))


def _state_at(tokens: list[str], j: int) -> tuple[str, str, int] | None:
    """(as written, attribute, tokens used) when a state phrase starts at tokens[j] ('switched on', 'switched-on')."""
    if j < len(tokens) and "-" in tokens[j] and tokens[j].replace("-", " ") in L.PARTICIPLE_STATES:
        written = tokens[j].replace("-", " ")
        return written, L.STATE_PHRASES[written], 1
    for phrase, attr in _STATES.get(tokens[j], ()) if j < len(tokens) else ():
        if tuple(tokens[j : j + len(phrase)]) == phrase:
            return " ".join(phrase), attr, len(phrase)
    return None


def _post_attrs_at(tokens: list[str], i: int) -> tuple[list[str], int] | None:
    """Attributes written after a noun, from tokens[i]: (attributes, tokens used) or None.

    A relative clause ("that is switched on", "which is dark green", "that's open", "which is not lit", "that is
    made of oak", "which is ajar": after a copula any one to three plain words that end the phrase) or a bare
    participle ("switched on", "unplugged"). What follows must end the noun phrase, so "that is on the table"
    is a relation and "that has red cushions" a 'with' anchor, not attributes.
    """
    n = len(tokens)
    j, clause, copula, negated = i, False, False, False
    if j < n and tokens[j] in L.RELATIVE_PRONOUNS:
        j, clause = j + 1, True
    elif j < n and tokens[j] in L.RELATIVE_CONTRACTED:
        j, clause, copula = j + 1, True, True
    start = j
    while j < n and j - start < 4 and (tokens[j] in L.COPULA_WORDS or tokens[j] in L.NEGATED_COPULAS):
        negated = negated or tokens[j] in L.NEGATED_COPULAS
        copula = copula or tokens[j] in L.TRUE_COPULAS  # "is", not "left" ("the front left speaker")
        j, clause = j + 1, True
    if j >= n:
        return None
    made = next((m for m in L.MADE_OF if tuple(tokens[j : j + len(m)]) == m), None)
    if made:
        j += len(made)
    else:
        st = _state_at(tokens, j)
        if st is not None:
            written, attr, used = st
            if negated:
                attr = L.STATE_OPPOSITES.get(attr)
            if attr is None or not (clause or written in L.PARTICIPLE_STATES) or not _np_end(tokens, j + used):
                return None
            return [attr], j + used - i
        if not clause or negated:
            return None
    k = j
    while k < n and L.is_modifier(tokens[k], tokens[k + 1] if k + 1 < n else None):
        k += 1
    if k > j and _np_end(tokens, k):
        return list(split_noun_phrase([*tokens[j:k], "x"])[0]), k - i
    if made or not copula or negated:
        return None
    # An adjective the lexicon does not know ("which is ajar", "that is slightly dusty"): open vocabulary.
    k = j
    while k < n and k - j < 3 and tokens[k].replace("-", "").replace("'", "").isalpha() and not _np_end(tokens, k) \
            and tokens[k] not in L.DETERMINERS and tokens[k] not in L.FILLER_NOUNS and tokens[k] not in _DANGLING:
        k += 1
    if k == j or not _np_end(tokens, k):
        return None
    return [" ".join(tokens[j:k])], k - i


def _join_prenominal_states(tokens: list[str]) -> list[str]:
    """'the switched on lamp' -> 'the switched-on lamp': a two-word state before a noun is one modifier."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        st = _state_at(tokens, i)
        if (st is not None and st[2] == 2 and st[0] in L.PARTICIPLE_STATES
                and (not out or out[-1] in L.DETERMINERS or L.is_modifier(out[-1], tokens[i]))
                and not _np_end(tokens, i + 2)):
            out.append("-".join(tokens[i : i + 2]))
            i += 2
        else:
            out.append(tokens[i])
            i += 1
    return out


def _read_np(tokens: list[str], i: int) -> tuple[list[str], int]:
    # A clause with no subject of its own ("and stands beside the kiln", "sitting next to the loom"): no noun.
    if i < len(tokens) and tokens[i] not in L.DETERMINERS and _boundary_at(tokens, i) is not None:
        return [], i
    while i < len(tokens) and tokens[i] in L.DETERMINERS:
        i += 1
    if tuple(tokens[i : i + 2]) == ("one", "of"):
        i += 2
        while i < len(tokens) and tokens[i] in L.DETERMINERS:
            i += 1
    words = []
    while i < len(tokens):
        if words and (_post_attrs_at(tokens, i) is not None or _boundary_at(tokens, i) is not None):
            break
        if not words and _relation_at(tokens, i) is not None:
            break
        if words and tokens[i] == "or" and _boundary_at(tokens, i + 1) is not None:
            break  # "with the kettle on it or beside it"
        if words and (tokens[i] in _RELATIVE_WORDS):
            break  # "the kiln which can be found near the loom": a clause, read by the caller

        words.append(tokens[i])
        i += 1
    # Relative-clause words left before a cut-out sensor phrase: "the fridge that is (colder than 5 C)",
    # "the appliance that is the (warmest)".
    while len(words) > 1 and (words[-1] in _DANGLING or words[-1] in L.DETERMINERS):
        words.pop()
    return words, i


def _room_name(words: list[str]) -> str:
    if len(words) >= 2 and words[-1] in L.ROOM_SUFFIXES and words[-1] != "room":
        words = words[:-1]
    return " ".join(words)


_RELATIVE_WORDS = L.RELATIVE_PRONOUNS | L.RELATIVE_CONTRACTED | frozenset({"whose"})
_CONTINUATION = (frozenset("which who where whose is are was were".split()) | L.RELATIVE_CONTRACTED | L.NEGATED_COPULAS
                 | L.MODALS)  # "and can be found near the loom"
_MODALS = frozenset("should must will would can could might may does do did".split())


def _continues(tokens: list[str]) -> bool:
    """The segment only adds to the previous goal: ", which is on", "and is switched on", ", that should be ..."
    ("that lamp" is a determiner and a noun)."""
    if not tokens:
        return False
    if tokens[0] in _CONTINUATION:
        return True
    if tokens[0] in ("it", "it's", "this", "they", "they're") and len(tokens) > 1 and (
            _boundary_at(tokens, 1) is not None or _post_attrs_at(tokens, 1) is not None):
        return True  # "it's next to the sofa", "it is switched on": the previous goal, described
    nxt = tokens[1] if len(tokens) > 1 else None
    return tokens[0] == "that" and (nxt is None or nxt in L.COPULA_WORDS or nxt in L.NEGATED_COPULAS
                                    or nxt in L.RELATIVE_LEADERS or nxt in _MODALS or _relation_at(tokens, 1) is not None)


def _possessive_room(tokens: list[str], piece: _Piece) -> list[str]:
    """'the pantry's kettle', 'the games room's warmest lamp': a room in the possessive names the goal's room."""
    if not tokens or tokens[0] not in L.DETERMINERS:
        return tokens
    for k in range(1, min(4, len(tokens) - 1)):
        if tokens[k].endswith("'s"):
            words = [*tokens[1:k], tokens[k][:-2]]
            if L.is_room_phrase(words):
                piece.room = piece.room or _room_name(words)
                return [tokens[0], *tokens[k + 1 :]]
            return tokens
    return tokens


def _sequencing_clause(tokens: list[str], raw: list[str]) -> bool:
    """A subordinate clause that names nothing: "once you're done there", "when you've finished", "after we
    get there" (a subordinator or a subject pronoun first, no determiner, no cut-out phrase)."""
    if not tokens or len(tokens) != len(raw) or any(t in L.DETERMINERS for t in tokens):
        return False
    return tokens[0] in L.SUBORDINATORS or (tokens[0] in L.SUBJECT_PRONOUNS and len(tokens) > 1)


_INTO = re.compile(r"\b(?:head|go|walk|step|pop|nip|move|come|get|wander|drive|roll)\s+"
                   r"(?:back\s+|over\s+|on\s+)?(?:into|in\s+to)\s+the\b")
# The words of a clause that only gives a reading: "humidity should be", "its temperature must read", "ideally",
# "the humidity in it should be"; it names the reading or refers back ("it should be hotter than 200 degrees").
_READING_WORDS = frozenset(k for k in L.READING_NAMES if " " not in k)
_READING_TALK = _READING_WORDS | frozenset(
    "its the it it's this that should be is must will would read reads reading show shows showing measure measures level "
    "value around about roughly approximately currently now still ideally ought to in inside of on measurement".split())
_REFERS_BACK = frozenset("it its it's this that should must will would ought be is".split())
_READING_NOUNS = _READING_WORDS | frozenset("reading readings value measurement".split())  # "the reading on it should be"


_APPOSITION_LEADS = (("it's",), ("it", "is"), ("that's",), ("that", "is"), ("this", "is"))


def _strip_apposition(tokens: list[str]) -> list[str]:
    """ "it's the thing running at over 100 degrees on the worktop": what follows describes the previous goal."""
    for lead in _APPOSITION_LEADS:
        n = len(lead)
        if (tuple(tokens[:n]) == lead and len(tokens) > n + 2 and tokens[n] in ("the", "a", "an")
                and tokens[n + 1] in L.GENERIC_HEADS | {"one"}):
            return tokens[n + 2:]
    return tokens


def _parse_segment(seg: str, marks: _Marks, connector: str) -> _Piece:
    raw = _TOKEN.findall(seg)
    piece = _Piece(node=None, connector=connector, texts=[marks.restore(seg)])
    tokens = []
    for t in raw:
        if t == PAIR:
            piece.pair = True
        elif t.startswith("⟪"):
            if t in marks.locations:
                piece.locations.append(marks.locations[t])
            if t in marks.sensors:
                piece.sensors.extend(marks.sensors[t])
            if t in marks.times:
                piece.time = marks.times[t]
        else:
            tokens.append(t)
    if _sequencing_clause(tokens, raw):
        return piece  # "when you've finished there,": says only that what follows comes next
    m = _INTO.search(" ".join(tokens))  # "could you pop into the craft room": after any politeness
    piece.into = m is not None and "the" not in " ".join(tokens)[: m.start()].split()
    tokens, piece.led = _strip_leaders(tokens)
    tokens = _strip_apposition(tokens)
    if piece.sensors and tokens and all(w in _READING_TALK for w in tokens) and (
            _READING_NOUNS.intersection(tokens) or tokens[0] in _REFERS_BACK):
        return piece  # "- humidity should be about 80%": a reading of the previous goal
    room_end = next((k for k in range(3, min(len(tokens), 7)) if tokens[k] in ("the", "a", "an")), 0)
    if tokens[:2] == ["in", "the"] and room_end and L.is_room_phrase(tokens[2:room_end]):
        # "in the music room the record player on the credenza": the room comes first
        piece.room, tokens, piece.led = _room_name(tokens[2:room_end]), tokens[room_end:], True
    tokens = _possessive_room(tokens, piece)
    tokens = _join_prenominal_states(tokens)
    piece.det = bool(tokens) and tokens[0] in L.DETERMINERS
    # ", which should be hotter than 100 degrees", ", which is on,": constraints of the previous goal; so is a
    # state with no noun ("... that is teal and switched on in the den").
    continuation = _continues(tokens) or _post_attrs_at(tokens, 0) is not None
    words, i = ([], 0) if continuation else _read_np(tokens, 0)
    top = _Node(words)
    current = top
    while i < len(tokens):
        post = _post_attrs_at(tokens, i)
        if post is not None:  # "that is switched on", "which is red": the nearest noun's attributes
            current.add_states(post[0])
            piece.clause = current
            i += post[1]
            continue
        b = _boundary_at(tokens, i)
        if b is None:  # words of a clause that are neither attributes nor relations ("which should be")
            i += 1
            continue
        rtype, used, room_prep = b
        prep = tokens[i + used - 1]
        if tokens[i] in L.RELATIVE_PRONOUNS or tokens[i] in L.RELATIVE_CONTRACTED:
            piece.clause = current  # "the desk that sits near the lamp [and has ...]": the desk's clause
        i += used
        if i < len(tokens) and tokens[i] == "or":
            alt = _boundary_at(tokens, i + 1)
            if alt is not None:  # "on or next to it": the last relation is read, the first has no anchor
                continue
        anchor, i = _read_np(tokens, i)
        if room_prep and L.is_room_phrase(anchor):
            piece.room = piece.room or _room_name(anchor)
            continue
        if not anchor or all(w in L.FILLER_NOUNS and w not in L.PRONOUN_ANCHORS for w in anchor):
            continue  # "with" before a sensor phrase, "nearby"
        node = _Node(anchor)
        if not words and piece.led and current is top and not top.relations and prep in ("at", "to", "on"):
            # "start in the library at the reading lamp", "go in the den to the sofa": after the verb and its
            # room, the place the robot goes to is the goal, not an anchor; so is what a verb ends or starts on
            # ("and finish on the wheelbarrow")
            words, top = anchor, node
            current = node
            continue
        current.relations.append((rtype, node))
        current = node
    if words and words[-1] in ("one", "ones") and ((len(words) > 1 and words[-2] in _QUANTIFIERS) or (all(
            w in _SEQUENCE_WORDS for w in words[:-1]) and not (piece.sensors or piece.locations or piece.room or
                                                                 top.relations or top.states or piece.time))):
        # "pick up every one", "so long as each one is cleared", "and the last one, the speaker": the goals said
        # elsewhere, counted or put in order, no goal of its own
        return _Piece(node=None, connector=connector, texts=piece.texts)
    if words and words[-1] in ("one", "ones") and (len(words) > 1 or piece.sensors or piece.locations or
                                                      piece.room or top.relations or top.states):
        # "the coldest one", "the red one near the door": the head of the previous goal, elided.
        top.words = words[:-1]
        if L.is_room_phrase(top.words):  # "the kitchen one": the one in the kitchen
            piece.room = piece.room or _room_name(top.words)
            top.words = []
        piece.node, piece.ellipsis = top, True
        return piece
    if not words or all(w in L.FILLER_NOUNS for w in words):
        piece.relations = top.relations
        piece.attrs_after = top.states
    elif all(L.is_modifier(w, words[k + 1] if k + 1 < len(words) else "red") for k, w in enumerate(words)) and not (
        top.relations or top.states or piece.room or piece.locations or piece.sensors
    ):
        piece.attrs_only = list(words)  # "the big, red chair": "the big" describes the next goal
    else:
        piece.node = top
    return piece


def _only_related(p: _Piece) -> bool:
    """Whether an elided phrase ("the one ...") says nothing of its own but relations ("the one by the door")."""
    return (p.node is not None and all(w in ("one", "ones") for w in p.node.words) and not p.node.states
            and bool(p.node.relations or p.relations) and not (p.room or p.locations or p.sensors or p.attrs_after))


def _noun_follows(pieces: list[_Piece], i: int) -> bool:
    """Whether bare describing words (pieces[i]) run on through ', ' or 'and' into a noun without a determiner
    ("the big, red chair"), rather than end ("the shelf unit, lacquered, lilac, then ...")."""
    for q in pieces[i + 1:]:
        if q.connector not in (",", "and") or q.det or q.led or not (q.node is not None or q.attrs_only):
            return False
        if q.node is not None:
            return True
    return False


def _all_modifiers(words: list[str]) -> bool:
    return bool(words) and all(L.is_modifier(w, words[k + 1] if k + 1 < len(words) else "red") for k, w in enumerate(words))


def _attr_kind(attr: str) -> str:
    """What an attribute describes (colour, material, state, size), so 'the red chair, the blue one' lists two
    chairs while 'the heater, the black one' describes one."""
    last = attr.split()[-1]
    if attr in _STATE_ATTRS:
        return "state"
    if last in L.COLOURS or last.split("-")[-1] in L.COLOURS or (last.endswith("ish") and last[:-3] in L.COLOURS):
        return "colour"
    if last in L.MATERIALS:
        return "material"
    if last in L.SIZE_WORDS:
        return "size"
    return "other: " + attr


_STATE_ATTRS = frozenset(L.STATE_PHRASES.values())


def _clashes(goal: _Piece, extra: _Piece) -> bool:
    """Whether an elided phrase after a comma ("the blue one") names another object than the goal before it."""
    g, e = goal.node, extra.node
    if (goal.room and extra.room) or (goal.locations and extra.locations):
        return True
    if {c.reading for c in goal.sensors} & {c.reading for c in extra.sensors}:
        return True
    if (goal.relations or g.relations) and (extra.relations or e.relations):
        return True
    kinds = {_attr_kind(a) for a in (*split_noun_phrase(g.words)[0], *g.states)}
    return any(_attr_kind(a) in kinds for a in (*split_noun_phrase([*e.words, "x"])[0], *e.states))


# ----------------------------------------------------------------------------------------------------


# A line break ends a list item (one item a line is how lists are written) unless it only wraps a sentence: the
# next line goes on in lower case with no determiner ("go to the red\nsofa"), or the line before ends in a word
# that needs what follows ("go to the\nsofa", "the lamp near\nthe bed").
_LINE_BREAK = re.compile(r"(?P<last>\S*)[ \t]*(?:\r?\n|\r)\s*(?P<next>\S*)")
_NEEDS_MORE = frozenset("a an the my your our to of at in on near by with from into onto and or but then than".split())


def _line_break(m: re.Match) -> str:
    last, nxt = m.group("last"), m.group("next")
    before = m.string[: m.start("last")].split()[-1:]
    state = last.lower() in ("on", "off") and before and before[0].lower() in ("switched", "turned", "left", "still")
    item = (not nxt[:1].islower() or nxt.lower() in ("the", "a", "an", "my", "your", "our")
            ) and (last.lower().strip("\"'") not in _NEEDS_MORE or state)
    return f"{last}{' ; ' if item and last[-1:] not in ';,:' else ' '}{nxt}"


# A letter's closing on a line of its own, and the name under it: "Kind regards,\nPat", "Thanks,\nSam", "Best".
_SIGN_OFF = re.compile(r"(?:(?:\r?\n|\r)|(?<=[.!?])[ \t]+)\s*(?:(?:kind|best|warm|many|warmest)\s+)?(?:regards|wishes|thanks|thank\s+you|cheers"
                       r"|best|sincerely|yours(?:\s+(?:truly|sincerely))?)\s*[,.!]?\s*(?:(?:\r?\n|\r)[^\n\r]{1,30})?\s*$",
                       re.IGNORECASE)


# A telegram's full stop: "STOP" in capitals, a word of its own ("ARRIVE KITCHEN STOP THENCE FRIDGE STOP").
_TELEGRAM_STOP = re.compile(r"(?<![\w-])STOP(?![\w-])")


def input_problem(text) -> str | None:
    """Why `text` is no instruction at all, whatever reads it (not text, blank, longer than MAX_CHARS), or None.
    The instruction tagger reads what the parser cannot, but not this."""
    if not isinstance(text, str):
        return f"an instruction must be text, got {type(text).__name__}"
    if len(text) > MAX_CHARS:
        return f"the instruction is too long ({len(text)} characters; at most {MAX_CHARS})"
    if not text.strip():
        return "the instruction is empty: say where to go, e.g. 'go to the sofa, then the fridge'"
    return None


def _normalise(text) -> str:
    problem = input_problem(text)
    if problem is not None:
        raise ParseError(problem)
    # Degree look-alikes that NFKC would turn into letters: masculine ordinal "º", ring above "˚".
    t = unicodedata.normalize("NFKC", text.translate({0xBA: "°", 0x2DA: "°"}))
    t = t.translate({0x2212: "-", 0x2013: "-", 0x2014: " - ", 0x2018: "'", 0x2019: "'", 0x27EA: " ", 0x27EB: " "})
    t = re.sub(r"(?<=\d)[·•](?=\d)", ".", t)  # a raised decimal point: "0·63"
    t = _TELEGRAM_STOP.sub(" ; ", t)
    t = _LINE_BREAK.sub(_line_break, _SIGN_OFF.sub("", t))
    t = "".join(ch if ch.isprintable() else " " for ch in t).lower()
    t = re.sub(r"\s+", " ", t).strip()
    if not t:
        raise ParseError("the instruction is empty: say where to go, e.g. 'go to the sofa, then the fridge'")
    return t


_ARTICLES = ("the", "a", "an")
_RELATIVES = frozenset("that which who whose".split())
_GLUE = frozenset("also too plus additionally".split())  # said between two items the parser has no word for
_GLUE_TAIL = re.compile(rf"(?:\s+(?:{'|'.join(sorted(_GLUE))}))+\s*$")


def _glued(piece: _Piece) -> list[list[str]]:
    """The word lists of a parsed segment's phrases (its noun, its anchors', its room) that hold an article after
    their first word: no noun phrase does, so two items ran together where the parser knew no word between them
    ("the sofa the lamp", "the craft room the music stand", "the sofa also the lamp")."""
    out: list[list[str]] = []

    def walk(node: _Node | None) -> None:
        if node is not None:
            out.append(node.words)
            for _, a in node.relations:
                walk(a)

    walk(piece.node)
    for _, a in piece.relations:
        walk(a)
    out += [piece.room.split()] if piece.room else []
    return [w for w in out if any(x in _ARTICLES for x in w[1:-1])]


def _unglue(seg: str, marks: _Marks) -> list[str]:
    """A segment cut before each article that starts a second item inside one of its parsed phrases (`_glued`),
    less the glue words before the cut. Not where what follows is an object relative or ends in a preposition
    ("the room the lamp is in", "the chair the cat sleeps on"): there the second noun phrase belongs to the first."""
    glued = _glued(_parse_segment(seg, marks, ""))
    if not glued:
        return [seg]
    toks = [m for m in _TOKEN.finditer(seg) if not m.group(0).startswith("⟪")]
    words = [m.group(0) for m in toks]
    for w in glued:
        for k in range(1, len(w) - 1):
            j = next((i for i in range(k - 1, -1, -1) if w[i] not in _GLUE), 0)
            if w[k] not in _ARTICLES or w[j] in L.CLOSED_CLASS or "'" in w[j]:
                continue  # "same room as the", "there's the": the article opens the phrase of a word before it
            for p in range(k - j, len(words) - 1):
                if words[p - (k - j) : p + 2] != w[j : k + 2]:
                    continue
                rest = words[p + 1 :]
                cop = next((i for i, x in enumerate(rest) if x in L.TRUE_COPULAS), None)
                if (rest and rest[-1] in L.CLOSED_CLASS and rest[-1] not in ("one", "ones")) or (
                        cop is not None and not _RELATIVES & set(rest[:cop])):
                    continue
                if _READING_WORDS & set(next((rest[:i] for i, x in enumerate(rest) if x in L.CLOSED_CLASS), rest)):
                    continue  # "the dryer boasting the top air temperature reading": a reading is no goal of its own
                head = seg[: toks[p].start()]
                head = _GLUE_TAIL.sub(" ", head)
                if head.strip():
                    return [head, *_unglue(seg[toks[p].start():], marks)]
    return [seg]


# A line that opens a list item: a bullet or dash, "1.", "2)", "(a)", "[ ]" (round 41).
_ITEM_LINE = re.compile(r"^[ \t]*(?:[•·*▪►‣][ \t]*|(?:[–—-]|\(?\d{1,2}[.)]|\(?[a-h]\)|\[[ xX]?\])[ \t]+)\S")


def _preamble(text: str) -> str:
    """The lines before a list of two or more marked items ("Big table, this one.\n• the fern\n• the kiln" ->
    "Big table, this one."), up to a colon on the last of them that the first marked item follows ("Places to
    check: - the fern\n- the kiln" -> "Places to check:"), or "" when the text holds no such list or opens with it."""
    lines = text.splitlines()
    items = [i for i, line in enumerate(lines) if _ITEM_LINE.match(line)]
    if len(items) < 2 or items[0] == 0:
        return ""
    pre = lines[: items[0]]
    head, colon, tail = pre[-1].rpartition(":")
    if colon and _ITEM_LINE.match(tail):
        pre[-1] = head + colon
    return "\n".join(pre)


def _sends(seg: str) -> bool:
    """Whether a verb the lexicon knows leads the segment, after any politeness ("please go to the kiln")."""
    tokens, changed = [m.group(0) for m in _TOKEN.finditer(seg)], True
    while changed and tokens:
        tokens, changed = _strip_phrases(tokens, _LEADS)
    return _strip_phrases(tokens, _VERBS)[1]


def _segments(text: str, marks: _Marks) -> tuple[list[tuple[str, str]], str]:
    """Normalised `text` cut into (connector, segment) pairs, and the order it states ("strict" or "free")."""
    s = _normalise(text)
    m = _MULTIDOT.search(s)
    if m:
        raise ParseError(f"could not read the number starting '{m.group(0)}'")
    m = _ALTERNATIVES.search(s)
    if m:  # a task chain holds goals, not a choice between objects
        raise ParseError(f"'{m.group(0)}': a choice between objects is not supported; name the one to visit "
                         "(or list both to visit both)")
    s = cut_times(s, lambda original, t: marks.add(original, time=t))  # before canonical forms reword "first"
    s = _number_words(_canonical(s))
    s = _FIRST_OF_ALL.sub("first", s)
    s = _cut(s, marks)
    order = "strict"
    if _FREE.search(s):
        order = "free"
        s = _FREE.sub(" ", s)
    s = _STRICT.sub(" ", s)
    s, free = _order_remarks(s)
    order = "free" if free else order

    parts = _SPLIT.split(s)
    # re.split with one named group yields [seg, connector, seg, connector, ...]
    segments = [(parts[k - 1].strip() if k else "", parts[k]) for k in range(0, len(parts), 2)]
    # Two items run together with no word the parser knows between them are two segments.
    segments = [(c if i == 0 else ",", piece) for c, seg in segments for i, piece in enumerate(_unglue(seg, marks))]
    return segments, order


def parse_instruction(text: str) -> TaskChain:
    """Parses a free-text multi-goal instruction into a TaskChain; raises ParseError on bad input."""
    marks = _Marks()
    segments, order = _segments(text, marks)
    kept = [k for k, (_, seg) in enumerate(segments) if seg.strip()]
    pieces = [_parse_segment(segments[k][1], marks, re.sub(r"\s+", " ", segments[k][0])) for k in kept]
    # A list's preamble names the list, greets or sets the scene ("Big table, this one, so any order.\n• the
    # fern\n• the kiln", "CONDITION REPORT - ROUTE OF EXAMINATION\n1. the ..."): its pieces are no goals, unless
    # a verb sends the robot to something ("Go to the kiln first, then:\n- the fern"). Round 41.
    pre = _preamble(text)
    if pre.strip():
        try:
            n_pre = sum(1 for _, seg in _segments(pre, _Marks())[0] if seg.strip())
        except ParseError:
            n_pre = 0
        keep = [i >= n_pre or (p.det and _sends(segments[k][1])) for i, (k, p) in enumerate(zip(kept, pieces))]
        kept = [k for k, ok in zip(kept, keep) if ok]
        pieces = [p for p, ok in zip(pieces, keep) if ok]
    # A colon between a segment and the next, whatever list mark follows it ("jobs for today:\n- the kiln").
    colon = [any(c == ":" for c, _ in segments[k + 1 : nxt + 1]) for k, nxt in zip(kept, kept[1:] + [len(segments)])]

    # A heading before a colon names nothing: "route to take:", "first things first:", "i need two things seen:".
    pieces = [p for k, p in enumerate(pieces) if not (
        k + 1 < len(pieces) and colon[k] and not p.det and not p.locations and not p.sensors
        and not p.room and (p.node is None or not p.node.relations))]
    for p, q in zip(pieces, pieces[1:]):
        if (p.into and p.node is not None and q.node is not None and not q.room and not p.relations and not p.sensors
                and not p.locations and not p.node.relations and not p.node.states and q.connector in ("and", "then", ",")):
            p.room, p.node = " ".join(p.node.words), None  # "head into the flour store and find the sack": its room
    goals: list[_Piece] = []
    pending: _Piece | None = None
    opened = False  # a bracket opened on words that say nothing ("(to be precise, the ..."): the next piece is in it
    for idx, p in enumerate(pieces):
        nxt = pieces[idx + 1] if idx + 1 < len(pieces) else None
        in_bracket, opened = p.connector in APPOSITION or (opened and p.connector == ","), False
        continues = (nxt is not None and nxt.connector in (",", "and") and not nxt.det and not nxt.led
                     and (nxt.node is not None or nxt.attrs_only))
        if (p.attrs_only and goals and p.connector in LIST_SEPARATORS
                and not (p.det or p.led or _noun_follows(pieces, idx))):
            # "the bean bag, turquoise, in the games room": bare describing words after a comma describe the goal
            p.attrs_after, p.attrs_only = p.attrs_only, []
        if p.attrs_only and not (goals and p.connector in APPOSITION) and not continues:
            # "the iron, the charcoal one": words that no noun follows are the noun ("the big, red chair" has one)
            if not (p.connector == "and" and not p.det and goals and goals[-1].clause is not None):
                p.node, p.attrs_only = _Node(p.attrs_only), []
        if (p.node is not None and p.connector == "and" and not p.det and not p.led and goals
                and goals[-1].clause is not None and _all_modifiers(p.node.words)):
            # "the chest that is ivory and open in the den": adjectives with no noun go on with the clause
            p.attrs_only, p.attrs_after, p.relations = p.node.words, p.node.states, p.node.relations
            p.node = None
        if (p.node is None and p.connector == "and" and goals and goals[-1].clause is not None and not p.det
                and not (p.empty and p.led)):
            # "the bin that is lilac and closed", "the desk that is oak and has a lamp on it": the clause goes on
            # ("...that is closed; and last of all, the minibar": order words alone lead the next goal)
            node = goals[-1].clause
            node.add_states(p.attrs_only + p.attrs_after)
            if node is goals[-1].node:
                goals[-1].relations += p.relations
            else:
                node.relations += p.relations
            p.relations, p.attrs_only, p.attrs_after = [], [], []
            _merge(goals[-1], p)
            continue
        if p.node is None:
            if p.empty:
                opened = in_bracket
                continue
            if p.attrs_only and goals and p.connector in APPOSITION:  # "the heater (black)"
                p.attrs_after, p.attrs_only = p.attrs_only, []
            anchor = _last_anchor(goals[-1]) if goals and p.connector in APPOSITION else None
            if anchor is not None and p.attrs_after and not (p.room or p.locations or p.sensors or p.relations):
                # "the stool by the loom (teal)", "near the fan (switched off)": what a bracket says straight after
                # an anchor is the anchor's, as in "the lamp by the shelf (the oak one)"
                anchor.add_states(p.attrs_after)
                goals[-1].texts += p.texts
                continue
            if p.attrs_only or not goals:
                pending = p if pending is None else _merge(pending, p)
            else:
                _merge(goals[-1], p)
            continue
        anchor = _last_anchor(goals[-1]) if goals and in_bracket and not p.ellipsis and pending is None else None
        if anchor is not None and split_noun_phrase(p.node.words)[1] == split_noun_phrase(anchor.words)[1]:
            # "the airer near the bin (to be precise, the bin by the door)": the anchor's noun said again in a
            # bracket straight after it is more about the anchor
            anchor.words = [w for w in split_noun_phrase(p.node.words)[0] if w not in anchor.words] + anchor.words
            anchor.add_states(p.node.states + p.attrs_after)
            anchor.relations += p.node.relations + p.relations
            goals[-1].texts += p.texts
            continue
        of_anchor = (p.ellipsis and goals and p.connector in LIST_SEPARATORS and not p.led and _only_related(p)
                     and _last_anchor(goals[-1]) is not None)
        if p.ellipsis and goals and pending is None and (
            p.connector in APPOSITION or of_anchor or
                (p.connector in LIST_SEPARATORS and not p.led and not _clashes(goals[-1], p))
        ):
            # "the heater, the black one," / "the fern (the one by the window)": more about the same goal; in
            # brackets straight after an anchor ("the lamp by the shelf (the one near the door)"), about the anchor,
            # as is "the one" with nothing but a relation after an anchor and a comma or dash ("the bin close to
            # the butcher block - the one parked next to the stand mixer -")
            anchor = _last_anchor(goals[-1]) if (p.connector in APPOSITION or of_anchor) and p.node is not None else None
            if anchor is not None:
                anchor.words = [w for w in p.node.words if w not in ("one", "ones")] + anchor.words
                anchor.add_states(p.node.states + p.attrs_after)
                anchor.relations += p.node.relations + p.relations
                goals[-1].texts += p.texts
                goals[-1].time = goals[-1].time or p.time  # "the armchair -- the one we passed first"
            else:
                _merge(goals[-1], p)
            continue
        if pending is not None:
            p = _merge(p, pending, prefix=True)
            pending = None
        if p.ellipsis:
            head = goals[-1].node.words[-len(split_noun_phrase(goals[-1].node.words)[1].split()) :] if goals else []
            p.node.words = p.node.words + (head or ["one"])
        goals.append(p)
    if pending is not None and goals:
        _merge(goals[-1], pending)
    if any(g.det for g in goals):  # "...ring out to the credenza. Stand.": a one-word sentence with no determiner,
        # where the other goals have theirs, is a command or a sign-off (a list that drops determiners drops them all)
        goals = [g for g in goals if not (
            g.connector in (".", "!", "?") and not g.det and g.node is not None and len(g.node.words) == 1
            and not (g.room or g.locations or g.sensors or g.relations or g.node.relations or g.node.states))]
    if any(g.time is not None for g in goals):  # a time-indexed instruction names its objects with determiners ("the
        # mug you saw first"): its pieces with none and no mark are vocatives, greetings and sign-offs ("okay, team,",
        # "chop chop", "heard?", "off you go to it, love")
        goals = [g for g in goals if g.det or g.time is not None or g.room or g.locations or g.sensors] or goals
    if not goals:
        raise ParseError(
            "no recognisable goal in the instruction: name at least one place or object to go to, "
            "e.g. 'go to the sofa' or 'find the red chair near the desk'"
        )
    goals = [x for g in goals for x in ((g, dataclasses.replace(g, connector="and")) if g.pair and g.node else (g,))]
    if len(goals) > MAX_SUBGOALS:
        raise ParseError(f"too many goals ({len(goals)}; at most {MAX_SUBGOALS})")
    # Reorder: "X after Y" / "X, but first Y" put Y before X; "before Y, X" puts X before Y.
    k = 0
    while k < len(goals):
        c = goals[k].connector
        if k > 0 and c in SWAP_BACK:
            goals[k - 1], goals[k] = goals[k], goals[k - 1]
            goals[k - 1].connector = ""
        elif k == 0 and c == "before" and len(goals) > 1:
            goals[0], goals[1] = goals[1], goals[0]
            goals[1].connector = ""
            k += 1
        k += 1

    subgoals: list[Subgoal] = []
    for idx, g in enumerate(goals):
        antecedent = subgoals[-1].target if subgoals else None
        target = g.node.target(antecedent)
        extra = tuple(Relation(t, n.target(antecedent, 1)) for t, n in g.relations if not n.pronoun or antecedent)
        if extra:
            target = dataclasses.replace(target, relations=target.relations + extra)
        subgoals.append(
            Subgoal(
                index=idx,
                target=target,
                room=g.room,
                location=g.locations[0] if g.locations else None,
                sensors=tuple(g.sensors),
                text=" ".join(t for t in g.texts if t),
                time=g.time,
            )
        )
    subgoals_t = tuple(subgoals)
    return TaskChain(
        instruction=text.strip(),
        subgoals=subgoals_t,
        order=order,
        dependencies=derive_dependencies(subgoals_t, order),
        parser="rules",
    )


# A remark about the order that the phrase lists above do not know ("order not important", "the order makes no
# difference to me", "i don't care which one first"): a short clause about the order or about which goes first,
# naming no object, read by its cue words. Indifference wins over emphasis ("order matters" is strict, "order
# doesn't matter" is free). A negation alone is no indifference: it says the order is free only where it negates
# emphasis ("order not important"); otherwise it forbids disorder ("no station out of sequence", "do not alter
# order", "no skips, no sequence breaks"), and the order stays as written (round 28+: reading a strict order as free
# fails the episode, reading a free one as strict only lengthens the route).
_ORDER_CLAUSE = re.compile(r"[^.;:!?()\[\],⟪⟫]*\b(?:order|sequence|first)\b[^.;:!?()\[\],⟪⟫]*")
_FREE_CUES = frozenset("any anything either whatever whichever no not never matter difference care mind fussy fussed bothered "
                       "flexible free choose pick decide optional random irrelevant unimportant up yours particular".split())
_NEGATIONS = frozenset("no not never".split())
_EMPHASIS = frozenset("important matters counts".split())
_STRICT_CUES = frozenset("this that given listed as keep stick follow strict strictly exact exactly same written shown above "
                         "below important matters counts specified numbered sequence order".split())
_FIRST_CUES = frozenset("which what either whichever".split())


def _order_remarks(s: str) -> tuple[str, bool]:
    """(s without its remarks about the order, whether one says the order is free)."""
    free = False

    def read(m: re.Match) -> str:
        nonlocal free
        words = m.group(0).replace("n't", " not").split()
        if not words or len(words) > 9 or ("first" in words and not any(w in ("order", "sequence") for w in words)
                                           and not _FIRST_CUES & set(words)):
            return m.group(0)
        rest = [w for k, w in enumerate(words) if not (w in ("the", "a", "an") and k + 1 < len(words)
                                                       and words[k + 1] in ("order", "sequence"))]
        if any(w in ("the", "a", "an", "my", "your", "our") for w in rest):
            return m.group(0)  # "first the kettle", "visit the kettle in any order": goals, not remarks
        cues = _FREE_CUES & set(words)
        if cues and (cues - _NEGATIONS or _EMPHASIS & set(words)):
            free = True
            return " "
        return " " if _STRICT_CUES & set(words) else m.group(0)

    return _ORDER_CLAUSE.sub(read, s), free


def _last_anchor(g: _Piece) -> _Node | None:
    """The anchor whose words end the goal's text ("the lamp by the shelf" -> the shelf), if any."""
    words = _TOKEN.findall(g.texts[-1].lower()) if g.texts else []
    rels = list(g.relations) + (list(g.node.relations) if g.node is not None else [])
    while rels:
        a = rels[-1][1]
        if a.relations:
            rels = list(a.relations)
            continue
        return a if a.words and words[-len(a.words):] == a.words else None
    return None


def _merge(into: _Piece, extra: _Piece, prefix: bool = False) -> _Piece:
    """Adds a noun-less piece's (or an apposition's) constraints to a goal piece (in place; returns it)."""
    into.room = into.room or extra.room
    into.locations += extra.locations
    into.sensors += extra.sensors
    into.time = into.time or extra.time
    into.relations += extra.relations
    if extra.attrs_only:
        if into.node is not None:
            into.node.words = extra.attrs_only + into.node.words
        else:
            into.attrs_only = extra.attrs_only + into.attrs_only
    if extra.attrs_after:
        if into.node is not None:
            into.node.add_states(extra.attrs_after)
        else:
            into.attrs_after += [a for a in extra.attrs_after if a not in into.attrs_after]
    if extra.node is not None and into.node is not None:  # an apposition: "the black one near the door"
        into.node.words = extra.node.words + into.node.words
        into.node.add_states(extra.node.states)
        into.node.relations += extra.node.relations
    into.texts = (extra.texts + into.texts) if prefix else (into.texts + extra.texts)
    into.clause = (into.clause or extra.clause) if prefix else (extra.clause or into.clause)
    if into.clause is not None and not into.clause.words and into.node is not None:
        into.clause = into.node  # "the kiln - the red one - which is lit and ...": a noun-less piece's clause is the goal's
    return into
