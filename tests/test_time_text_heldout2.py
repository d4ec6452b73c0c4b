"""Tests of the held-out time-indexed set no. 2 (ragnav_jax/language/time_text_heldout2.py).

Written, with the module, by a helper session that read no instruction reader of the project and no other
sentence set. The readers below are hand-written for THIS set's wording only (one per voice); they are not the
project's parser and say nothing about it.

Broken on purpose (each break made on the module, the tests run, the module restored byte for byte (checked with
cmp), then re-run: 9 passed):
1. In the nurse's second shape the room clause was dropped (the lead became "Head" even when a room was given):
   1 failed, 8 passed -- test_every_voice_every_shape_every_rank[nurse] (room missing from the text). The
   hypothesis tests, at 40 random examples, did not happen to draw that shape with a room in that run; the
   exhaustive per-shape test is the one that guards every shape.
2. The barrister's third-most-recent ordinal "antepenultimate" was replaced by "penultimate" (a wording that says
   rank 2): 1 failed, 8 passed -- test_every_voice_every_shape_every_rank[barrister] (the barrister reader got
   ("last", 2) back for ("last", 3)).
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ragnav_jax.language.time_text_heldout2 import _VOICE_NAMES, _VOICES, _voice_goal, time_goal_heldout2

ROOMS = ["kitchen", "living room", "laundry room", "bathroom", "master bedroom", "bedroom", "hallway",
         "dining room", "garage", "home office"]
PHRASES = ["mug", "grey mug", "floor lamp", "tall oak bookcase", "armchair", "potted plant", "umbrella",
           "red office chair", "ironing board", "tv", "first aid kit", "alarm clock"]
COMBOS = [(o, r) for o in ("first", "last") for r in (1, 2, 3)]

_FAST = settings(max_examples=40, deadline=None, database=None)

seeds = st.integers(0, 2**32 - 1)
phrases = st.sampled_from(PHRASES)
orders = st.sampled_from(["first", "last"])
ranks = st.sampled_from([1, 2, 3])
rooms = st.one_of(st.none(), st.sampled_from(ROOMS))


def _whole(needle: str, text: str) -> bool:
    return re.search(r"(?<![\w-])" + re.escape(needle) + r"(?![\w-])", text) is not None


# --------------------------------------------------------------------------------------------------------------
# Readers: one per voice, each knowing only that voice's wording.
# --------------------------------------------------------------------------------------------------------------

_ORD = {"first": 1, "second": 2, "third": 3}


def _strip(text: str, phrase: str) -> tuple[str, str | None]:
    """Lower-case the text, cut the goal phrase out, and find the room among the known room names."""
    low = text.lower().replace(phrase, " <goal> ")
    for room in sorted(ROOMS, key=len, reverse=True):
        if _whole(room, low):
            return low.replace(room, " <room> "), room
    return low, None


def _scan(low: str, table: list[tuple[str, tuple[str, int]]]) -> tuple[str, int]:
    for pattern, key in table:
        if re.search(pattern, low):
            return key
    raise AssertionError(f"reader found no time cue in {low!r}")


def read_nurse(text: str, phrase: str) -> tuple[str, int, str | None]:
    low, room = _strip(text, phrase)
    order, rank = _scan(low, [
        (r"third-to-last|third most recent", ("last", 3)),
        (r"second-to-last|next-to-last|second most recent", ("last", 2)),
        (r"\blast\b|most recent|latest", ("last", 1)),
        (r"\bthird\b", ("first", 3)),
        (r"\bsecond\b", ("first", 2)),
        (r"\bfirst\b|earliest", ("first", 1)),
    ])
    return order, rank, room


def read_foreman(text: str, phrase: str) -> tuple[str, int, str | None]:
    low, room = _strip(text, phrase)
    counting = re.search(r"counting (from the start|back from the end).*?the (first|second|third)\s+<goal>", low)
    if counting:
        return ("first" if counting.group(1) == "from the start" else "last"), _ORD[counting.group(2)], room
    order, rank = _scan(low, [
        (r"last[- ]but[- ]two|third[- ]from[- ]last", ("last", 3)),
        (r"last[- ]but[- ]one|second[- ]from[- ]last", ("last", 2)),
        (r"\blast\b|most recently|latest", ("last", 1)),
        (r"\bthird\b", ("first", 3)),
        (r"\bsecond\b", ("first", 2)),
        (r"\bfirst\b", ("first", 1)),
    ])
    return order, rank, room


def read_barrister(text: str, phrase: str) -> tuple[str, int, str | None]:
    low, room = _strip(text, phrase)
    reckoning = re.search(r"reckoning (from the beginning|backwards from the end).*?the (first|second|third)\s+<goal>",
                          low)
    if reckoning:
        return ("first" if reckoning.group(1) == "from the beginning" else "last"), _ORD[reckoning.group(2)], room
    order, rank = _scan(low, [
        (r"antepenultimate|third most recent|third-from-last|two places before", ("last", 3)),
        (r"\bpenultimate(ly)?\b|second most recent|last-but-one|immediately preceding", ("last", 2)),
        (r"most recent|\blast\b|\bfinal\b|latest", ("last", 1)),
        (r"\bthird\b", ("first", 3)),
        (r"\bsecond\b", ("first", 2)),
        (r"\bfirst\b|earliest", ("first", 1)),
    ])
    return order, rank, room


READERS = {"nurse": read_nurse, "foreman": read_foreman, "barrister": read_barrister}


# --------------------------------------------------------------------------------------------------------------


def test_three_voices_each_with_at_least_four_shapes():
    assert set(_VOICE_NAMES) == set(READERS) and len(_VOICE_NAMES) == 3
    for voice, shapes in _VOICES.items():
        assert len(shapes) >= 4, voice


@_FAST
@given(seeds, phrases, orders, ranks, rooms)
def test_phrase_and_room_verbatim_no_digits(seed, phrase, order, rank, room):
    text = time_goal_heldout2(np.random.default_rng(seed), phrase, order, rank, room)
    assert _whole(phrase, text), text
    if room is not None:
        assert _whole(room, text), text
    assert not re.search(r"\d", text), text


@_FAST
@given(seeds, phrases, orders, ranks, rooms)
def test_same_seed_same_text(seed, phrase, order, rank, room):
    a = time_goal_heldout2(np.random.default_rng(seed), phrase, order, rank, room)
    b = time_goal_heldout2(np.random.default_rng(seed), phrase, order, rank, room)
    assert a == b


def test_public_function_draws_every_voice():
    seen = set()
    for seed in range(60):
        rng = np.random.default_rng(seed)
        voice = _VOICE_NAMES[int(rng.integers(len(_VOICE_NAMES)))]
        expected = _voice_goal(rng, voice, "floor lamp", "last", 2, "living room")
        assert time_goal_heldout2(np.random.default_rng(seed), "floor lamp", "last", 2, "living room") == expected
        seen.add(voice)
    assert seen == set(_VOICE_NAMES)


@pytest.mark.parametrize("voice", list(READERS))
def test_every_voice_every_shape_every_rank(voice):
    """Every (order, rank) is produced by every shape of every voice, and the voice's reader gets it back."""
    reader = READERS[voice]
    rng = np.random.default_rng(7)
    for shape in _VOICES[voice]:
        for order, rank in COMBOS:
            for phrase, room in [("grey mug", None), ("tall oak bookcase", "laundry room"), ("mug", "kitchen")]:
                for _ in range(4):
                    text = shape(rng, phrase, order, rank, room)
                    assert _whole(phrase, text) and not re.search(r"\d", text), text
                    assert room is None or _whole(room, text), text
                    assert reader(text, phrase) == (order, rank, room), (shape.__name__, text)


@_FAST
@given(seeds, st.sampled_from(_VOICE_NAMES), phrases, orders, ranks, rooms)
def test_voice_reader_recovers_order_rank_room(seed, voice, phrase, order, rank, room):
    text = _voice_goal(np.random.default_rng(seed), voice, phrase, order, rank, room)
    assert READERS[voice](text, phrase) == (order, rank, room), text


def test_bad_arguments_are_refused():
    with pytest.raises(ValueError):
        time_goal_heldout2(np.random.default_rng(0), "mug", "middle", 1, None)
    with pytest.raises(ValueError):
        time_goal_heldout2(np.random.default_rng(0), "mug", "first", 4, None)
