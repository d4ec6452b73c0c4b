"""Shared pieces of the template-set tests (tests/test_phrasings_dev*.py): targets as the generator builds
them, seeded generators and hypothesis strategies for goals. Each test file keeps its own, independent
readers of numbers, coordinates and order words: those are what the tests compare the templates against."""

import re

import numpy as np
from hypothesis import strategies as st

from ragnav_jax.language.types import RELATION_TYPES, Relation, SensorConstraint, Target

STATES = ("switched on", "switched off", "open", "closed", "empty", "full")


def word(w):
    """Regex for w as a whole word ('running' in 'hottest-running' is part of a prefix, not the state)."""
    return rf"(?<![\w-]){re.escape(w)}(?![\w-])"


def T(head, attrs=(), rels=()):
    """A target as the generator builds it: the phrase holds the modifiers, never the states."""
    return Target(" ".join(a for a in (*attrs, head) if a not in STATES), head, tuple(attrs),
                  tuple(Relation(t, a) for t, a in rels))


def gen(seed):
    return np.random.default_rng(seed)


def phrases(t):
    """Every word of a target that its text must carry: head, attributes, and the same for each anchor."""
    yield t.head
    yield from t.attributes
    for r in t.relations:
        yield from phrases(r.anchor)


def target_strategy(heads, mods):
    """Targets with up to three modifiers or states and up to two relations, anchors nested once."""
    leaf = st.builds(T, st.sampled_from(heads), st.lists(st.sampled_from(mods + STATES), max_size=2, unique=True))
    anchor = st.one_of(leaf, st.builds(T, st.sampled_from(heads), st.lists(st.sampled_from(mods), max_size=1),
                                       st.lists(st.tuples(st.sampled_from(RELATION_TYPES), leaf), min_size=1,
                                                max_size=1)))
    return st.builds(T, st.sampled_from(heads), st.lists(st.sampled_from(mods + STATES), max_size=3, unique=True),
                     st.lists(st.tuples(st.sampled_from(RELATION_TYPES), anchor), max_size=2))


SENSORS = st.one_of(
    st.none(),
    st.builds(SensorConstraint, st.sampled_from(("temperature_c", "ndvi", "humidity_pct")),
              st.sampled_from(("max", "min"))),
    st.builds(SensorConstraint, st.just("temperature_c"), st.sampled_from(("gt", "ge", "lt", "le", "approx")),
              st.integers(-30, 950).map(float)),
    st.builds(SensorConstraint, st.just("humidity_pct"), st.sampled_from(("gt", "ge", "lt", "le", "approx")),
              st.integers(0, 100).map(float)),
    st.builds(SensorConstraint, st.just("ndvi"), st.sampled_from(("gt", "ge", "lt", "le", "approx")),
              st.integers(-5, 20).map(lambda k: k * 0.05)),
)
