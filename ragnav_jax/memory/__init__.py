"""ragnav_jax.memory: the dual-basis memory (key poses, captions, map, semantic forest) and its banks.

    from ragnav_jax.memory import load_bank
    bank = load_bank("runs/paper/memory/bank")
"""

from ragnav_jax.exports import lazy_exports

__getattr__, __dir__, __all__ = lazy_exports(__name__, {
    "build_bank": "build",
    "load_bank": "checkpoint",
    "save_bank": "checkpoint",
    "DualBasisMemory": "types",
    "MemoryBank": "types",
    "MemoryMeta": "types",
    "make_embedder": "encoder",
})
