"""ragnav_jax: RAGNav (retrieval-augmented multi-goal navigation) in JAX and MuJoCo MJX."""

__version__ = "0.1.0"
