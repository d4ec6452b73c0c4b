"""ragnav_jax.sim."""
