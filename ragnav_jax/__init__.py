"""ragnav_jax: RAGNav (retrieval-augmented multi-goal navigation) in JAX and MuJoCo MJX."""

import os as _os

__version__ = "0.1.0"

# One config and seed, one result, on a GPU too: without XLA's deterministic GPU ops, MJX exploration differs
# between two runs on an H100 (the lidar and poses of a stream; experiments/results/gpu-determinism-h100/).
# Read when JAX starts its backend, so it takes effect when ragnav_jax is imported first; an XLA_FLAGS that
# names the flag already (=false to opt out) is left alone. The CPU backend ignores it.
if "xla_gpu_deterministic_ops" not in _os.environ.get("XLA_FLAGS", ""):
    _os.environ["XLA_FLAGS"] = (_os.environ.get("XLA_FLAGS", "") + " --xla_gpu_deterministic_ops=true").strip()
