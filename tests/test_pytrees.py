"""Host-side pytree indexing and stacking: the same arrays as eager device indexing, and no compilation."""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from jax import monitoring

from ragnav_jax.pytrees import stack, take


@pytest.fixture
def compiles():
    n = []

    def on(event, dur, **kw):
        if "backend_compile" in event:
            n.append(event)

    monitoring.register_event_duration_secs_listener(on)
    yield n
    n.clear()


def tree(seed: int, shape=(3, 4)):
    k = jax.random.split(jax.random.PRNGKey(seed), 3)
    return {"f": jax.random.normal(k[0], shape), "i": jax.random.randint(k[1], shape[:1] + (5,), 0, 9),
            "b": jax.random.uniform(k[2], shape[:1]) > 0.5, "nested": (jnp.arange(shape[0], dtype=jnp.int32),)}


@pytest.mark.parametrize("index", [0, 2, (1, 3), slice(0, 2), np.array([2, 0, 2]), jnp.array([1, 1])])
def test_take_is_eager_indexing_bit_for_bit_and_compiles_nothing(index, compiles):
    t = tree(0)
    if isinstance(index, tuple):  # (row, column): the leaves with two axes
        t = {"f": t["f"], "i": t["i"]}
    want = jax.tree.map(lambda x: x[index], t)
    t = jax.tree.map(jax.block_until_ready, t)
    compiles.clear()
    got = take(t, index)
    assert not compiles
    for a, b in zip(jax.tree.leaves(got), jax.tree.leaves(want)):
        assert a.dtype == b.dtype and a.shape == b.shape and np.array_equal(np.asarray(a), np.asarray(b))


@pytest.mark.parametrize("n", [1, 3])
def test_stack_is_jnp_stack_bit_for_bit_and_compiles_nothing(n, compiles):
    ts = [jax.tree.map(jax.block_until_ready, tree(s)) for s in range(n)]
    want = jax.tree.map(lambda *xs: jnp.stack(xs), *ts)
    compiles.clear()
    got = stack(ts)
    assert not compiles
    assert jax.tree.structure(got) == jax.tree.structure(want)
    for a, b in zip(jax.tree.leaves(got), jax.tree.leaves(want)):
        assert a.dtype == b.dtype and np.array_equal(np.asarray(a), np.asarray(b))
