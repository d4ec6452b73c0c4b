"""Held-out TIME-INDEXED goal instructions, written blind.

Provenance
----------
Written by a helper session that the project started inside itself, told to write a held-out set of time-indexed
navigation instructions ("go to the <object> identified by when the robot saw it during exploration") WITHOUT reading
any instruction reader / parser of the project and without seeing any other set's wording.

What the author read: the brief it was given, and the ``[tool.ruff]`` / ``[tool.ruff.lint]`` tables of
pyproject.toml. Nothing under ragnav_jax/ or tests/, nor README.md, nor experiments/ was opened.

Slips: none in content. The only look at the repository beyond pyproject.toml was a shell existence check of the
directory ragnav_jax/language (output suppressed; no listing or file contents were shown) and a check that the two
new files did not exist yet. pytest, run as the brief says, may have loaded the repository's own pytest set-up
(conftest / config) on its own; none of it was opened or shown. A final ``git status --short`` in /work/main (to
confirm it was left untouched) listed the NAMES of three uncommitted files there under ragnav_jax/language/ (a
parser, a types module and a time-words module); their contents were never seen, and this set was finished before.

Voices (one is drawn per instruction with ``rng``)
--------------------------------------------------
* ``grandmother``: a retired grandmother, warm and chatty, old-fashioned British endearments and sign-offs.
* ``teen``: a teenager texting from a phone, all lower case, text-speak abbreviations, double question marks.
* ``chef``: a head chef on a busy service, clipped kitchen-brigade orders and call-backs.

Each voice has five sentence shapes (``_SHAPES[voice]``), several perception verbs, "you"/"we" subjects (and "I"
in frames), ordinal adjectives before the noun as well as adverbs after the verb, and several ways of saying "most
recent", "second" and "second / third most recent". When a room is given it appears as "in the <room>" and the
ranking is read among the objects of that kind in that room. Filler (frames, reasons, sign-offs) never uses a time or
order word, and no filler names another object.

Tests broken on purpose (recorded in tests/test_time_text_heldout.py too), each time restored afterwards:
(1) the chef voice's second-most-recent adjectives were replaced by plain "second" -> the chef reader test and the
public read-back test failed; (2) every voice's "second" / "third" (adjectives and adverbs) were written as "2nd" /
"3rd" -> the no-digit property test, all three per-voice reader tests and the public read-back test failed.
After restoring, all tests pass.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

import numpy as np

__all__ = ["time_goal_heldout"]

_Key = tuple[str, int]


def _pick(rng: np.random.Generator, options: Sequence[str]) -> str:
    return options[int(rng.integers(len(options)))]


def _tidy(text: str) -> str:
    text = re.sub(r"\s+", " ", text).strip()
    text = re.sub(r"\s+([,.?!])", r"\1", text)
    return text


def _cap(word: str) -> str:
    return word[:1].upper() + word[1:]


# ----------------------------------------------------------------------------------------------------------------
# Grandmother
# ----------------------------------------------------------------------------------------------------------------

_G_ADJ: dict[_Key, list[str]] = {
    ("first", 1): ["first", "very first", "earliest"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["last", "very last", "most recent", "latest"],
    ("last", 2): ["last-but-one", "next-to-last", "second-to-last"],
    ("last", 3): ["last-but-two", "third-to-last"],
}
_G_ADV: dict[_Key, list[str]] = {
    ("first", 1): ["first", "first of all"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["last", "last of all", "most recently"],
    ("last", 2): ["last but one", "next to last", "second to last"],
    ("last", 3): ["last but two", "third from last"],
}
_G_VERB = ["saw", "came across", "spotted", "laid eyes on", "happened upon", "noticed"]
_G_SUBJ = ["you", "we"]
_G_OPEN = ["hello, dear,", "now then, love,", "oh, sweetheart,", "yoo-hoo, pet,", ""]
_G_MOVE = ["toddle over to", "pop along to", "go and stand by", "make your way over to", "go over to"]
_G_ENDEAR = ["love", "dear", "pet", "sweetheart"]
_G_REASON = [
    "I want a proper look at it.",
    "My knees aren't up to it today.",
    "The grandchildren were asking after it.",
    "I've a feeling it wants a good dusting.",
    "",
]
_G_SIGN = ["Thank you, love.", "Ta, dear.", "Bless you.", "You're a treasure.", ""]


def _g1(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    return (
        f"{_pick(rng, _G_OPEN)} would you {_pick(rng, _G_MOVE)} the {_pick(rng, _G_ADJ[key])} {phrase} "
        f"{_pick(rng, _G_SUBJ)} {_pick(rng, _G_VERB)}{room_in}? {_pick(rng, _G_SIGN)}"
    )


def _g2(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    subj = _pick(rng, _G_SUBJ)
    return (
        f"{subj} {_pick(rng, _G_VERB)} more than one {phrase}{room_in} earlier on, didn't {subj}? "
        f"Would you {_pick(rng, _G_MOVE)} the one {subj} {_pick(rng, _G_VERB)} {_pick(rng, _G_ADV[key])}, "
        f"{_pick(rng, _G_ENDEAR)}?"
    )


def _g3(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    return (
        f"{_pick(rng, _G_OPEN)} the {phrase} {_pick(rng, _G_SUBJ)} {_pick(rng, _G_VERB)} "
        f"{_pick(rng, _G_ADV[key])}{room_in} - that's the one I'd like you to go to. {_pick(rng, _G_REASON)}"
    )


def _g4(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    return (
        f"I'd like you to {_pick(rng, _G_MOVE)} the {phrase}{room_in} that {_pick(rng, _G_SUBJ)} "
        f"{_pick(rng, _G_VERB)} {_pick(rng, _G_ADV[key])}, {_pick(rng, _G_ENDEAR)}. {_pick(rng, _G_REASON)}"
    )


def _g5(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    return (
        f"{_pick(rng, _G_OPEN)} do you remember the {_pick(rng, _G_ADJ[key])} {phrase} you "
        f"{_pick(rng, _G_VERB)}{room_in}? Off you go to it, {_pick(rng, _G_ENDEAR)}."
    )


# ----------------------------------------------------------------------------------------------------------------
# Teenager texting
# ----------------------------------------------------------------------------------------------------------------

_T_ADJ: dict[_Key, list[str]] = {
    ("first", 1): ["first", "very first"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["last", "very last", "most recent", "latest"],
    ("last", 2): ["second to last", "second-last", "next to last"],
    ("last", 3): ["third to last", "third-last"],
}
_T_ADV: dict[_Key, list[str]] = {
    ("first", 1): ["first", "first of all"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["last", "most recently", "last of all"],
    ("last", 2): ["second to last", "next to last"],
    ("last", 3): ["third to last", "third from last"],
}
_T_VERB = ["saw", "spotted", "clocked", "found", "ran into", "came across"]
_T_SUBJ = ["u", "we", "you"]
_T_OPEN = ["yo", "ok so", "hey", "heyy", "omg ok", ""]
_T_TAG = ["pls", "ty", "thx", "asap pls", "lol", "fr", "no rush", "ty ily", ""]


def _t1(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    return (
        f"{_pick(rng, _T_OPEN)} go to the {_pick(rng, _T_ADJ[key])} {phrase} {_pick(rng, _T_SUBJ)} "
        f"{_pick(rng, _T_VERB)}{room_in} {_pick(rng, _T_TAG)}"
    )


def _t2(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    subj = _pick(rng, _T_SUBJ)
    return (
        f"{_pick(rng, _T_OPEN)} {subj} {_pick(rng, _T_VERB)} more than one {phrase}{room_in} right?? "
        f"go to the {_pick(rng, _T_ADJ[key])} one {subj} {_pick(rng, _T_VERB)} {_pick(rng, _T_TAG)}"
    )


def _t3(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    return (
        f"the {phrase} {_pick(rng, _T_SUBJ)} {_pick(rng, _T_VERB)} {_pick(rng, _T_ADV[key])}{room_in}?? "
        f"thats where i need u {_pick(rng, _T_TAG)}"
    )


def _t4(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    return (
        f"{_pick(rng, _T_OPEN)} need u at the {phrase}{room_in} {_pick(rng, _T_SUBJ)} {_pick(rng, _T_VERB)} "
        f"{_pick(rng, _T_ADV[key])} {_pick(rng, _T_TAG)}"
    )


def _t5(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    return (
        f"{_pick(rng, _T_OPEN)} remember the {_pick(rng, _T_ADJ[key])} {phrase} {_pick(rng, _T_SUBJ)} "
        f"{_pick(rng, _T_VERB)}{room_in}? go there rn {_pick(rng, _T_TAG)}"
    )


# ----------------------------------------------------------------------------------------------------------------
# Head chef mid-service
# ----------------------------------------------------------------------------------------------------------------

_C_ADJ: dict[_Key, list[str]] = {
    ("first", 1): ["first", "very first", "earliest"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["last", "most recent", "latest"],
    ("last", 2): ["second-to-last", "second-last", "second most recent"],
    ("last", 3): ["third-to-last", "third-last", "third most recent"],
}
_C_ADV: dict[_Key, list[str]] = {
    ("first", 1): ["first", "first of all"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["last", "most recently"],
    ("last", 2): ["one before last", "second from last", "second to last"],
    ("last", 3): ["two before last", "third from last"],
}
_C_VERB = ["saw", "clocked", "spotted", "passed", "eyeballed", "came across"]
_C_SUBJ = ["you", "we"]
_C_OPEN = ["listen up -", "okay, team,", "eyes up -", "right,", "robot,", ""]
_C_SIGN = ["Heard?", "Go.", "Move it.", "Chop chop.", "Let's go.", ""]
_C_TIME = ["now", "quick", "right away", "sharpish"]


def _c1(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    return (
        f"{_pick(rng, _C_OPEN)} the {_pick(rng, _C_ADJ[key])} {phrase} {_pick(rng, _C_SUBJ)} "
        f"{_pick(rng, _C_VERB)}{room_in} - go to it. {_pick(rng, _C_SIGN)}"
    )


def _c2(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    return (
        f"{_pick(rng, _C_OPEN)} get over to the {phrase}{room_in} {_pick(rng, _C_SUBJ)} {_pick(rng, _C_VERB)} "
        f"{_pick(rng, _C_ADV[key])}. {_pick(rng, _C_SIGN)}"
    )


def _c3(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    subj = _pick(rng, _C_SUBJ)
    return (
        f"{subj} {_pick(rng, _C_VERB)} more than one {phrase}{room_in} - I want you at the "
        f"{_pick(rng, _C_ADJ[key])} one {subj} {_pick(rng, _C_VERB)}. {_pick(rng, _C_SIGN)}"
    )


def _c4(rng, phrase, key, room):
    room_in = f" in the {room}" if room else ""
    return (
        f"{_pick(rng, _C_OPEN)} I need you at the {phrase} {_pick(rng, _C_SUBJ)} {_pick(rng, _C_VERB)} "
        f"{_pick(rng, _C_ADV[key])}{room_in}, {_pick(rng, _C_TIME)}. {_pick(rng, _C_SIGN)}"
    )


def _c5(rng, phrase, key, room):
    lead = f"in the {room}:" if room else f"{_pick(rng, _C_OPEN)} where I need you:"
    return (
        f"{lead} the {_pick(rng, _C_ADJ[key])} {phrase} {_pick(rng, _C_SUBJ)} {_pick(rng, _C_VERB)}, "
        f"{_pick(rng, _C_TIME)}. {_pick(rng, _C_SIGN)}"
    )


_Shape = Callable[[np.random.Generator, str, _Key, "str | None"], str]

_SHAPES: dict[str, list[_Shape]] = {
    "grandmother": [_g1, _g2, _g3, _g4, _g5],
    "teen": [_t1, _t2, _t3, _t4, _t5],
    "chef": [_c1, _c2, _c3, _c4, _c5],
}
_VOICES: tuple[str, ...] = tuple(_SHAPES)
_LOWER_CASE_VOICES = frozenset({"teen"})  # texting: never capitalises; no shape starts with the phrase or room


def _finish(voice: str, text: str) -> str:
    text = _tidy(text)
    return text if voice in _LOWER_CASE_VOICES else _cap(text)


def _check(phrase: str, order: str, rank: int, room: str | None) -> _Key:
    if order not in ("first", "last"):
        raise ValueError(f"order must be 'first' or 'last', got {order!r}")
    if rank not in (1, 2, 3):
        raise ValueError(f"rank must be 1, 2 or 3, got {rank!r}")
    if not phrase or phrase != phrase.strip():
        raise ValueError(f"bad phrase {phrase!r}")
    if room is not None and (not room or room != room.strip()):
        raise ValueError(f"bad room {room!r}")
    return (order, int(rank))


def _in_voice(rng: np.random.Generator, voice: str, phrase: str, order: str, rank: int, room: str | None) -> str:
    """One instruction in a given voice (shape drawn with ``rng``)."""
    key = _check(phrase, order, rank, room)
    shapes = _SHAPES[voice]
    shape = shapes[int(rng.integers(len(shapes)))]
    return _finish(voice, shape(rng, phrase, key, room))


def _in_shape(
    rng: np.random.Generator, voice: str, index: int, phrase: str, order: str, rank: int, room: str | None
) -> str:
    """One instruction in a given voice and sentence shape (for the tests)."""
    key = _check(phrase, order, rank, room)
    return _finish(voice, _SHAPES[voice][index](rng, phrase, key, room))


def time_goal_heldout(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    """One instruction asking the robot to go to one object, identified by when the robot saw it.

    phrase: the object's noun phrase, lower case, without determiner (e.g. "mug", "grey mug", "floor lamp",
      "tall oak bookcase"); it appears verbatim, whole, in the output.
    order: "first" or "last". rank: 1, 2 or 3.
      ("first", 1): the one the robot saw earliest of all objects of that kind; ("first", 2): the second
      one it came across; ("first", 3): the third. ("last", 1): the one it saw most recently (latest);
      ("last", 2): the second most recent / the one before the last; ("last", 3): third most recent.
    room: a room name such as "kitchen", "living room", "laundry room", or None. When given, the
      object is in that room and the ranking is among the objects of that kind in that room; the room
      name appears verbatim.
    """
    voice = _VOICES[int(rng.integers(len(_VOICES)))]
    return _in_voice(rng, voice, phrase, order, rank, room)
