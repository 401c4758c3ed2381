"""Names that reach C: the model's and the parameters' names are C identifiers
``[A-Za-z][A-Za-z0-9_]*`` of at most MAX_NAME_LEN characters, not starting with '_', not C
keywords (C99/C11/C23) or ``main``."""
from __future__ import annotations

import re

from .yamldoc import Doc, describe

MAX_NAME_LEN = 64

C_KEYWORDS = frozenset("""
auto break case char const continue default do double else enum extern float for goto if inline
int long register restrict return short signed sizeof static struct switch typedef union unsigned
void volatile while _Alignas _Alignof _Atomic _Bool _Complex _Generic _Imaginary _Noreturn
_Static_assert _Thread_local alignas alignof bool constexpr false nullptr static_assert
thread_local true typeof typeof_unqual main""".split())

_IDENT = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


def check_identifier(doc: Doc, path, name, what: str) -> str:
    if not isinstance(name, str):
        raise doc.error(path, f"expected {what} (a C identifier), got {describe(name)}")
    if len(name) > MAX_NAME_LEN:
        raise doc.error(path, f"{what} {name[:20]!r}... is longer than {MAX_NAME_LEN} characters")
    if name.startswith("_"):
        raise doc.error(path, f"{what} {name!r} must not start with '_'")
    if not _IDENT.fullmatch(name):
        raise doc.error(path, f"{what} {name!r} is not an identifier: expected a letter followed "
                              "by letters, digits or '_' ([A-Za-z][A-Za-z0-9_]*)")
    if name in C_KEYWORDS:
        raise doc.error(path, f"{what} {name!r} is a C keyword (or 'main'); choose another name")
    return name
