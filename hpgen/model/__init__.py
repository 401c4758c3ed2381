"""The model stage (stage 1): read a model file, validate it, and produce a hpgen.model.Model.

Public API:
    load_model(path) -> Model
    load_model_text(text, filename="<string>") -> Model

Every problem raises hpgen.errors.ModelError with a one-line message
``file:line: field: what was expected``. The Lagrangian is parsed by a whitelist walker over
Python's ``ast`` (see hpgen.model.expr); nothing is ever evaluated as code.

Modules: yamldoc (YAML -> values with lines), loader (schema), syntax (ast parse + whitelist),
expr (ast -> sympy: Lagrangian and scene section), evaluator (the walker), families (groups
G^N and their sums), bodies (body-indexed names, vector functions), overrides (parameter
values set from the command line or the API), scene (scene / initial state), types (the
frozen IR dataclasses).
"""
from __future__ import annotations

from .loader import load_model, load_model_text
from .types import RESERVED_NAMES, IntegratorChoice, Model, Scene, SectionSpec

__all__ = ["load_model", "load_model_text", "Model", "Scene", "SectionSpec", "IntegratorChoice",
           "RESERVED_NAMES"]
