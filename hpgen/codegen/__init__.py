"""Code generation (stage 4): a DiscreteStep -> the files of a generated module.

Pure functions, no file I/O: ``emit(step, info)`` returns a GeneratedModule whose files the
caller writes to ``generated/<module>/``. Imports casadi and jinja2 (compile-time stack);
the generated module itself needs only numpy (and a C compiler for the C backend).
"""
from .contract import CodegenError
from .emit import (BACKENDS, META_FORMAT, GeneratedModule, emit, environment, header_lines,
                   meta, module_name, template_contexts, template_dir)

__all__ = ["emit", "module_name", "GeneratedModule", "CodegenError", "template_contexts",
           "template_dir", "environment", "header_lines", "meta", "BACKENDS", "META_FORMAT"]
