"""Time-indexed goals in an instruction: "the mug you saw first", "the second lamp we passed", "where the chair
was before it moved", "the chair you spotted most recently".

The rule parser cuts these phrases out of the normalised (lower-case) text before it splits goals, as it cuts
sensor phrases, and the goal whose segment holds the mark gets the TimeConstraint. An ordinal or recency word
counts only when a perception verb or participle ties it to seeing ("you saw first", "the first ... you
spotted", "seen last"); without one it stays an order word ("first the mug, then the lamp").
"""

from __future__ import annotations

import re
from collections.abc import Callable

from ragnav_jax.language.types import TimeConstraint

_SEP = r"[\s-]+"
# ordinal or recency word -> (order, rank); multi-word forms are written with single spaces
ORDINALS: dict[str, tuple[str, int]] = {
    "first": ("first", 1), "1st": ("first", 1), "earliest": ("first", 1), "very first": ("first", 1),
    "second": ("first", 2), "2nd": ("first", 2), "third": ("first", 3), "3rd": ("first", 3),
    "fourth": ("first", 4), "4th": ("first", 4), "fifth": ("first", 5), "5th": ("first", 5),
    "last": ("last", 1), "latest": ("last", 1), "most recent": ("last", 1), "most recently": ("last", 1),
    "final": ("last", 1), "very last": ("last", 1), "lately": ("last", 1),
    "second to last": ("last", 2), "next to last": ("last", 2), "last but one": ("last", 2),
    "penultimate": ("last", 2), "penultimately": ("last", 2), "second last": ("last", 2),
    "second most recent": ("last", 2), "second most recently": ("last", 2), "one before last": ("last", 2),
    "second from last": ("last", 2), "second from the end": ("last", 2),
    "third to last": ("last", 3), "last but two": ("last", 3), "third last": ("last", 3),
    "third from last": ("last", 3),
    "fourth to last": ("last", 4), "fifth to last": ("last", 5),
    "third most recent": ("last", 3), "third most recently": ("last", 3), "antepenultimate": ("last", 3),
}
# forms that only work as adverbs after the verb, not before the noun, and vice versa
_ADJ_ONLY = ("final", "very first", "very last")
_ADV_ONLY = ("most recently", "second most recently", "third most recently", "penultimately", "lately",
             "one before last")


def _alt(words) -> str:
    return "|".join(w.replace(" ", _SEP) for w in sorted(words, key=len, reverse=True))


_ORD_ADV = _alt(k for k in ORDINALS if k not in _ADJ_ONLY)
_ORD_ADJ = _alt(k for k in ORDINALS if k not in _ADV_ONLY)
_SUBJ = r"(?:i|you|we|u|the\s+robot|it)(?:'ve|'d|\s+have|\s+had)?"
# perception verbs in the past (a present "you see first" is an order of work, not a memory)
_VERB = ("saw|seen|spotted|spied|noticed|passed|came\\s+across|come\\s+across|found|encountered|observed|met|clocked|"
         "glimpsed|sighted|caught\\s+sight\\s+of|ran\\s+into|laid\\s+eyes\\s+on|set\\s+eyes\\s+on|"
         "walked\\s+(?:past|by)|"
         "went\\s+(?:past|by)|drove\\s+(?:past|by)|rolled\\s+(?:past|by)|recorded|logged|detected|mapped|viewed|"
         "looked\\s+at|discovered|registered|picked\\s+up|saw\\s+(?:it|one)|eyeballed|happened\\s+(?:up)?on|"
         "stumbled\\s+(?:up)?on|stumbled\\s+across|bumped\\s+into|came\\s+upon|clapped\\s+eyes\\s+on|"
         "laid\\s+eyes\\s+upon|set\\s+eyes\\s+upon|caught\\s+a\\s+glimpse\\s+of|got\\s+a\\s+look\\s+at|"
         "checked\\s+(?:on|out)|looked\\s+in\\s+on|identified|"
         "(?:watched|saw)\\s+(?:you|it|the\\s+robot)\\s+(?:find|spot|pass)")
_PARTICIPLE = ("seen|spotted|noticed|observed|sighted|encountered|glimpsed|recorded|logged|detected|viewed|"
               "discovered|registered|found|passed|mapped")
_TRAIL = (r"(?:\s+(?:it|one|them))?(?:\s+of\s+all)?"
          r"(?:\s+(?:during|on|in|while|when|as)\s+(?:the|your|our|its|my|you\s+were|we\s+were)?\s*"
          r"(?:exploration|exploring|explored|tour|walk|walkthrough|walk-through|patrol|sweep|survey|run|round|"
          r"first\s+pass|scouting(?:\s+run)?|look\s+around|mapping(?:\s+run)?|rounds|walk-?round)\b)?"
          r"(?:\s+(?:earlier(?:\s+on)?|previously|today|yesterday|this\s+morning|back\s+then))?")
_WORD = r"(?!(?:is|are|was|were|be|been|being|'s)\b)[^\s,.;:!?()\[\]⟪⟫]+"  # a word of a noun phrase, no copula
_NP = rf"(?P<np>(?:{_WORD}\s+){{0,5}}?{_WORD})"
_DET = r"(?P<det>the|your|that|my|our)"

# "the first mug you saw", "the second-to-last lamp that we passed", "the third bookcase seen"
_PRE = re.compile(rf"\b{_DET}\s+(?P<ord>{_ORD_ADJ})\s+{_NP}\s+(?:(?:that|which)\s+)?"
                  rf"(?:{_SUBJ}\s+(?:{_VERB})|(?:(?:was|were)\s+)?(?:{_PARTICIPLE}))\b{_TRAIL}")
# "the first-seen mug", "the most recently spotted lamp"
_PRE_PART = re.compile(rf"\b{_DET}\s+(?P<ord>{_ORD_ADV}){_SEP}(?:{_PARTICIPLE})\b")
# "you first saw", "i most recently spotted"
_ADV_BEFORE = re.compile(rf"(?:\s*,)?\s+(?:(?:that|which)\s+)?{_SUBJ}\s+(?P<ord>{_ORD_ADV})\s+(?:{_VERB})\b{_TRAIL}")
# "you saw first", "we passed most recently", "the robot came across second"
_ADV_AFTER = re.compile(rf"(?:\s*,)?\s+(?:(?:that|which)\s+)?{_SUBJ}\s+(?:{_VERB}){_TRAIL}\s+(?P<ord>{_ORD_ADV})\b"
                        rf"(?:\s+of\s+all)?{_TRAIL}")
# "the mug seen first", "the lamp that was spotted most recently"
_PART_AFTER = re.compile(rf"(?:\s*,)?\s+(?:(?:that|which)\s+(?:was|were)\s+)?(?:{_PARTICIPLE})\s+(?P<ord>{_ORD_ADV})\b"
                         rf"{_TRAIL}")
_PLACE = r"(?:spot|place|position|location)"
_WHERE = rf"\b(?:(?:the|to\s+the)\s+{_PLACE}\s+)?where\s+"  # "(the spot) where ..."
# "where the chair was before it moved", "the place where the vase stood originally"
_BEFORE_MOVE = re.compile(
    rf"{_WHERE}{_DET}\s+{_NP}\s+"
    r"(?:was|were|stood|sat|used\s+to\s+(?:be|stand|sit))\s+"
    r"(?:before\s+(?:it|they)\s+(?:was\s+|were\s+|got\s+)?moved|originally|at\s+(?:the\s+)?(?:start|beginning|outset)|"
    r"at\s+first|in\s+the\s+beginning)\b")
# "the chair's old spot", "the vase's original position"
_OLD_SPOT = re.compile(rf"\b{_DET}\s+{_NP}'s\s+(?:old|original|previous|former|first|earlier)\s+{_PLACE}\b")
# "where you last saw the chair", "the spot where we first spotted the mug"
_WHERE_SEEN = re.compile(
    rf"{_WHERE}{_SUBJ}\s+(?P<ord>{_ORD_ADV})\s+"
    rf"(?:{_VERB})\s+(?P<det>the|a|an|your|that|my|our)\s+{_NP}(?=\s*(?:[,.;:!?]|$|\s+(?:then|and|in|on|near|by|"
    r"next|beside|before|after|please)\b))")


# "you saw more than one toolbox (in the garage), right? go to the first one you found", "there was more than one
# kiln on your rounds. go to the third one": the sentence that says several were seen names no goal; the ordinal
# "one" (or "of them") after it is that noun phrase (and room).
_SEVERAL = re.compile(rf"(?P<all>[^.?!;:]*?\b(?:more\s+than\s+(?:one|1)|every|each|all\s+(?:of\s+)?the)\s+{_NP}"
                      rf"(?P<room>\s+(?:in|within)\s+the\s+{_NP.replace('np', 'rm')})?"
                      r"(?=\s*(?:[.?!;:,]|-\s|$|\s+(?:earlier|before|right|didn't|did|today|during|on|yesterday|in\s+"
                      rf"(?:chronological\s+)?order)\b|\s+(?:that\s+|which\s+)?{_SUBJ}\s+(?:{_VERB})\b))"
                      r"[^.?!;:,]*?(?:[.?!;:,]+|\s-\s))")
_ROOM_AFTER = re.compile(r"\b(?:in|within|inside)\s+the\s+(?P<rm>[a-z][a-z -]*?)"
                         r"(?=\s+(?:in\s+(?:chronological\s+)?order|on|"
                         r"during|earlier|today|this|when|while)\b|\s*[,.;:!?]|\s*$)")
_ONE = re.compile(rf"\bthe\s+(?:(?P<ord>{_alt(ORDINALS)})(?:[\s-]+(?:one|of\s+them))?|one|of\s+them)\b")
# what makes the several a memory: someone saw them, or they were met on the exploration
_SEEN_THEN = re.compile(rf"\b{_SUBJ}\s+(?:{_VERB})\b|\b(?:rounds|walk-?round|survey|exploration|tour|patrol|sweep)\b")


def _several(s: str, mark: Callable[[str, TimeConstraint], str]) -> str:
    """Rewrites "... more than one X ... . ... the <ordinal> one <seen ...>" as "... the <ordinal> X <seen ...>" where
    a time phrase about the one follows, and "... the <ordinal> one" as "... the X <mark>" where the sentence naming
    the several says they were seen; otherwise unchanged."""
    m = _SEVERAL.search(s)
    one = _ONE.search(s, m.end()) if m else None
    if not one:
        return s
    room = m.group("rm") if m.group("room") else None
    if room is None:  # "every speaker we saw down in the music room": the room after the verb
        r = _ROOM_AFTER.search(m.group("all"), m.end("np") - m.start())
        room = r.group("rm") if r else None
    x = m.group("np") + (f" in the {room}" if room else "")
    probe = s[one.start():]
    if any(rx.search(probe) for rx in (_PRE, _ADV_BEFORE, _ADV_AFTER, _PART_AFTER)) or re.match(
            rf"the\s+(?:{_ORD_ADJ})\s+one\s+(?:(?:that|which)\s+)?{_SUBJ}\s+(?:{_VERB})\b", probe):
        said = f"the {one.group('ord') + ' ' if one.group('ord') else ''}{x}"
    elif one.group("ord") and _SEEN_THEN.search(m.group("all") + " " + s[m.end(): one.start()]):
        said = f"the {x}{mark(one.group(0), ordinal(one.group('ord')))}"
    else:
        return s
    return s[: m.start()] + " " + s[m.end(): one.start()] + said + s[one.end():]


# "counting back from the end of your rounds, the first X you saw": the ordinals count from the latest view
_COUNTING = re.compile(r"\b(?:reckoning|counting|working|going|starting)\s+(?P<back>back(?:wards)?\s+)?from\s+the\s+"
                       r"(?:very\s+)?(?P<from>end|start|beginning|outset|latest|most\s+recent|earliest|first)\b"
                       r"(?:\s+of\s+(?:the|your|our|my|its)\s+[^,.;:!?]*)?\s*[,;:]?")


# "the first radiator you clocked is the one i want": what follows the time phrase says only that it is the goal
_THE_ONE_I_WANT = re.compile(r"(⟪[a-z]+⟫)\s*(?:(?:is|'s)\s+the\s+one\s+(?:(?:that|which)\s+)?(?:to\s+which\s+)?"
                             r"(?:i|we)\b[^.;:!?]*"
                             r"|(?:(?:that|which)\s+)?(?:i'm|i\s+am|we're|we\s+are)\s+after\b)")


# "just before the last one", "straight after the first": one place further from the end counted from
_RELATIVE = re.compile(rf"(?P<one>\bone\s+)?\b(?:just|right|straight|immediately)\s+(?P<rel>before|after)\s+the\s+"
                       rf"(?P<ref>{_alt(ORDINALS)})"
                       r"(?:[\s-]+one)?\b")
_WORDS = {("first", 1): "first", ("first", 2): "second", ("first", 3): "third", ("first", 4): "fourth",
          ("first", 5): "fifth", ("last", 1): "last", ("last", 2): "second to last", ("last", 3): "third to last",
          ("last", 4): "fourth to last", ("last", 5): "fifth to last"}
# "it's the first chair we saw", "the target is the second one": the goal said as what something is
_PRESENTING = re.compile(r"\b(?:it(?:'s|\s+is)|(?:the\s+)?(?:target|priority|goal|aim)\s+is)\s+(?=the\s+[^.;:!?]*⟪)")


def _relative(m: re.Match) -> str:
    t = ordinal(m.group("ref"))
    away = (m.group("rel") == "before") == (t.order == "last")  # before the last / after the first: one further
    word = _WORDS.get((t.order, t.rank + (1 if away else -1)))
    return m.group(0) if word is None else f"{word} one" if m.group("one") else word


def _reversed(t: TimeConstraint) -> TimeConstraint:
    return TimeConstraint("last" if t.order == "first" else "first", t.rank)


def ordinal(text: str) -> TimeConstraint:
    """'second-to-last' -> TimeConstraint('last', 2)."""
    order, rank = ORDINALS[re.sub(_SEP, " ", text.strip())]
    return TimeConstraint(order, rank)


def cut_times(s: str, mark: Callable[[str, TimeConstraint], str]) -> str:
    """Replaces every time phrase of the normalised text `s` by `mark(original, constraint)` (a placeholder
    token with spaces around it), keeping the noun phrase it describes in place."""

    def keep_np(order: TimeConstraint | None):
        def sub(m: re.Match) -> str:
            t = order or ordinal(m.group("ord"))
            return f" {m.group('det')} {m.group('np')}{mark(m.group(0), t)}"
        return sub

    m = _COUNTING.search(s)
    if m:  # counting from the end reverses the ordinals that follow; counting from the start is how they read
        s = s[: m.start()] + s[m.end():]
        if m.group("back") or m.group("from") in ("end", "latest") or m.group("from").startswith("most"):
            mark = (lambda put: lambda original, t: put(original, _reversed(t)))(mark)
    s = _RELATIVE.sub(_relative, s)
    s = _several(s, mark)
    s = _BEFORE_MOVE.sub(keep_np(TimeConstraint("first", 1)), s)
    s = _OLD_SPOT.sub(keep_np(TimeConstraint("first", 1)), s)
    s = _WHERE_SEEN.sub(keep_np(None), s)
    s = _PRE.sub(keep_np(None), s)
    s = _PRE_PART.sub(lambda m: f" {m.group('det')}{mark(m.group(0), ordinal(m.group('ord')))}", s)
    for rx in (_ADV_BEFORE, _ADV_AFTER, _PART_AFTER):
        s = rx.sub(lambda m: mark(m.group(0), ordinal(m.group("ord"))), s)
    return _PRESENTING.sub("", _THE_ONE_I_WANT.sub(r"\1", s))
