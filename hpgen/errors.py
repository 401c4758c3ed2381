"""The one exception tree of hpgen.

HpgenError
 +-- ModelError        bad model file, option or initial state (CLI exit status 2)
 +-- ArgumentError     bad argument of the Python API (shape, h, steps, ...; a ValueError)
 +-- BuildError        the C compiler is missing or failed (the Python backend is the fallback)
 +-- ConvergenceError  Newton did not converge, or a step produced non-finite values
      +-- DomainError  a start or a converged solution outside the chart map tau's domain
                       (reduce h; a Newton divergence is a plain ConvergenceError)

Every message is one line and says what to do.
"""
from __future__ import annotations


class HpgenError(Exception):
    """Base class of every error hpgen raises on purpose."""


class ModelError(HpgenError, ValueError):
    """Invalid input: names the file, the field (and YAML line where known) and what was expected.

    str(err) is ``"<file>:<line>: <field>: <message>"`` (parts that are unknown are left out).
    """

    def __init__(self, message: str, *, file: str | None = None, field: str | None = None,
                 line: int | None = None):
        self.file, self.field, self.line, self.message = file, field, line, message
        super().__init__(self._format())

    def _format(self) -> str:
        where = ""
        if self.file:
            where = f"{self.file}:{self.line}: " if self.line else f"{self.file}: "
        field = f"{self.field}: " if self.field else ""
        return (where + field + self.message).replace("\n", " ")

    def located(self, file: str | None = None, field: str | None = None,
                line: int | None = None) -> "ModelError":
        """A copy with missing location parts filled in."""
        return ModelError(self.message, file=self.file or file, field=self.field or field,
                          line=self.line or line)


class ArgumentError(HpgenError, ValueError):
    """A bad argument of the Python API (an array's shape or entries, h, steps, ...): one line,
    ``"<field>: <message>"``, field the argument's name. A ValueError, so ``except
    ValueError`` catches it; ModelError is for model files and compile options."""

    def __init__(self, message: str, *, field: str | None = None):
        self.field, self.message = field, message
        super().__init__(((f"{field}: " if field else "") + message).replace("\n", " "))


class BuildError(HpgenError):
    """The C compiler is missing or failed. Carries the command and its stderr."""

    def __init__(self, message: str, *, command: list[str] | None = None, stderr: str = ""):
        self.command, self.stderr = command, stderr
        first = stderr.strip().splitlines()[0] if stderr.strip() else ""
        text = message + (f" (command: {' '.join(command)})" if command else "")
        text += (f": {first}" if first else "") + "; use backend='python' as a fallback"
        super().__init__(text)


class ConvergenceError(HpgenError):
    """A step failed: Newton did not converge or produced non-finite values.

    Attributes: step (index of the failed step, 0-based), time (t_k at its start),
    residual (last residual norm), iterations, and partial (the Trajectory computed
    before the failure, flagged partial=True, or None).
    """

    def __init__(self, message: str, *, step: int, time: float, residual: float,
                 iterations: int, partial=None):
        self.step, self.time, self.residual, self.iterations = step, time, residual, iterations
        self.reason, self.partial = message, partial
        super().__init__(f"step {step} (t = {time:.6g}): {message}; residual norm {residual:.3e} "
                         f"after {iterations} Newton iterations; try a smaller h")


class DomainError(ConvergenceError):
    """The chart map tau was evaluated outside its domain (e.g. |h xi| >= 1 for skew)."""


class RecordError(ConvergenceError):
    """A recorded value (a ``record:`` expression, xi, energy, ...) is not finite at a state
    the run reached (the step itself converged), or the velocity xi behind it did not
    converge. ``step`` is the step whose end state gave the value; ``names`` the record
    entries that are not finite; ``partial`` the records up to and including that state."""

    def __init__(self, message: str, *, step: int, time: float, names=(), partial=None):
        self.step, self.time, self.residual, self.iterations = step, time, 0.0, 0
        self.reason, self.partial, self.names = message, partial, tuple(names)
        HpgenError.__init__(self, f"step {step} (t = {time:.6g}): {message}")
