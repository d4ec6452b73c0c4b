"""ragnav_jax.evaluation: closed-loop navigation, hyperparameter sweeps, gradient tuning, the verifier's fit.

    from ragnav_jax.evaluation import evaluate_navigation, run_sweep
"""

from ragnav_jax.exports import lazy_exports

__getattr__, __dir__, __all__ = lazy_exports(__name__, {
    "NAV_METHODS": "methods",
    "evaluate_navigation": "navigate",
    "run_sweep": "sweep",
    "run_tune": "tune",
    "fit_verifier": "fitting",
})
