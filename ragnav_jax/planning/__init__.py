"""ragnav_jax.planning."""
