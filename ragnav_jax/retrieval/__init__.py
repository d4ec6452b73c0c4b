"""ragnav_jax.retrieval: scoring memory nodes against parsed subgoals, the baselines, and their evaluation.

    from ragnav_jax.retrieval import evaluate_retrieval, params_from_config
"""

from ragnav_jax.exports import lazy_exports

__getattr__, __dir__, __all__ = lazy_exports(__name__, {
    "METHODS": "evaluate",
    "evaluate_retrieval": "evaluate",
    "prepare_batch": "evaluate",
    "ABLATIONS": "params",
    "RetrievalParams": "params",
    "params_from_config": "params",
    "score_subgoal": "score",
})
