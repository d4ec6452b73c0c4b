"""Retrieval hyperparameters and ablation flags as array pytrees (sweeps vmap over them)."""

from __future__ import annotations

import jax.numpy as jnp
from flax import struct

from ragnav_jax.config import RetrievalConfig, hyperparameters


@struct.dataclass
class RetrievalParams:
    """Every field is a scalar array so a grid of them vmaps through one compiled function.

    Ablation flags are 0/1 floats of the same kernel (never separate code paths).
    """

    sigma: jnp.ndarray  # metres, width of the Gaussian in S_spatial (paper's sigma)
    eta: jnp.ndarray  # neighbour boosting coefficient (paper's eta)
    top_k: jnp.ndarray  # int32, candidates recalled for A in anchor-guided retrieval (paper's K)
    hops: jnp.ndarray  # int32, neighbourhood radius for anchor validation
    boost_hops: jnp.ndarray  # int32, neighbourhood radius for boosting
    beam: jnp.ndarray  # int32, semantic forest beam width per level
    anchor_threshold: jnp.ndarray  # a node matches the anchor phrase at or above this similarity
    boost_threshold: jnp.ndarray  # a neighbour is relevant at or above this score
    w_slot: jnp.ndarray  # weight of the per-object (instance) similarity vs the node fingerprint
    match_threshold: jnp.ndarray  # head-noun similarity above which an instance counts as the category
    sigma_loc: jnp.ndarray  # metres, width of the location-hint Gaussian
    sigma_rel: jnp.ndarray  # metres, width of the instance-level "A near B" Gaussian (anchor_proximity)
    w_loc: jnp.ndarray  # exponent of the location term (0 ignores hints)
    w_sensor: jnp.ndarray  # exponent of the sensor term (0 ignores sensor constraints)
    w_time: jnp.ndarray  # exponent of the time term of time-indexed queries (0 ignores "the one you saw first")
    w_recency: jnp.ndarray  # recency weight: instances seen longer ago score exp(-w_recency * age), age in [0, 1]
    w_room: jnp.ndarray  # 1: soft room constraint from the forest's summary labels; 0: off
    tau_room: jnp.ndarray  # softness of the room term (similarity units)
    forest_lock: jnp.ndarray  # 1: a room phrase prunes leaves outside the beam's region (paper); 0: soft room term only
    use_forest: jnp.ndarray  # 1: hierarchical pruning; 0: flat scoring of all nodes ("w/o semantic forest")
    use_topology: jnp.ndarray  # 1: anchor validation and boosting over G_t; 0: neither ("w/o topological map")
    use_spatial: jnp.ndarray  # 1: anchor-guided spatial term ("w/o spatial enhancement" at 0)
    use_boost: jnp.ndarray  # 1: neighbour boosting ("w/o neighbour enhancement" at 0)

    @staticmethod
    def create(**overrides) -> RetrievalParams:
        base = dict(DEFAULTS)
        unknown = set(overrides) - set(base)
        if unknown:
            raise KeyError(f"unknown retrieval parameter(s): {sorted(unknown)}")
        base.update(overrides)
        return RetrievalParams(
            **{k: jnp.asarray(v, jnp.int32 if k in INT_FIELDS else jnp.float32) for k, v in base.items()}
        )


# The hyperparameters (default, range, type) are written once, in the config section's table
# (config.RetrievalConfig); the ablation flags are on unless an ablation turns one off.
_TABLE = hyperparameters(RetrievalConfig)
INT_FIELDS = tuple(name for name, h in _TABLE.items() if h.type is int)
FLAGS = ("use_forest", "use_topology", "use_spatial", "use_boost")
DEFAULTS = {**{name: h.default for name, h in _TABLE.items()}, **dict.fromkeys(FLAGS, 1.0)}
# Static array-size limits of the compiled kernels (a param above its limit is clipped by the kernel).
MAX_K = 16
MAX_HOPS = 3
MAX_BEAM = 32

ABLATIONS = {
    "ragnav": {},
    "no_forest": {"use_forest": 0.0},
    "no_topology": {"use_topology": 0.0},
    "no_spatial": {"use_spatial": 0.0},
    "no_boost": {"use_boost": 0.0},
}


def params_from_config(cfg) -> RetrievalParams:
    """RetrievalParams from a config section with the same field names (e.g. cfg.retrieval)."""
    return RetrievalParams.create(**{f: getattr(cfg, f) for f in DEFAULTS if hasattr(cfg, f)})


def ablation_params(base: RetrievalParams, variant: str) -> RetrievalParams:
    if variant not in ABLATIONS:
        raise KeyError(f"unknown ablation '{variant}' (known: {', '.join(ABLATIONS)})")
    return base.replace(**{k: jnp.asarray(v, jnp.float32) for k, v in ABLATIONS[variant].items()})


def stack_params(ps: list[RetrievalParams]) -> RetrievalParams:
    """A leading grid axis over several parameter sets (stacked on the host: no compilation per field)."""
    from ragnav_jax.pytrees import stack

    return stack(ps)


