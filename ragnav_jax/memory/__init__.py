"""ragnav_jax.memory."""
