"""The `unseen` held-out templates (set P): every piece of the ground truth is written down.

Checked with small readers of their own (words for relations, comparators, readings, units, coordinates, order
cues) that share no code with the templates, over random subgoals drawn by hypothesis. Determinism is checked here
and in tests/test_episodes_split.py.
"""

from __future__ import annotations

import re

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from template_checks import check_coordinates, check_goal, check_order, check_sensor
from test_phrasings_dev8 import _has, constraints, subgoals

from ragnav_jax.config import EPISODE_SPLITS
from ragnav_jax.language import phrasings_heldout as H
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
# P's words for each relation, written here apart from the templates' own table
P_REL_WORDS = {"near": ("near", "close by", "within reach of", "proximity to", "far off"), "next_to": ("next to",),
               "beside": ("beside",), "by": ("by",), "on": ("on", "atop"), "under": ("under", "beneath"),
               "above": ("above",), "in": ("in", "inside", "within", "housed in"),
               "with": ("with", "featuring", "that has", "that have"),
               "in_room_with": ("same room as", "also holds", "whichever room has", "room where you'll find"),
               "in_front_of": ("in front of",), "behind": ("behind",),
               "opposite": ("opposite", "across from", "facing", "over the way from"), "left_of": ("left of",),
               "right_of": ("right of",)}


def test_split_is_wired():
    assert EPISODE_SPLITS[-1] == "unseen" and UNSEEN_TEMPLATES["unseen"] == ("phrasings_heldout", "heldout")
    assert _renderer("unseen", "goal") is H.render_goal_heldout
    assert _renderer("unseen", "sensor") is H.render_sensor_heldout
    assert _renderer("unseen", "hint") is H.hint_text_heldout
    assert _renderer("unseen", "instruction") is H.render_instruction_heldout


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=5), seed=st.integers(0, 2**31), strict=st.booleans())
def test_same_seed_same_text(sgs, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        res = [H.render_goal_heldout(rng, sg, hint=H.hint_text_heldout(rng, "3.5", "2")) for sg in sgs]
        extra = H.render_sensor_heldout(rng, SensorConstraint("humidity_pct", "le", 40.0))
        return res, extra, H.render_instruction_heldout(rng, res, "strict" if strict else "free")

    assert run() == run()


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = H.render_goal_heldout(np.random.default_rng(seed), sg)
    check_goal(text, sg, P_REL_WORDS, "{}")
    assert not text.endswith((",", "—")), text
    # the room is written before any relation, so it cannot be read as an anchor's
    if sg.room and sg.target.relations:
        first_anchor = min(text.rfind(r.anchor.phrase) for r in sg.target.relations)
        assert text.find(sg.room) < first_anchor, text


def test_anchor_relations_stay_between_their_marks():
    t = Target("lamp", "lamp", (), (Relation("next_to", Target("credenza", "credenza", ("open",), (
        Relation("with", Target("record player", "record player")),))), Relation("under", Target("shelves", "shelves"))))
    rng = np.random.default_rng(0)
    for _ in range(60):
        text = H.render_goal_heldout(rng, Subgoal(0, t, room="music room"))
        assert "the open credenza" in text and re.search(r"credenza( — the one|, itself) ", text), text
        assert re.search(r"record player( —|,) ", text) and text.index("record player") < text.index("shelves"), text


def _comparator(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"or thereabouts|close on|neighbourhood of|circa|ballpark", "approx"),
                  (r"or over|or more|not below|no less than", "ge"),
                  (r"\btops\b|hasn't gone past|not over|capped at", "le"),
                  (r"gone past|beyond|past|above|warmer than|more humid than", "gt"),
                  (r"hasn't reached|yet to hit|less than|below|cooler than|drier than", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def _reading(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|vegetation|health|green|vigorous|poorly", t):
        return "ndvi"
    if re.search(r"humid|damp|dri|steam|clamm|%|percent|per cent", t):
        return "humidity_pct"
    if re.search(r"temp|warm|hot|cold|cool|°|degree|\bdeg\.|\d c\b", t):
        return "temperature_c"
    return "?"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = H.render_sensor_heldout(np.random.default_rng(seed), c)
    check_sensor(rendered, c, _comparator, r"cold|cool|least|poor|driest|lowest|bottom", r"°|degree|\bdeg\.|\d c\b",
                 r"%|percent|per cent")
    assert _reading((rendered[0] + " " + rendered[1]).strip()) == c.reading, rendered


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase(c, sg, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = H.render_sensor_heldout(rng, c)
    sg = Subgoal(0, Target(sg.target.phrase, sg.target.head, sg.target.attributes), room=sg.room)
    text = H.render_goal_heldout(rng, sg, prefix=prefix, tail=tail)
    assert _has(text, sg.target.head), text
    if prefix:  # a superlative adjective stands right before the noun phrase
        assert text.startswith(f"the {prefix} "), text
    else:
        core = tail.split(" ", 1)[1]
        assert core in text and text.index(sg.target.head) < text.index(core), text


def test_number_formats_vary():
    rng = np.random.default_rng(3)
    seen = set()
    for _ in range(400):
        _, tail, _ = H.render_sensor_heldout(rng, SensorConstraint("temperature_c", "lt", -18.0))
        seen.add("words" if "minus eighteen" in tail else "minus" if "minus 18" in tail else
                 "decimal" if "-18.0" in tail else "digits")
    assert seen == {"words", "minus", "decimal", "digits"}
    ndvi = {H.render_sensor_heldout(rng, SensorConstraint("ndvi", "gt", 0.6))[1] for _ in range(200)}
    assert any(re.search(r"(?<![\d])\.6\b", t) for t in ndvi) and any("0.60" in t for t in ndvi)


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(H.hint_text_heldout, H.render_goal_heldout, H.render_instruction_heldout, x, y, seed)


def test_signed_coordinates_never_use_compass_or_stage_words():
    rng = np.random.default_rng(5)
    for _ in range(200):
        hint = H.hint_text_heldout(rng, "-3.5", "2.0")
        assert not re.search(r"\beast\b|\bnorth\b|across|deep", hint), hint


STRICT_CUES = r"route is fixed|follow it exactly|keep to that route|keep to the timings|as numbered|" \
              r"do not reshuffle|script order|blocking is locked|exact sequence|sequentially|sequence critical|" \
              r"numerical order|same order every rep|number order|no skipping|stick to that order"
FREE_CUES = r"no set route|route's up to you|whichever sequence|whatever flows best|shoot order: flexible|" \
            r"any order works|improvise the path|non-critical|not critical|randomise|in any order|" \
            r"any order ya like|mix it up|don't care which|free-for-all"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_keep_their_order(sgs, seed, strict):
    check_order(H.render_goal_heldout, H.render_instruction_heldout, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    if strict:  # a strict text also says so in words of its own
        rng = np.random.default_rng(seed)
        res = [H.render_goal_heldout(rng, sg) for sg in sgs]
        assert re.search(STRICT_CUES, H.render_instruction_heldout(rng, res, "strict").lower())


def test_every_register_is_used():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [H.render_instruction_heldout(rng, res, order) for order in ("strict", "free") for _ in range(60)]
    marks = ("viewing|clients|route|features to show|highlights", "robot enters|shot list|robot wanders",
             "procedure|sop |sampling|method", "drill|righto|station")
    for m in marks:
        assert any(re.search(m, t.lower()) for t in texts), m
