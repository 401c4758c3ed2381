"""Progress bars for long runs: tqdm when it is installed and wanted, else a no-op.

``progress``: True (show), False (never), None (the default: show only when stderr is a
terminal). The bar writes to stderr, so piped output and files never carry it; without tqdm
installed (the runtime needs numpy only) no bar is shown. Standard library at import.
"""
from __future__ import annotations

import sys


class _NoBar:
    """What ``bar`` returns when no bar is shown: the calls of a tqdm bar that hpgen uses
    (update, close, write a line to stderr, context manager)."""

    def update(self, n=1):
        pass

    def close(self):
        pass

    def write(self, text, file=None):
        print(text, file=file or sys.stderr, flush=True)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


def wanted(progress) -> bool:
    """Whether a bar is shown for ``progress`` (True / False / None = stderr is a terminal)."""
    if progress is None:
        try:
            return sys.stderr.isatty()
        except (AttributeError, ValueError):
            return False
    return bool(progress)


def bar(total, desc: str, unit: str, progress=None):
    """A tqdm bar on stderr over ``total`` ``unit``s (None: a counter), or a no-op with the
    same calls when not ``wanted`` or tqdm is not installed."""
    if not wanted(progress):
        return _NoBar()
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return _NoBar()
    return tqdm(total=total, desc=desc, unit=unit, file=sys.stderr, leave=False,
                dynamic_ncols=True, mininterval=0.5)
