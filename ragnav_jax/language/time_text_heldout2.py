"""Held-out set no. 2 of TIME-INDEXED goal instructions ("go to the <thing> you saw <when>").

Provenance
----------
Written by a helper session that the project started inside itself, told to write a held-out, time-indexed
instruction set WITHOUT reading any instruction reader (parser) of the project or the wording of any other
sentence set, so that the parser can be measured on an author nobody tuned it on.

What the author read of the repository: the ``[tool.ruff]`` table of pyproject.toml, printed with a filter that
also showed its ``[tool.ruff.lint]`` sub-table (select / ignore lists) and nothing else. Nothing under ragnav_jax/
or tests/ was opened, nor README.md nor experiments/; no directory of the project was listed. The two files of
this set were created blind in a fresh worktree (/tmp/tq2).

Slips: (1) the author also printed the project's ``.gitignore`` (a list of ignored build / cache folders, to
check where hypothesis and pytest caches would go); that file is outside what the brief allowed, though it holds
no code and no wording. (2) ``test -d`` checks told the author that ragnav_jax/language/ and tests/ exist
(nothing of their content). (3) ``git status`` in the fresh worktree listed only the ``.venv`` link and, later,
this set's two files. (4) At the very end, a ``git status`` of /work/main (run to confirm it was left untouched)
showed two paths of the main checkout's uncommitted work: a modified module under ragnav_jax/language/ whose name
suggests time words, and a results folder under experiments/results/. Only those names were seen -- not their
content -- and the set was already finished and tested when they appeared. No code or wording of any
instruction reader or any other set was seen.

Voices (one drawn per instruction, each with six sentence shapes)
-----------------------------------------------------------------
* ``nurse``     -- a hospital ward nurse on a busy night shift: brisk but warm, thinks of the exploration as the
  robot's "rounds", small thanks at the end.
* ``foreman``   -- a building-site foreman: blunt, British trade slang, "walk-round", counts things off,
  "last but one" style ordinals.
* ``barrister`` -- a retired barrister: formal, over-precise, "for the avoidance of doubt", Latinate ordinals
  (penultimate, antepenultimate), may speak of the robot in the third person.

Semantics (identical in every voice)
------------------------------------
order "first", rank k: the k-th object of that kind the robot came across, counting from the start of the
exploration; order "last", rank k: the k-th counting back from the most recent sighting. With a room, the count
runs only over the objects of that kind in that room, and the wording ties the count to the room ("the second
X you saw in the kitchen", "In the kitchen, ... the X you saw second", "more than one X in the kitchen ...").
No other object is ever mentioned; the phrase and the room name appear verbatim; no digits are used.

Tests broken on purpose (details in the docstring of tests/test_time_text_heldout2.py): (1) the nurse's second
shape made to drop the room clause -> the exhaustive per-shape test failed for the nurse; (2) the barrister's
"antepenultimate" (rank 3 from the end) swapped for "penultimate" -> the barrister reader recovered rank 2 and the
per-shape test failed. Both restored byte for byte; 9 tests pass.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

_Key = tuple[str, int]


def _pick(rng: np.random.Generator, options: Sequence[str]) -> str:
    return options[int(rng.integers(len(options)))]


def _cap(text: str) -> str:
    return text[:1].upper() + text[1:]


def _pick_before_one(rng: np.random.Generator, options: Sequence[str]) -> str:
    """An ordinal to stand before the word "one" (so never "last-but-one one")."""
    return _pick(rng, [o for o in options if not o.endswith("one")])


def _in_room(room: str | None) -> str:
    return f" in the {room}" if room else ""


# ---------------------------------------------------------------------------------------------------------------
# Voice 1: ward nurse on a night shift
# ---------------------------------------------------------------------------------------------------------------

_NURSE_ADJ: dict[_Key, list[str]] = {
    ("first", 1): ["first", "very first", "earliest"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["last", "most recent", "latest"],
    ("last", 2): ["second-to-last", "second most recent", "next-to-last"],
    ("last", 3): ["third-to-last", "third most recent"],
}
_NURSE_ADV: dict[_Key, list[str]] = {
    ("first", 1): ["first", "earliest"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["last", "most recently"],
    ("last", 2): ["second-to-last", "second most recently", "next-to-last"],
    ("last", 3): ["third-to-last", "third most recently"],
}
_NURSE_VERB = ["saw", "came across", "checked on", "passed"]
_NURSE_OPEN = ["", "Quick one for you: ", "When you've got a sec, ", "Sorry to bother you, "]
_NURSE_CLOSE = ["", " Thanks, lovely.", " Thanks so much.", " Bless you."]


def _nurse_1(rng, phrase, order, rank, room):
    adj = _pick(rng, _NURSE_ADJ[order, rank])
    verb = _pick(rng, _NURSE_VERB)
    opener = _pick(rng, _NURSE_OPEN)
    body = f"could you go to the {adj} {phrase} you {verb}{_in_room(room)}, please?"
    return (opener + body if opener else _cap(body)) + _pick(rng, _NURSE_CLOSE)


def _nurse_2(rng, phrase, order, rank, room):
    adv = _pick(rng, _NURSE_ADV[order, rank])
    verb = _pick(rng, _NURSE_VERB)
    lead = f"Over in the {room}, head" if room else "Head"
    return f"{lead} to the {phrase} you {verb} {adv}, please." + _pick(rng, _NURSE_CLOSE)


def _nurse_3(rng, phrase, order, rank, room):
    adv = _pick(rng, _NURSE_ADV[order, rank])
    where = f" through the {room}" if room else ""
    return (f"Think back to your rounds{where} earlier. "
            f"I need you at the {phrase} you {_pick(rng, _NURSE_VERB)} {adv}." + _pick(rng, _NURSE_CLOSE))


def _nurse_4(rng, phrase, order, rank, room):
    adj = _pick_before_one(rng, _NURSE_ADJ[order, rank])
    return (f"There was more than one {phrase}{_in_room(room)} on your rounds. "
            f"Go to the {adj} one, please." + _pick(rng, _NURSE_CLOSE))


def _nurse_5(rng, phrase, order, rank, room):
    adv = _pick(rng, _NURSE_ADV[order, rank])
    verb = _pick(rng, ["passed", "saw", "went past"])
    if room:
        return f"In the {room}, go to the {phrase} -- the one we {verb} {adv} on our rounds." + _pick(
            rng, _NURSE_CLOSE)
    return f"Go to the {phrase} -- the one we {verb} {adv} on our rounds." + _pick(rng, _NURSE_CLOSE)


def _nurse_6(rng, phrase, order, rank, room):
    adj = _pick(rng, _NURSE_ADJ[order, rank])
    opener = _pick(rng, ["I was keeping an eye on your rounds", "From what you told me of your rounds"])
    return (f"{opener}: you passed more than one {phrase}{_in_room(room)}. "
            f"Please go to the {adj} of them." + _pick(rng, _NURSE_CLOSE))


# ---------------------------------------------------------------------------------------------------------------
# Voice 2: building-site foreman
# ---------------------------------------------------------------------------------------------------------------

_FOREMAN_ADJ: dict[_Key, list[str]] = {
    ("first", 1): ["first", "very first"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["last", "very last", "latest"],
    ("last", 2): ["last-but-one", "second-from-last"],
    ("last", 3): ["last-but-two", "third-from-last"],
}
_FOREMAN_ADV: dict[_Key, list[str]] = {
    ("first", 1): ["first", "first of the lot"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["last", "most recently", "last of the lot"],
    ("last", 2): ["last but one", "second from last"],
    ("last", 3): ["last but two", "third from last"],
}
_FOREMAN_COUNT = {1: "first", 2: "second", 3: "third"}
_FOREMAN_VERB = ["clocked", "ran into", "came across", "saw"]
_FOREMAN_CLOSE = ["", " Cheers.", " Sharpish, please.", " Ta, mate.", " No messing about."]


def _foreman_1(rng, phrase, order, rank, room):
    adj = _pick(rng, _FOREMAN_ADJ[order, rank])
    lead = _pick(rng, ["Right, get yourself over to", "Right, off you go to", "Get yourself over to"])
    return f"{lead} the {adj} {phrase} you {_pick(rng, _FOREMAN_VERB)}{_in_room(room)}." + _pick(rng, _FOREMAN_CLOSE)


def _foreman_2(rng, phrase, order, rank, room):
    adv = _pick(rng, _FOREMAN_ADV[order, rank])
    verb = _pick(rng, _FOREMAN_VERB)
    lead = f"In the {room}, get" if room else "Get"
    return f"{lead} over to the {phrase} you {verb} {adv}." + _pick(rng, _FOREMAN_CLOSE)


def _foreman_3(rng, phrase, order, rank, room):
    start = "from the start" if order == "first" else "back from the end"
    where = f" of the {room}" if room else ""
    return (f"Counting {start} of your walk-round{where}, the {_FOREMAN_COUNT[rank]} {phrase} you "
            f"{_pick(rng, _FOREMAN_VERB)} is the one I want. {_pick(rng, ['Go to it.', 'Off you go.', 'Get to it.'])}")


def _foreman_4(rng, phrase, order, rank, room):
    adj = _pick_before_one(rng, _FOREMAN_ADJ[order, rank])
    return (f"You passed more than one {phrase}{_in_room(room)} on your walk-round. "
            f"I want you at the {adj} one." + _pick(rng, _FOREMAN_CLOSE))


def _foreman_5(rng, phrase, order, rank, room):
    adv = _pick(rng, _FOREMAN_ADV[order, rank])
    where = f" of the {room}" if room else ""
    return (f"On that walk-round{where} we did, mate -- go to the {phrase} we {_pick(rng, _FOREMAN_VERB)} "
            f"{adv}." + _pick(rng, _FOREMAN_CLOSE))


def _foreman_6(rng, phrase, order, rank, room):
    adj = _pick(rng, _FOREMAN_ADJ[order, rank])
    tail = _pick(rng, [" No rush.", " When you're ready.", ""])
    return f"I need you at the {adj} {phrase} you {_pick(rng, _FOREMAN_VERB)}{_in_room(room)}.{tail}"


# ---------------------------------------------------------------------------------------------------------------
# Voice 3: retired barrister
# ---------------------------------------------------------------------------------------------------------------

_BARRISTER_ADJ: dict[_Key, list[str]] = {
    ("first", 1): ["first", "earliest", "very first"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["most recent", "last", "final"],
    ("last", 2): ["penultimate", "second most recent", "last-but-one"],
    ("last", 3): ["antepenultimate", "third most recent", "third-from-last"],
}
_BARRISTER_ADV: dict[_Key, list[str]] = {
    ("first", 1): ["first", "earliest"],
    ("first", 2): ["second"],
    ("first", 3): ["third"],
    ("last", 1): ["most recently", "last"],
    ("last", 2): ["second most recently", "penultimately"],
    ("last", 3): ["third most recently"],
}
_BARRISTER_GLOSS: dict[_Key, str] = {
    ("first", 1): "the earliest of its kind that you encountered",
    ("first", 2): "the second of its kind, in order of sighting",
    ("first", 3): "the third of its kind, in order of sighting",
    ("last", 1): "the latest of its kind that you encountered",
    ("last", 2): "the one immediately preceding the most recent of its kind",
    ("last", 3): "the one two places before the most recent of its kind",
}
_BARRISTER_VERB = ["encountered", "observed", "came upon"]
_BARRISTER_CLOSE = ["", " Much obliged.", " With thanks.", " I am obliged to you."]


def _barrister_1(rng, phrase, order, rank, room):
    adj = _pick(rng, _BARRISTER_ADJ[order, rank])
    where = f" of the {room}" if room else ""
    return (f"I should be obliged if you would proceed to the {adj} {phrase} that you "
            f"{_pick(rng, _BARRISTER_VERB)} in the course of your survey{where}." + _pick(rng, _BARRISTER_CLOSE))


def _barrister_2(rng, phrase, order, rank, room):
    adv = _pick(rng, _BARRISTER_ADV[order, rank])
    who = _pick(rng, ["the robot", "you"])
    verb = _pick(rng, ["observed", "encountered"])
    lead = f"Within the {room}, kindly" if room else "Kindly"
    return f"{lead} make your way to the {phrase} which {who} {verb} {adv}." + _pick(rng, _BARRISTER_CLOSE)


def _barrister_3(rng, phrase, order, rank, room):
    adj = _pick(rng, _BARRISTER_ADJ[order, rank])
    return (f"For the avoidance of doubt, you encountered more than one {phrase}{_in_room(room)}; "
            f"I refer to the {adj} of them. Please proceed there." + _pick(rng, _BARRISTER_CLOSE))


def _barrister_4(rng, phrase, order, rank, room):
    adj = _pick(rng, _BARRISTER_ADJ[order, rank])
    return (f"Please go to the {adj} {phrase} you {_pick(rng, _BARRISTER_VERB)}{_in_room(room)} -- that is to "
            f"say, {_BARRISTER_GLOSS[order, rank]}." + _pick(rng, _BARRISTER_CLOSE))


def _barrister_5(rng, phrase, order, rank, room):
    start = "from the beginning" if order == "first" else "backwards from the end"
    count = {1: "first", 2: "second", 3: "third"}[rank]
    where = f" of the {room}" if room else ""
    return (f"Reckoning {start} of our survey{where}, the {count} {phrase} we came upon is the one to "
            f"which I should like you to proceed." + _pick(rng, _BARRISTER_CLOSE))


def _barrister_6(rng, phrase, order, rank, room):
    adj = _pick_before_one(rng, _BARRISTER_ADJ[order, rank])
    lead = _pick(rng, ["Would you be so good as to attend at", "Would you be good enough to go to"])
    return f"{lead} the {phrase}{_in_room(room)}? The {adj} one you came upon, to be precise." + _pick(
        rng, _BARRISTER_CLOSE)


_Shape = Callable[[np.random.Generator, str, str, int, str | None], str]

_VOICES: dict[str, tuple[_Shape, ...]] = {
    "nurse": (_nurse_1, _nurse_2, _nurse_3, _nurse_4, _nurse_5, _nurse_6),
    "foreman": (_foreman_1, _foreman_2, _foreman_3, _foreman_4, _foreman_5, _foreman_6),
    "barrister": (_barrister_1, _barrister_2, _barrister_3, _barrister_4, _barrister_5, _barrister_6),
}
_VOICE_NAMES: tuple[str, ...] = tuple(_VOICES)


def _voice_goal(rng: np.random.Generator, voice: str, phrase: str, order: str, rank: int, room: str | None) -> str:
    """One instruction in the named voice (a random shape of that voice)."""
    if order not in ("first", "last"):
        raise ValueError(f"order must be 'first' or 'last', got {order!r}")
    if rank not in (1, 2, 3):
        raise ValueError(f"rank must be 1, 2 or 3, got {rank!r}")
    shapes = _VOICES[voice]
    shape = shapes[int(rng.integers(len(shapes)))]
    return shape(rng, phrase, order, int(rank), room or None)


def time_goal_heldout2(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
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
    voice = _VOICE_NAMES[int(rng.integers(len(_VOICE_NAMES)))]
    return _voice_goal(rng, voice, phrase, order, rank, room)
