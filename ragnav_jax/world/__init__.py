"""RAGNav scene world: schema, loading and validation, procedural generator, array padding."""
