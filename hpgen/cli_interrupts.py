"""How ``hpgen run`` reports a failed or interrupted run (used by hpgen.cli): the failed
step's line with where the samples before it were saved (``failed``), SIGTERM raised like
SIGINT while a run writes its chunks (``sigterm_raises``), and the interruption's line with
what was saved and how to resume (``interrupted``, exit status 128 + signal). Standard
library only.
"""
from __future__ import annotations

import shlex
import signal
import sys
from pathlib import Path


def failed(e, what: str) -> int:
    """A failed step: its one line, with where the samples before it were saved."""
    saved = getattr(e, "saved", None)
    note = (f"; the {saved[1]} {what} before the failure were saved to {saved[0]} with "
            "partial=True" if saved and saved[1] else "")
    print(f"hpgen: error: {e}{note}", file=sys.stderr)
    return 1


class _Terminated(KeyboardInterrupt):
    """SIGTERM (what ``timeout`` and job schedulers send), raised like SIGINT's
    KeyboardInterrupt so that ``hpgen run`` saves its completed chunks."""
    signum = signal.SIGTERM


class sigterm_raises:
    """Within: the first SIGTERM raises _Terminated, later ones are ignored (the save in
    progress completes); the previous handler is restored on exit. Main thread only."""

    def __enter__(self):
        import threading
        self.old = None
        if threading.current_thread() is threading.main_thread():
            self.old = signal.signal(signal.SIGTERM, self._raise)
        return self

    def __exit__(self, *exc):
        if self.old is not None:
            signal.signal(signal.SIGTERM, self.old)
        return False

    @staticmethod
    def _raise(signum, frame):
        signal.signal(signal.SIGTERM, signal.SIG_IGN)
        raise _Terminated()


def resume_command(args) -> str:
    argv = list(getattr(args, "argv", None) or [])
    return shlex.join(["hpgen", *argv, *([] if "--resume" in argv else ["--resume"])])


def interrupted(e) -> int:
    """One line for an interrupted command: what was saved and how to resume; 128 + signal."""
    signum = getattr(e, "signum", signal.SIGINT)
    line = f"hpgen: interrupted by {signal.Signals(signum).name}"
    saved = getattr(e, "saved", None)
    if saved is not None:
        path, samples, k, parts = saved
        if path is None:
            line += "; no chunk had completed, nothing was saved"
        else:
            line += (f" after {k} steps; the {samples} samples of the completed chunks were "
                     f"saved to {path} with partial=True, and kept in {parts}/ for "
                     f"--resume: {_resume_hint(parts)}")
    print(line, file=sys.stderr)
    return 128 + signum


def _resume_hint(parts) -> str:
    import json
    try:
        return json.loads((Path(parts) / "manifest.json").read_text())["resume"]
    except (OSError, ValueError, KeyError):
        return "run the same command with --resume"
