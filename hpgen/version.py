"""hpgen's version: the one place it is written (pyproject.toml reads it from here). A module
of its own so that stages (codegen, the cache keys) can import it without the package root."""

__version__ = "0.1.0"
