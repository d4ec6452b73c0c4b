"""ragnav_jax.retrieval."""
