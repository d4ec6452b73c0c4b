"""RAGNav scene world: schema, loading and validation, procedural generator, array padding.

    from ragnav_jax.world import load_scene, stack_scenes
"""

from ragnav_jax.exports import lazy_exports

__getattr__, __dir__, __all__ = lazy_exports(__name__, {
    "Scene": "scene",
    "load_scene": "scene",
    "load_scene_set": "scene",
    "save_scene": "scene",
    "scene_files": "scene",
    "generate_scene": "generator",
    "generate_scenes": "generator",
    "stack_scenes": "arrays",
})
