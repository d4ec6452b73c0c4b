"""Tests for ragnav_jax/language/time_text_heldout.py (held-out time-indexed instructions, written blind).

The readers below are hand-written for this module's own wording only (one per voice); they are NOT the project's
instruction parser, which the author of this set never read.

Broken on purpose (each time the suite was run, seen to fail, and the module restored):
1. The chef voice's second-most-recent adjectives were replaced by plain "second" (so ("last", 2) read like
   ("first", 2)): test_each_voice_reader_recovers_every_combo[chef] and test_public_function_reads_back failed.
2. Every voice's "second" / "third" (adjectives and adverbs) were written as "2nd" / "3rd": test_text_properties
   (a digit appeared), test_each_voice_reader_recovers_every_combo[grandmother|teen|chef] and
   test_public_function_reads_back failed.
After restoring, the whole file passes.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ragnav_jax.language import time_text_heldout as tt
from ragnav_jax.language.time_text_heldout import time_goal_heldout

ROOMS = ["kitchen", "living room", "laundry room", "bathroom", "hall", "dining room", "bedroom", "guest bedroom"]
PHRASES = ["mug", "grey mug", "floor lamp", "tall oak bookcase", "armchair", "potted plant", "small blue vase", "sofa"]
COMBOS = [(o, r) for o in ("first", "last") for r in (1, 2, 3)]

# Each reader: (pattern, (order, rank)) tried in this order; the first that matches wins.
GRANDMOTHER_READER = [
    (r"\blast[- ]but[- ]two\b|\bthird[- ]to[- ]last\b|\bthird from last\b", ("last", 3)),
    (r"\blast[- ]but[- ]one\b|\bnext[- ]to[- ]last\b|\bsecond[- ]to[- ]last\b", ("last", 2)),
    (r"\blast\b|\bmost recent(ly)?\b|\blatest\b", ("last", 1)),
    (r"\bthird\b", ("first", 3)),
    (r"\bsecond\b", ("first", 2)),
    (r"\bfirst\b|\bearliest\b", ("first", 1)),
]
TEEN_READER = [
    (r"\bthird[- ]to[- ]last\b|\bthird-last\b|\bthird from last\b", ("last", 3)),
    (r"\bsecond[- ]to[- ]last\b|\bsecond-last\b|\bnext to last\b", ("last", 2)),
    (r"\blast\b|\bmost recent(ly)?\b|\blatest\b", ("last", 1)),
    (r"\bthird\b", ("first", 3)),
    (r"\bsecond\b", ("first", 2)),
    (r"\bfirst\b", ("first", 1)),
]
CHEF_READER = [
    (r"\bthird[- ]to[- ]last\b|\bthird-last\b|\bthird most recent\b|\btwo before last\b|\bthird from last\b",
     ("last", 3)),
    (r"\bsecond[- ]to[- ]last\b|\bsecond-last\b|\bsecond most recent\b|\bone before last\b|\bsecond from last\b",
     ("last", 2)),
    (r"\blast\b|\bmost recent(ly)?\b|\blatest\b", ("last", 1)),
    (r"\bthird\b", ("first", 3)),
    (r"\bsecond\b", ("first", 2)),
    (r"\bfirst\b|\bearliest\b", ("first", 1)),
]
READERS = {"grandmother": GRANDMOTHER_READER, "teen": TEEN_READER, "chef": CHEF_READER}


def read_back(voice: str, text: str, phrase: str) -> tuple[str, int, str | None]:
    """Recover (order, rank, room) from one of this module's texts, knowing its voice and the object phrase."""
    body = text.replace(phrase, " <obj> ")
    room = None
    for cand in sorted(ROOMS, key=len, reverse=True):
        if re.search(rf"\b[Ii]n the {re.escape(cand)}\b", body):
            room = cand
            body = re.sub(rf"\b[Ii]n the {re.escape(cand)}\b", " <room> ", body)
            break
    low = body.lower()
    for pattern, (order, rank) in READERS[voice]:
        if re.search(pattern, low):
            return order, rank, room
    raise AssertionError(f"reader found no time words in {text!r}")


def whole(needle: str, text: str) -> bool:
    return re.search(rf"(?<![\w-]){re.escape(needle)}(?![\w-])", text) is not None


def sentences(text: str) -> int:
    return len(re.findall(r"[.?!]+(?=\s|$)", text))


@settings(max_examples=60, deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    phrase=st.sampled_from(PHRASES),
    combo=st.sampled_from(COMBOS),
    room=st.none() | st.sampled_from(ROOMS),
)
def test_text_properties(seed, phrase, combo, room):
    order, rank = combo
    text = time_goal_heldout(np.random.default_rng(seed), phrase, order, rank, room)
    assert whole(phrase, text), text
    if room is not None:
        assert whole(room, text), text
        assert f"in the {room}" in text.lower(), text
    assert not re.search(r"\d", text), text
    assert sentences(text) <= 2, text
    assert text == time_goal_heldout(np.random.default_rng(seed), phrase, order, rank, room)


@pytest.mark.parametrize("voice", tt._VOICES)
def test_each_voice_reader_recovers_every_combo(voice):
    assert len(tt._SHAPES[voice]) >= 4
    rng = np.random.default_rng(7)
    for index in range(len(tt._SHAPES[voice])):
        for order, rank in COMBOS:
            for room in (None, "kitchen", "laundry room"):
                for phrase in ("mug", "tall oak bookcase"):
                    text = tt._in_shape(rng, voice, index, phrase, order, rank, room)
                    assert whole(phrase, text) and not re.search(r"\d", text), text
                    assert read_back(voice, text, phrase) == (order, rank, room), (voice, index, text)


def test_public_function_reads_back(monkeypatch):
    """Every voice is drawn and produces every (order, rank); its reader reads the public output back."""
    drawn: list[str] = []
    real = tt._in_voice

    def spy(rng, voice, *args):
        drawn.append(voice)
        return real(rng, voice, *args)

    monkeypatch.setattr(tt, "_in_voice", spy)
    seen: set[tuple[str, str, int]] = set()
    for seed in range(150):
        order, rank = COMBOS[seed % len(COMBOS)]
        room = ROOMS[seed % len(ROOMS)] if seed % 3 else None
        phrase = PHRASES[seed % len(PHRASES)]
        text = time_goal_heldout(np.random.default_rng(seed), phrase, order, rank, room)
        voice = drawn[-1]
        assert read_back(voice, text, phrase) == (order, rank, room), (voice, text)
        seen.add((voice, order, rank))
    assert seen == {(v, o, r) for v in tt._VOICES for o, r in COMBOS}


def test_bad_arguments_rejected():
    rng = np.random.default_rng(0)
    with pytest.raises(ValueError):
        time_goal_heldout(rng, "mug", "middle", 1, None)
    with pytest.raises(ValueError):
        time_goal_heldout(rng, "mug", "first", 4, None)
