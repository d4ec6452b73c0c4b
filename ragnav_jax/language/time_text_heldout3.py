"""Held-out set no. 3 of time-indexed navigation instructions ("go to the <object> you saw <when>").

Provenance
----------
Written by a helper session that the project started inside itself, with a brief to write a held-out set of
time-indexed instructions WITHOUT reading any instruction reader (parser) of the project or the wording of any
other sentence set. The helper worked in its own git worktree (/tmp/tq3) and read, of the repository, only the
``[tool.ruff]`` / ``[tool.ruff.lint]`` tables of pyproject.toml (line length 120, target py311, rule selection).
It opened no file under ragnav_jax/ or tests/ other than the two files it wrote (this module and
tests/test_time_text_heldout3.py), nor README.md nor experiments/. It checked that the folder
ragnav_jax/language exists (``test -d``) and that this file did not yet exist (``test -e``), without listing
anything. Slips: none known. The wording below is the helper's own, written from scratch.

Voices (one drawn per instruction with ``rng``)
-----------------------------------------------
``hill_farmer``      a laconic upland sheep farmer: short, blunt, dialect past tense ("you seen"),
                     British counting ("last but one", "last but two"), gruff thanks.
``consultant``       a corporate management consultant / executive: process jargon, "please proceed",
                     "penultimate"/"antepenultimate", "most recent", sometimes talks about "the robot" in the
                     third person as if delegating to a colleague.
``new_parent``       an exhausted parent of a newborn, whispering and apologetic: hesitant fillers, "we"/"I"
                     perspectives, "right after the first one", "second-to-last", pleas for quiet.

Each voice has five sentence shapes: time word before the noun, time adverb after the perception verb, a
separate clause that sets the scope then a pronoun ("... the second one"), an "of every <noun>" scope, and a
relative clause after a room/noun. Phrase and room are inserted verbatim; nothing is pluralised; no digits.

Sanity checks broken on purpose (see tests/test_time_text_heldout3.py): (1) the new-parent pre-noun word for
("last", 3) was changed to "second-to-last": the new-parent reader test and the public-function reader test
failed; restored. (2) the voice was drawn from a fresh ``numpy.random.default_rng()`` instead of ``rng``: the
same-seed test and the public-function reader test failed; restored. All 8 tests pass on the module as it stands.
"""

from __future__ import annotations

import numpy as np

__all__ = ["time_goal_heldout3"]

_KEYS = (("first", 1), ("first", 2), ("first", 3), ("last", 1), ("last", 2), ("last", 3))


def _pick(rng: np.random.Generator, options):
    return options[int(rng.integers(len(options)))]


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


# Per voice, per (order, rank):
#   pre  - words that go straight before the noun phrase: "the <pre> <phrase> you saw"
#   post - adverbials that go after the perception verb: "the <phrase> you saw <post>"
#   pro  - whole noun phrases that stand for "the one": "make for <pro>"
_VOCAB = {
    "hill_farmer": {
        ("first", 1): dict(pre=["first", "very first"], post=["first", "first off"],
                           pro=["the first one", "the very first one"]),
        ("first", 2): dict(pre=["second"], post=["second", "straight after the first one"],
                           pro=["the second one", "the one straight after the first"]),
        ("first", 3): dict(pre=["third"], post=["third", "straight after the second one"],
                           pro=["the third one"]),
        ("last", 1): dict(pre=["last", "very last", "latest"], post=["last", "last of all"],
                          pro=["the last one", "the latest one"]),
        ("last", 2): dict(pre=["last-but-one", "second-to-last"], post=["last but one", "just before the last one"],
                          pro=["the last but one", "the one just before the last"]),
        ("last", 3): dict(pre=["last-but-two", "third-to-last"], post=["last but two", "two before the last one"],
                          pro=["the last but two"]),
    },
    "consultant": {
        ("first", 1): dict(pre=["first", "earliest"], post=["first", "earliest"],
                           pro=["the first one", "the earliest one"]),
        ("first", 2): dict(pre=["second"], post=["second"], pro=["the second one"]),
        ("first", 3): dict(pre=["third"], post=["third"], pro=["the third one"]),
        ("last", 1): dict(pre=["most recent", "latest", "final"], post=["most recently", "last"],
                          pro=["the most recent one", "the latest one", "the final one"]),
        ("last", 2): dict(pre=["penultimate", "second most recent"], post=["second most recently", "second-to-last"],
                          pro=["the penultimate one", "the second most recent one"]),
        ("last", 3): dict(pre=["antepenultimate", "third most recent"], post=["third most recently", "third-to-last"],
                          pro=["the antepenultimate one", "the third most recent one"]),
    },
    "new_parent": {
        ("first", 1): dict(pre=["first", "very first"], post=["first", "first of all"],
                           pro=["the first one", "the very first one"]),
        ("first", 2): dict(pre=["second"], post=["second", "right after the first one"],
                           pro=["the second one", "the one right after the first"]),
        ("first", 3): dict(pre=["third"], post=["third", "right after the second one"],
                           pro=["the third one"]),
        ("last", 1): dict(pre=["last", "most recent"], post=["last", "most recently"],
                          pro=["the last one", "the most recent one"]),
        ("last", 2): dict(pre=["second-to-last", "next-to-last"], post=["second-to-last", "right before the last one"],
                          pro=["the second-to-last one", "the one right before the last"]),
        ("last", 3): dict(pre=["third-to-last"], post=["third-to-last", "third most recently"],
                          pro=["the third-to-last one"]),
    },
}

# Subject + perception verb, ready for "the <phrase> <sv> ...".
_SV = {
    "hill_farmer": ["you spotted", "you clapped eyes on", "you seen", "we went past", "you clocked",
                    "we saw"],
    "consultant": ["you logged", "you identified", "you encountered", "we observed", "you came across"],
    "new_parent": ["you saw", "you spotted", "we walked past", "we saw", "you found", "I watched you find"],
}
_ROBOT_VERBS = ["logged", "identified", "encountered", "observed"]  # consultant, "the robot ... it <verb>"

_ROOM_PREP = {
    "hill_farmer": ["in the", "down in the", "over in the"],
    "consultant": ["in the", "within the"],
    "new_parent": ["in the"],
}

_REASON = {
    "hill_farmer": ["", "", ", I've not got all day", ", the light's going"],
    "consultant": ["", "", ", as it's time-sensitive", ", so we can close this out"],
    "new_parent": ["", "", ", and keep it quiet", ", nice and quiet"],
}

_CLOSE = {
    "hill_farmer": ["", " Ta.", " Cheers.", " Go on, then."],
    "consultant": ["", " Thanks in advance.", " Much appreciated.", " Keep me posted."],
    "new_parent": ["", " Thank you so much.", " Tiptoe, okay?", " Bless you."],
}


def _room(rng: np.random.Generator, voice: str, room: str | None) -> str:
    return "" if room is None else f" {_pick(rng, _ROOM_PREP[voice])} {room}"


def _hill_farmer(rng, phrase, key, room):
    v, voc = "hill_farmer", _VOCAB["hill_farmer"][key]
    shape = _pick(rng, ["pre", "post_topic", "clause_pro", "every_pro", "relative"])
    sv, where = _pick(rng, _SV[v]), _room(rng, v, room)
    reason, close = _pick(rng, _REASON[v]), _pick(rng, _CLOSE[v])
    if shape == "pre":
        opener = _pick(rng, ["Right, get", "Go on, get", "Now then, get", "Get"])
        text = f"{opener} yourself over to the {_pick(rng, voc['pre'])} {phrase} {sv}{where}{reason}.{close}"
    elif shape == "post_topic":
        text = f"That {phrase} {sv} {_pick(rng, voc['post'])}{where}: go and stand by it{reason}.{close}"
    elif shape == "clause_pro":
        when = _pick(rng, [" on the rounds earlier", " earlier on", ""])
        text = f"{_cap(sv)} more than one {phrase}{where}{when}. Make for {_pick(rng, voc['pro'])}{reason}.{close}"
    elif shape == "every_pro":
        text = (f"Of every {phrase} {sv}{where}, it's {_pick(rng, voc['pro'])} I'm after. "
                f"Get yourself there{reason}.{close}")
    else:  # relative
        lead = _pick(rng, ["Off you go to", "Get over to", "Shift yourself to"])
        text = f"{lead} the {phrase}{where} that {sv} {_pick(rng, voc['post'])}{reason}.{close}"
    return text, shape


def _consultant(rng, phrase, key, room):
    v, voc = "consultant", _VOCAB["consultant"][key]
    shape = _pick(rng, ["pre", "post_step", "robot_pre", "chrono_pro", "relative"])
    sv, where = _pick(rng, _SV[v]), _room(rng, v, room)
    reason, close = _pick(rng, _REASON[v]), _pick(rng, _CLOSE[v])
    if shape == "pre":
        opener = _pick(rng, ["Quick ask: please", "Per this morning's walkthrough, please", "Please",
                             "Following up on the walkthrough, kindly"])
        text = f"{opener} proceed to the {_pick(rng, voc['pre'])} {phrase} {sv}{where}{reason}.{close}"
    elif shape == "post_step":
        lead = _pick(rng, ["Next step", "Priority for now", "Immediate ask"])
        text = f"{lead}: navigate to the {phrase} {sv} {_pick(rng, voc['post'])}{where}{reason}.{close}"
    elif shape == "robot_pre":
        verb = _pick(rng, _ROBOT_VERBS)
        text = f"Can we get the robot over to the {_pick(rng, voc['pre'])} {phrase} it {verb}{where}?{close}"
    elif shape == "chrono_pro":
        word = _pick(rng, ["target", "priority"])
        text = (f"Looking at every {phrase} {sv}{where} in chronological order, the {word} is "
                f"{_pick(rng, voc['pro'])}. Please go there{reason}.{close}")
    else:  # relative
        text = (f"Could you circle back to the {phrase}{where}, specifically the one {sv} "
                f"{_pick(rng, voc['post'])}?{close}")
    return text, shape


def _new_parent(rng, phrase, key, room):
    v, voc = "new_parent", _VOCAB["new_parent"][key]
    shape = _pick(rng, ["pre", "post_hesitant", "sleepless_pre", "every_pro", "not_just_any"])
    sv, where = _pick(rng, _SV[v]), _room(rng, v, room)
    reason, close = _pick(rng, _REASON[v]), _pick(rng, _CLOSE[v])
    if shape == "pre":
        opener = _pick(rng, ["Okay, quietly, can you", "Shh, sorry, could you", "Hey, can you", "Could you"])
        text = f"{opener} go to the {_pick(rng, voc['pre'])} {phrase} {sv}{where}{reason}?{close}"
    elif shape == "post_hesitant":
        text = f"Um, the {phrase}... the one {sv} {_pick(rng, voc['post'])}{where}. Go there, please{reason}.{close}"
    elif shape == "sleepless_pre":
        text = (f"Sorry, I'm running on no sleep, so: it's the {_pick(rng, voc['pre'])} {phrase} {sv}{where}. "
                f"Could you head over to it{reason}?{close}")
    elif shape == "every_pro":
        text = f"Of every {phrase} {sv}{where}, I need {_pick(rng, voc['pro'])}. Go to that one, please{reason}.{close}"
    else:  # not_just_any
        text = (f"Go to the {phrase}{where}, please{reason}. Not just any: the one {sv} "
                f"{_pick(rng, voc['post'])}.{close}")
    return text, shape


_VOICES = {"hill_farmer": _hill_farmer, "consultant": _consultant, "new_parent": _new_parent}


def _compose(rng: np.random.Generator, voice: str, phrase: str, order: str, rank: int,
             room: str | None) -> tuple[str, str]:
    """(text, shape name) for one instruction in the given voice. Used by the tests."""
    if (order, rank) not in _KEYS:
        raise ValueError(f"unsupported (order, rank): {(order, rank)!r}")
    return _VOICES[voice](rng, phrase, (order, rank), room)


def time_goal_heldout3(rng: np.random.Generator, phrase: str, order: str, rank: int, room: str | None) -> str:
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
    voice = _pick(rng, list(_VOICES))
    return _compose(rng, voice, phrase, order, rank, room)[0]
