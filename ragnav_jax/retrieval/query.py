"""Subgoals of a TaskChain as query arrays for the retrieval kernels.

Text is embedded on the host (once, cached by the embedder) between batched phases; the kernels then
see only fixed-shape arrays, so any number of subgoals, episodes and scenes batch together.
"""

from __future__ import annotations

from collections.abc import Sequence

import jax.numpy as jnp
import numpy as np
from flax import struct

from ragnav_jax.language.readings import READINGS
from ragnav_jax.language.types import Subgoal
from ragnav_jax.retrieval.kernels import (
    OP_APPROX,
    OP_GT,
    OP_LT,
    OP_MAX,
    OP_MIN,
    OP_NONE,
    TIME_FIRST,
    TIME_LAST,
    TIME_NONE,
)

TIME_ORDERS = {"first": TIME_FIRST, "last": TIME_LAST}
COMPARATOR_OPS = {"gt": OP_GT, "ge": OP_GT, "lt": OP_LT, "le": OP_LT, "approx": OP_APPROX, "max": OP_MAX, "min": OP_MIN}
# The natural softness of each reading: a sigmoid/Gaussian of width one unit of this.
SENSOR_SCALES = {k: r.tolerance for k, r in READINGS.items()}


@struct.dataclass
class QueryArrays:
    """One subgoal (or, with leading axes, many) ready for retrieval."""

    target: jnp.ndarray  # (D,) embedding of the target phrase (attributes + head noun)
    head: jnp.ndarray  # (D,) embedding of the head noun alone (category match for superlatives)
    anchor: jnp.ndarray  # (D,) embedding of the first relation's anchor phrase (zeros when none)
    has_anchor: jnp.ndarray  # () bool
    anchor_near: jnp.ndarray  # () bool: the relation is metric (near, next to, beside, by, on, with), not "in the room with"
    room: jnp.ndarray  # (D,) embedding of the room constraint (zeros when none)
    has_room: jnp.ndarray  # () bool
    hint: jnp.ndarray  # (2,) float32 location hint (x, y)
    has_hint: jnp.ndarray  # () bool
    sensor_channel: jnp.ndarray  # () int32 index into the memory's sensor names (0 when none)
    sensor_op: jnp.ndarray  # () int32 OP_* (OP_NONE when none)
    sensor_value: jnp.ndarray  # () float32 threshold / target (0 for superlatives)
    sensor_scale: jnp.ndarray  # () float32 softness in the reading's unit
    time_order: jnp.ndarray  # () int32 kernels.TIME_* ("the mug you saw first": TIME_FIRST; TIME_NONE when none)
    time_rank: jnp.ndarray  # () int32 1-based rank in that order (1 when none)


def query_texts(sg: Subgoal) -> tuple[str, str, str, str]:
    """(target, head, anchor, room) texts of a subgoal; '' where absent."""
    t = sg.target
    anchor = t.relations[0].anchor.phrase if t.relations else ""
    return t.phrase, t.head, anchor, (sg.room or "")


def encode_subgoals(subgoals: Sequence[Subgoal], embedder, sensor_names: Sequence[str]) -> QueryArrays:
    """Embeds and packs subgoals into a QueryArrays with a leading axis (Q, ...).

    A sensor constraint on a reading the memory does not hold is dropped (it cannot be checked), and
    only the first sensor constraint of a subgoal is used.
    """
    texts = [query_texts(sg) for sg in subgoals]
    flat = [x for tup in texts for x in tup if x]
    vecs = dict(zip(flat, embedder.embed(flat))) if flat else {}
    dim = embedder.dim
    zero = np.zeros(dim, np.float32)

    def emb(x):
        return vecs[x] if x else zero

    rows = []
    for sg, (tgt, head, anc, room) in zip(subgoals, texts):
        ch, op, val, scale = 0, OP_NONE, 0.0, 1.0
        for c in sg.sensors:
            if c.reading in sensor_names:
                ch, op = sensor_names.index(c.reading), COMPARATOR_OPS[c.comparator]
                val = float(c.value) if c.value is not None else 0.0
                scale = SENSOR_SCALES.get(c.reading, 1.0)
                break
        rows.append(
            dict(
                target=emb(tgt), head=emb(head), anchor=emb(anc), has_anchor=bool(anc),
                anchor_near=bool(anc) and sg.target.relations[0].type != "in_room_with", room=emb(room),
                has_room=bool(room),
                hint=np.array([sg.location.x, sg.location.y] if sg.location else [0.0, 0.0], np.float32),
                has_hint=sg.location is not None, sensor_channel=np.int32(ch), sensor_op=np.int32(op),
                sensor_value=np.float32(val), sensor_scale=np.float32(scale),
                time_order=np.int32(TIME_ORDERS[sg.time.order] if sg.time else TIME_NONE),
                time_rank=np.int32(sg.time.rank if sg.time else 1),
            )
        )
    if not rows:
        raise ValueError("encode_subgoals needs at least one subgoal")
    return QueryArrays(**{k: jnp.asarray(np.stack([np.asarray(r[k]) for r in rows])) for k in rows[0]})
