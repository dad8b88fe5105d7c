"""One typing module per grammar row: see ``elements.pyi``."""
