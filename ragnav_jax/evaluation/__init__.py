"""ragnav_jax.evaluation."""
