"""Host-side indexing and stacking of pytrees of arrays that compile nothing.

    idx0 = take(index, 3)            # every leaf x -> x[3]
    bank = stack([mem_a, mem_b])     # leaves stacked on a new leading axis

Indexing or stacking a device array eagerly (`x[b]`, `jnp.stack`) runs a small XLA program that is compiled
once per leaf shape and dtype: set-up code that walks a memory bank's or an index's dozens of leaves
compiled over a hundred of them (a 36-episode `ragnav eval` on 2 CPU cores: 141 compilations). These do the
same on the host with NumPy and put the result on the default device: the same arrays, bit for bit, with no
compilation. For set-up code only; inside traced code index as usual.
"""

from __future__ import annotations

from collections.abc import Sequence

import jax
import numpy as np


def take(tree, index):
    """Every leaf indexed by `index` (an int, a slice, a tuple or an integer/boolean array), on the host."""
    index = np.asarray(index) if isinstance(index, jax.Array) else index
    return jax.tree.map(lambda x: jax.device_put(np.asarray(np.asarray(x)[index])), tree)


def stack(trees: Sequence):
    """The trees' leaves stacked along a new leading axis, on the host."""
    return jax.tree.map(lambda *xs: jax.device_put(np.stack([np.asarray(x) for x in xs])), *trees)
