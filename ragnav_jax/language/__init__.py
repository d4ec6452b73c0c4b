"""ragnav_jax.language: instructions to task chains (rule parser, optional LLM parser) and episodes.

    from ragnav_jax.language import parse_instruction
    chain = parse_instruction("first the sofa, then the fridge")
"""

from ragnav_jax.exports import lazy_exports

__getattr__, __dir__, __all__ = lazy_exports(__name__, {
    "parse_instruction": "parser",
    "parse_with_fallback": "llm",
    "ParseError": "types",
    "TaskChain": "types",
    "Subgoal": "types",
    "Target": "types",
    "Episode": "episodes",
    "load_episodes": "episodes",
    "save_episodes": "episodes",
    "generate_episodes": "episodes",
    "parse_agreement": "agreement",
})
