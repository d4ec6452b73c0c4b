"""Held-out set no. 4 of time-indexed navigation instructions ("go to the object you saw at such a time").

Provenance
----------
Written by a helper session that the project started inside itself, told to write a held-out set of
time-indexed instructions without reading any instruction reader (parser) or any other sentence set's wording.

What it read: its brief, and the ``[tool.ruff]`` / ``[tool.ruff.lint]`` tables of ``pyproject.toml``. Nothing else in
the repository: no file under ``ragnav_jax/`` or ``tests/``, no README, nothing under ``experiments/``. The only
repository commands it ran were ``git worktree add`` (to make its own worktree), a check that the directories
``ragnav_jax/language`` and ``tests`` exist (by name, without listing them), a check that its own two target file
names were still free, ruff, and pytest on its own test file.

Slips: none known. It did not open, list or grep any other file of the project.

Voices (one drawn per instruction with ``rng``)
-----------------------------------------------
- ``pilot``: an airline captain talking as on the radio; clipped procedure words, tasking and acknowledgements.
- ``archivist``: a retired records archivist; formal, courteous, exact about sequence and chronology.
- ``landlady``: a northern-English pub landlady; warm, chatty, terms of endearment, regional idiom.

Each voice has five sentence shapes: the time words come before the noun, after the perception verb, in a
separate clause (as "the ... one"), or as counting/listing language, and the room (when given) sits after the
noun or after the verb. Perception verbs vary in person ("you", "we", "I", "the robot") and tense.

Semantics: ``order="first"`` ranks by earliest sighting (rank 1 = earliest, 2 = the second one seen, 3 = the third);
``order="last"`` ranks by latest sighting (rank 1 = most recent, 2 = the one before it, 3 = the one before that).
When ``room`` is given, the ranking is among objects of that kind in that room, and the room is named after
"in the". Outputs contain no digits, at most two sentences, and mention no object but the goal.

Tests broken on purpose (see ``tests/test_time_text_heldout4.py``; each time the module was restored from a copy and
checked byte-identical): (1) the pilot's next-to-last wording was swapped for third-to-last wording, and the pilot
reader test failed; (2) one landlady word was drawn with Python's global ``random`` instead of ``rng``; the
hypothesis-only same-seed test missed it at first, so an exhaustive same-seed test over every voice and shape was
added, which then failed on the re-break. All tests pass on the restored module.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

__all__ = ["time_goal_heldout4"]

Key = tuple[str, int]

_VOICES: tuple[str, ...] = ("pilot", "archivist", "landlady")


def _pick(rng: np.random.Generator, options: tuple[str, ...] | list[str]) -> str:
    return options[int(rng.integers(len(options)))]


def _in(room: str | None) -> str:
    return f" in the {room}" if room is not None else ""


# ---------------------------------------------------------------------------------------------------------------
# Time wording per voice. Slots: "pre" goes before the noun ("the ___ lamp"), "post" goes after the perception verb
# ("the lamp you saw ___"), "one" is a noun phrase completed by "the" ("the ___").
# ---------------------------------------------------------------------------------------------------------------

_TIME: dict[str, dict[str, dict[Key, tuple[str, ...]]]] = {
    "pilot": {
        "pre": {
            ("first", 1): ("first", "very first"),
            ("first", 2): ("second",),
            ("first", 3): ("third",),
            ("last", 1): ("last", "latest", "most recent"),
            ("last", 2): ("second-to-last", "next-to-last"),
            ("last", 3): ("third-to-last",),
        },
        "post": {
            ("first", 1): ("first", "first of all"),
            ("first", 2): ("second", "second from the start"),
            ("first", 3): ("third", "third from the start"),
            ("last", 1): ("last", "last of all", "most recently"),
            ("last", 2): ("second-to-last", "second from the end"),
            ("last", 3): ("third-to-last", "third from the end"),
        },
        "one": {
            ("first", 1): ("first one", "very first one"),
            ("first", 2): ("second one",),
            ("first", 3): ("third one",),
            ("last", 1): ("latest one", "most recent one"),
            ("last", 2): ("one before the latest", "next-to-last one"),
            ("last", 3): ("third-to-last one", "third most recent one"),
        },
    },
    "archivist": {
        "pre": {
            ("first", 1): ("first", "earliest", "very first"),
            ("first", 2): ("second",),
            ("first", 3): ("third",),
            ("last", 1): ("most recent", "latest", "last"),
            ("last", 2): ("penultimate", "second most recent", "next-to-last"),
            ("last", 3): ("antepenultimate", "third most recent"),
        },
        "post": {
            ("first", 1): ("first", "earliest", "first of all"),
            ("first", 2): ("second", "second in sequence"),
            ("first", 3): ("third", "third in sequence"),
            ("last", 1): ("most recently", "last of all"),
            ("last", 2): ("second most recently", "next-to-last"),
            ("last", 3): ("third most recently", "third from last"),
        },
        "one": {
            ("first", 1): ("first one", "earliest one"),
            ("first", 2): ("second one",),
            ("first", 3): ("third one",),
            ("last", 1): ("most recent one", "latest one"),
            ("last", 2): ("penultimate one", "second most recent one"),
            ("last", 3): ("antepenultimate one", "third most recent one"),
        },
    },
    "landlady": {
        "pre": {
            ("first", 1): ("first", "very first"),
            ("first", 2): ("second",),
            ("first", 3): ("third",),
            ("last", 1): ("last", "latest"),
            ("last", 2): ("last-but-one", "next-to-last"),
            ("last", 3): ("last-but-two",),
        },
        "post": {
            ("first", 1): ("first", "first of all"),
            ("first", 2): ("second",),
            ("first", 3): ("third",),
            ("last", 1): ("last", "most recently"),
            ("last", 2): ("last but one", "second to last"),
            ("last", 3): ("last but two", "third to last"),
        },
        "one": {
            ("first", 1): ("very first one", "first one"),
            ("first", 2): ("second one",),
            ("first", 3): ("third one",),
            ("last", 1): ("last one", "latest one"),
            ("last", 2): ("last-but-one", "one before the last one"),
            ("last", 3): ("last-but-two", "third-from-last one"),
        },
    },
}

# Subject + perception verb, as used after "the <noun>" ("the lamp you logged ...").
_SEEN: dict[str, tuple[str, ...]] = {
    "pilot": ("you saw", "you logged", "you spotted", "we passed", "we had eyes on", "the robot logged"),
    "archivist": (
        "you observed",
        "you encountered",
        "you came upon",
        "I watched you find",
        "the robot noted",
        "we catalogued",
    ),
    "landlady": (
        "you saw",
        "you clocked",
        "you came across",
        "you clapped eyes on",
        "we spotted",
        "you'd seen",
        "we came across",
    ),
}


def _t(rng: np.random.Generator, voice: str, slot: str, order: str, rank: int) -> str:
    return _pick(rng, _TIME[voice][slot][(order, rank)])


Shape = Callable[[np.random.Generator, str, str, int, str | None], str]


# --- pilot ---------------------------------------------------------------------------------------------------------


def _pilot_0(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    opener = _pick(rng, ("Roger", "Copy", "Copy that", "Affirm"))
    pre = _t(rng, "pilot", "pre", order, rank)
    seen = _pick(rng, _SEEN["pilot"])
    over = _pick(rng, (", over", ""))
    return f"{opener}, proceed direct to the {pre} {phrase} {seen}{_in(room)}{over}."


def _pilot_1(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    seen = _pick(rng, _SEEN["pilot"])
    post = _t(rng, "pilot", "post", order, rank)
    close = _pick(rng, ("Over.", "Confirm on arrival.", "Report when on station."))
    return f"Request you navigate to the {phrase}{_in(room)} {seen} {post}. {close}"


def _pilot_2(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    seen = _pick(rng, _SEEN["pilot"])
    one = _t(rng, "pilot", "one", order, rank)
    go = _pick(rng, ("proceed there now", "make your approach", "head there now"))
    return f"If {seen} more than one {phrase}{_in(room)} on the survey pass, target is the {one}; {go}."


def _pilot_3(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    heading = _pick(rng, ("New heading", "Next waypoint", "Your destination"))
    seen = _pick(rng, _SEEN["pilot"])
    post = _t(rng, "pilot", "post", order, rank)
    close = _pick(rng, ("Over.", "Confirm on arrival.", "Acknowledge."))
    return f"{heading}: the {phrase} {seen} {post}{_in(room)}. {close}"


def _pilot_4(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    opener = _pick(rng, ("Roger", "Copy", "Stand by for tasking"))
    one = _t(rng, "pilot", "one", order, rank)
    seen = _pick(rng, _SEEN["pilot"])
    over = _pick(rng, (", over", ""))
    return f"{opener}. Destination is the {phrase}{_in(room)}, the {one} {seen}{over}."


# --- archivist -----------------------------------------------------------------------------------------------------


def _archivist_0(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    pre = _t(rng, "archivist", "pre", order, rank)
    seen = _pick(rng, _SEEN["archivist"])
    reason = _pick(rng, ("", " I should like to examine it.", " Thank you kindly.", " I am much obliged."))
    return f"Would you kindly proceed to the {pre} {phrase} {seen}{_in(room)}?{reason}"


def _archivist_1(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    seen = _pick(rng, _SEEN["archivist"])
    listed = _pick(rng, ("list", "arrange"))
    chrono = "chronological" if order == "first" else "reverse chronological"
    nth = ("first", "second", "third")[rank - 1]
    return (
        f"If one were to {listed} every {phrase} {seen}{_in(room)} in {chrono} order, the one I require "
        f"would be the {nth} on that list; please proceed to it."
    )


def _archivist_2(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    one = _t(rng, "archivist", "one", order, rank)
    seen = _pick(rng, _SEEN["archivist"])
    thanks = _pick(rng, ("", " Thank you.", " Much obliged."))
    return f"Please go to the {phrase}{_in(room)}; specifically, the {one} {seen}.{thanks}"


def _archivist_3(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    seen = _pick(rng, ("you encountered", "you observed", "you came upon", "the robot noted"))
    post = _t(rng, "archivist", "post", order, rank)
    ask = _pick(rng, ("kindly go to", "please make your way to", "I should be grateful if you went to"))
    return f"If {seen} more than one {phrase}{_in(room)}, {ask} that which {seen} {post}."


def _archivist_4(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    pre = _t(rng, "archivist", "pre", order, rank)
    seen = _pick(rng, _SEEN["archivist"])
    ask = _pick(rng, ("kindly make your way to it", "please go there at your convenience", "do proceed to it"))
    return f"The item of interest is the {pre} {phrase} {seen}{_in(room)}; {ask}."


# --- landlady ------------------------------------------------------------------------------------------------------


def _landlady_0(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    pre = _t(rng, "landlady", "pre", order, rank)
    seen = _pick(rng, _SEEN["landlady"])
    tail = _pick(rng, ("", " Ta, pet.", " You're a star.", " I want to give it a once-over."))
    return f"Be a love and nip over to the {pre} {phrase} {seen}{_in(room)}, would you?{tail}"


def _landlady_1(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    pet = _pick(rng, ("pet", "love", "flower", "duck"))
    seen = _pick(rng, _SEEN["landlady"])
    post = _t(rng, "landlady", "post", order, rank)
    go = _pick(rng, ("Go and stand by it for me.", "Get yourself over there.", "Pop over and wait by it."))
    return f"Right, {pet}, that {phrase}{_in(room)}, the one {seen} {post}? {go}"


def _landlady_2(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    seen = _pick(rng, ("you saw", "you clocked", "you came across", "we spotted"))
    one = _t(rng, "landlady", "one", order, rank)
    return f"If {seen} more than one {phrase}{_in(room)} on the wander round, it's the {one} I'm after, so off you pop."


def _landlady_3(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    seen = _pick(rng, _SEEN["landlady"])
    post = _t(rng, "landlady", "post", order, rank)
    tail = _pick(rng, ("", " Cheers, love.", " Ta."))
    return f"Do us a favour and find the {phrase} {seen} {post}{_in(room)}, then wait there for me.{tail}"


def _landlady_4(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    pet = _pick(rng, ("pet", "love", "flower", "duck"))
    pre = _t(rng, "landlady", "pre", order, rank)
    seen = _pick(rng, _SEEN["landlady"])
    tail = _pick(rng, ("", " Ta.", " Go on with you."))
    return f"Now then, {pet}: the {pre} {phrase} {seen}{_in(room)}, that's where I want you.{tail}"


_SHAPES: dict[str, tuple[Shape, ...]] = {
    "pilot": (_pilot_0, _pilot_1, _pilot_2, _pilot_3, _pilot_4),
    "archivist": (_archivist_0, _archivist_1, _archivist_2, _archivist_3, _archivist_4),
    "landlady": (_landlady_0, _landlady_1, _landlady_2, _landlady_3, _landlady_4),
}


def _check(phrase: str, order: str, rank: int, room: str | None) -> None:
    if order not in ("first", "last"):
        raise ValueError(f"order must be 'first' or 'last', got {order!r}")
    if rank not in (1, 2, 3):
        raise ValueError(f"rank must be 1, 2 or 3, got {rank!r}")
    if not phrase.strip() or any(c.isdigit() for c in phrase):
        raise ValueError(f"phrase must be non-empty and digit-free, got {phrase!r}")
    if room is not None and (not room.strip() or any(c.isdigit() for c in room)):
        raise ValueError(f"room must be None or a non-empty, digit-free name, got {room!r}")


def _compose(
    rng: np.random.Generator, voice: str, shape: int, phrase: str, order: str, rank: int, room: str | None
) -> str:
    """One instruction in a given voice and sentence shape (the remaining choices drawn from ``rng``)."""
    _check(phrase, order, rank, room)
    return _SHAPES[voice][shape](rng, phrase, order, rank, room)


def _draw(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> tuple[str, int, str]:
    """(voice, shape index, text), every choice drawn from ``rng``."""
    _check(phrase, order, rank, room)
    voice = _VOICES[int(rng.integers(len(_VOICES)))]
    shape = int(rng.integers(len(_SHAPES[voice])))
    return voice, shape, _SHAPES[voice][shape](rng, phrase, order, rank, room)


def time_goal_heldout4(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
    """One instruction asking the robot to go to one object, identified by when the robot saw it.

    phrase: the object's noun phrase, lower case, without determiner (e.g. "mug", "grey mug", "floor lamp",
      "tall oak bookcase"); it must appear verbatim, whole, in the output (you may put a determiner or
      possessive before it, but no words inside it).
    order: "first" or "last". rank: 1, 2 or 3.
      ("first", 1): the one the robot saw earliest of all objects of that kind; ("first", 2): the second
      one it came across; ("first", 3): the third. ("last", 1): the one it saw most recently (latest);
      ("last", 2): the second most recent / the one before the last; ("last", 3): third most recent.
    room: a room name such as "kitchen", "living room", "laundry room", or None. When given, the
      object is in that room and the ranking is among the objects of that kind in that room; the room
      name must appear verbatim.
    """
    return _draw(rng, phrase, order, rank, room)[2]
