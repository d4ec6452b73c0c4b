"""The closed loop on the device: jittable pieces of the evaluation, batched over slots and episodes."""
