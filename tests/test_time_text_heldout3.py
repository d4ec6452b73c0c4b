"""Tests for ragnav_jax.language.time_text_heldout3 (held-out time-indexed instructions, set no. 3).

The readers below are hand-written, one per voice, and know only the wording of that module; they are NOT the
project's instruction parser (which the author of this set never read). Each reader blanks out the phrase and
the room, finds every time expression of its voice, requires that they all agree on one (order, rank), and
reads the room from "<preposition> the <room>".

Broken on purpose (both restored afterwards; all 8 tests pass on the module as left in the worktree):
1. In the new-parent vocabulary, the pre-noun word for ("last", 3) was changed to "second-to-last":
   test_each_voice_reader_recovers_all[new_parent] and test_public_function_readable failed (the reader
   recovered ("last", 2)); 6 others passed.
2. The voice choice in time_goal_heldout3 was drawn from numpy.random.default_rng() instead of ``rng``:
   test_same_seed_same_text and test_public_function_readable failed; 6 others passed.
"""

import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ragnav_jax.language.time_text_heldout3 import _KEYS, _VOICES, _compose, time_goal_heldout3

PHRASES = ["mug", "grey mug", "floor lamp", "tall oak bookcase", "armchair", "umbrella", "glass", "shelf",
           "potted fern", "old radio"]
ROOMS = ["kitchen", "living room", "laundry room", "bathroom", "bedroom", "hallway", "garage", "dining room",
         "study", "office"]

# Hand-written readers: expression -> (order, rank), per voice.
READERS = {
    "hill_farmer": {
        "straight after the first": ("first", 2), "straight after the second": ("first", 3),
        "just before the last": ("last", 2), "two before the last": ("last", 3),
        "last but one": ("last", 2), "last-but-one": ("last", 2), "last but two": ("last", 3),
        "last-but-two": ("last", 3), "second-to-last": ("last", 2), "third-to-last": ("last", 3),
        "first": ("first", 1), "second": ("first", 2), "third": ("first", 3),
        "last": ("last", 1), "latest": ("last", 1),
    },
    "consultant": {
        "second most recently": ("last", 2), "third most recently": ("last", 3),
        "second most recent": ("last", 2), "third most recent": ("last", 3),
        "second-to-last": ("last", 2), "third-to-last": ("last", 3),
        "antepenultimate": ("last", 3), "penultimate": ("last", 2),
        "most recently": ("last", 1), "most recent": ("last", 1), "latest": ("last", 1), "final": ("last", 1),
        "last": ("last", 1), "earliest": ("first", 1), "first": ("first", 1), "second": ("first", 2),
        "third": ("first", 3),
    },
    "new_parent": {
        "right after the first": ("first", 2), "right after the second": ("first", 3),
        "right before the last": ("last", 2), "second-to-last": ("last", 2), "next-to-last": ("last", 2),
        "third-to-last": ("last", 3), "third most recently": ("last", 3),
        "most recently": ("last", 1), "most recent": ("last", 1), "last": ("last", 1),
        "first": ("first", 1), "second": ("first", 2), "third": ("first", 3),
    },
}
ROOM_PREPS = {"hill_farmer": ["down in the", "over in the", "in the"], "consultant": ["within the", "in the"],
              "new_parent": ["in the"]}


def read(voice: str, text: str, phrase: str):
    """(order, rank, room) from text, knowing only the wording of ``voice``."""
    t = re.sub(r"\b" + re.escape(phrase) + r"\b", " <OBJ> ", text.lower())
    room = None
    preps = "|".join(re.escape(p) for p in ROOM_PREPS[voice])
    rooms = "|".join(re.escape(r) for r in sorted(ROOMS, key=len, reverse=True))
    found_rooms = re.findall(rf"\b(?:{preps}) ({rooms})\b", t)
    if found_rooms:
        assert len(set(found_rooms)) == 1, text
        room = found_rooms[0]
        t = t.replace(room, " <ROOM> ")
    exprs = sorted(READERS[voice], key=len, reverse=True)
    hits = re.findall(r"\b(" + "|".join(re.escape(e) for e in exprs) + r")\b", t)
    keys = {READERS[voice][h] for h in hits}
    assert len(keys) == 1, (text, hits)
    order, rank = keys.pop()
    return order, rank, room


def _drawn_voice(seed: int) -> str:
    """The voice time_goal_heldout3 draws first from a fresh rng of this seed (its first rng call)."""
    rng = np.random.default_rng(seed)
    return list(_VOICES)[int(rng.integers(len(_VOICES)))]


@pytest.mark.parametrize("voice", sorted(_VOICES))
def test_each_voice_reader_recovers_all(voice):
    shapes = set()
    for seed in range(40):
        for order, rank in _KEYS:
            rng = np.random.default_rng(seed)
            phrase = PHRASES[seed % len(PHRASES)]
            room = None if seed % 3 == 0 else ROOMS[seed % len(ROOMS)]
            text, shape = _compose(rng, voice, phrase, order, rank, room)
            shapes.add(shape)
            assert read(voice, text, phrase) == (order, rank, room), text
    assert len(shapes) >= 4, shapes


key_st = st.sampled_from(_KEYS)
room_st = st.one_of(st.none(), st.sampled_from(ROOMS))


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), phrase=st.sampled_from(PHRASES), key=key_st, room=room_st)
def test_verbatim_and_no_digits(seed, phrase, key, room):
    text = time_goal_heldout3(np.random.default_rng(seed), phrase, key[0], key[1], room)
    assert re.search(r"(?<![\w-])" + re.escape(phrase) + r"(?![\w-])", text), text
    assert not re.search(r"\d", text), text
    if room is None:
        assert not any(re.search(rf"\b{re.escape(r)}\b", text) for r in ROOMS), text
    else:
        assert re.search(rf"\b{re.escape(room)}\b", text), text


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), phrase=st.sampled_from(PHRASES), key=key_st, room=room_st)
def test_same_seed_same_text(seed, phrase, key, room):
    a = time_goal_heldout3(np.random.default_rng(seed), phrase, key[0], key[1], room)
    b = time_goal_heldout3(np.random.default_rng(seed), phrase, key[0], key[1], room)
    assert a == b


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), phrase=st.sampled_from(PHRASES), key=key_st, room=room_st)
def test_public_function_readable(seed, phrase, key, room):
    text = time_goal_heldout3(np.random.default_rng(seed), phrase, key[0], key[1], room)
    assert read(_drawn_voice(seed), text, phrase) == (key[0], key[1], room), text


def test_all_voices_drawn():
    assert {_drawn_voice(seed) for seed in range(60)} == set(_VOICES)


def test_bad_key_rejected():
    with pytest.raises(ValueError):
        time_goal_heldout3(np.random.default_rng(0), "mug", "middle", 1, None)
