"""ragnav_jax.language."""
