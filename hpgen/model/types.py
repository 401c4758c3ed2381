"""The IR produced by the model stage: a validated, immutable description of a model file."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

#: names the Lagrangian may use besides parameters (see hpgen.model.expr for products)
RESERVED_NAMES = ("xi", "g", "R", "x", "t", "dot", "sin", "cos", "tan", "exp", "log", "sqrt",
                  "cross", "transpose", "norm2", "sum")


@dataclass(frozen=True)
class IntegratorChoice:
    """Defaults from the model's ``integrator:`` section (CLI flags / API arguments override).

    tableau: a catalog name (str) or a hpgen.tableaus.ButcherTableau built from {A, b}.
    tau: 'exp' | 'cay' | 'skew'.  rkmk: 'exact' | 'truncated' (the paper's q = 0).
    """
    tableau: Any = "stormer-verlet"
    tau: str = "cay"
    rkmk: str = "exact"
    #: a composition of the step (hpgen.tableaus.composition), None: the plain step
    compose: str | None = None


@dataclass(frozen=True)
class SectionSpec:
    """The scene's Poincare section s(g, mu): the runtime records its upward zero crossings
    (s < 0 at one node, s >= 0 at the next).

    text: the expression as written. expr: sympy scalar in ``mu_symbols`` (mu_0 .. mu_{d-1},
    real; the node momentum) and ``g_symbols`` (g_i_j, real, an n x n tuple of tuples),
    parameters substituted as for the Lagrangian; never xi. The g symbols are equal (==, same
    hash) to Model.g_symbols (same names and assumptions). expr depends on mu or on an entry of
    g that varies on the group. Built by hpgen.model.expr.parse_section (whitelist parser).
    """
    text: str
    expr: Any                      # sympy.Expr
    mu_symbols: tuple
    g_symbols: tuple


@dataclass(frozen=True)
class RecordExpr:
    """A user expression recorded at each sample: ``label`` (its array name) and ``text``
    as written; ``expr`` a sympy scalar in ``xi_symbols`` (xi_0..xi_{d-1}, the same
    symbols as Model.xi_symbols), ``mu_symbols`` (mu_0..mu_{d-1}, real, as SectionSpec's)
    and ``g_symbols`` (equal to Model.g_symbols), parameters substituted as for the
    Lagrangian. Built by hpgen.model.expr.parse_record (whitelist parser)."""
    label: str
    text: str
    expr: Any                      # sympy.Expr
    xi_symbols: tuple
    mu_symbols: tuple
    g_symbols: tuple


@dataclass(frozen=True)
class Scene:
    """What ``hpgen run`` simulates. g0 is an n x n tuple-of-tuples matrix on the group;
    exactly one of xi0 / mu0 is set (tuples of length d); section: the optional Poincare
    section (SectionSpec) or None. record: the names to record in file order, built-in names
    (hpgen.model.scene.RECORDABLE) and the labels of the user expressions; expressions: those
    expressions (RecordExpr, file order), looked up by label. u: the scene's control inputs
    (hpgen.model.controls.ControlSpec: ``u.rows(h, steps, t0)``) or None."""
    h: float
    steps: int
    g0: tuple
    xi0: tuple | None = None
    mu0: tuple | None = None
    record: tuple[str, ...] = ("g", "mu")
    every: int = 1
    section: SectionSpec | None = None
    expressions: tuple = ()        # tuple of RecordExpr, in file order
    #: a section in t (``section: {every_t: T}``): the stroboscopic samples every T, or None
    section_every_t: float | None = None
    #: the control inputs u (hpgen.model.controls.ControlSpec) of a model with inputs, or None
    u: Any = None
    #: ``initial.project: true``: move the initial state onto the constraints (the loader does)
    project: bool = False
    #: how far that moved it (hpgen.model.projection.InitialProjection), None when not asked
    projection: Any = None


@dataclass(frozen=True)
class Model:
    """A validated model.

    lagrangian: sympy expression in the symbols ``xi_symbols`` (xi_0 .. xi_{d-1}) and
    ``g_symbols`` (g_i_j, an n x n tuple of tuples), parameters already substituted as exact
    binary floats. It was built by hpgen's own whitelist parser, never by eval/sympify. A
    family model whose Lagrangian is a sum of body-local terms (family.local) is loaded
    without it (``lagrangian_expr`` None): ``lagrangian_builder()`` builds it on first use.
    """
    name: str
    path: str                      # file name used in error messages ("<string>" if none)
    source: str                    # the model file's text, copied next to generated code
    group_spec: Any                # the ``group`` field as written (str or list of str)
    group: Any                     # hpgen.groups.LieGroup
    parameters: tuple              # ((name, value), ...), value float | tuple | tuple of tuples
    lagrangian_text: str
    lagrangian_expr: Any           # sympy.Expr, or None until ``lagrangian`` builds it
    xi_symbols: tuple
    g_symbols: tuple
    integrator: IntegratorChoice = field(default_factory=IntegratorChoice)
    scene: Scene | None = None
    # forced, controlled and time-dependent models; the defaults are a closed,
    # conservative model whose parameters are all frozen into the generated code.
    #: ((name, shape), ...) in file order: the parameters that are kernel inputs; shape () for
    #: a number, (k,) a vector, (r, c) a matrix. Their file values are the defaults.
    runtime_parameters: tuple = ()
    #: the flat symbols of the runtime parameters, names in order, entries row-major: the
    #: kernel input ``params`` in this order (runtime_symbol)
    runtime_symbols: tuple = ()
    #: the defaults of runtime_symbols (floats, same order)
    runtime_defaults: tuple = ()
    #: the control inputs' names and their symbols (input_symbol): the kernel input ``u``
    inputs: tuple = ()
    input_symbols: tuple = ()
    #: the generalized force f in g*, left-trivialized (body frame), one sympy scalar per
    #: algebra coordinate in the order of xi (SE3: torque first); () when the file has none.
    #: Free symbols: xi_symbols, g_symbols, TIME_SYMBOL, runtime_symbols, input_symbols.
    forces: tuple = ()
    forces_text: tuple = ()
    #: holonomic constraints phi(g) = 0 (hpgen.model.constraints): one ConstraintSpec per
    #: entry of the file's ``constraints:`` list, in file order; () for an unconstrained model
    constraints: tuple = ()
    #: the family of bodies of a model on G^N (hpgen.model.families.BodyFamily: body group,
    #: N, the Lagrangian's per-body sums), None otherwise; ``group`` is then its product
    family: Any = None
    #: () -> the Lagrangian (sympy.Expr) when lagrangian_expr is None
    lagrangian_builder: Any = field(default=None, compare=False, repr=False)

    @property
    def lagrangian(self) -> Any:
        """The expanded Lagrangian (sympy.Expr), built on first use for a family loaded
        body by body."""
        if self.lagrangian_expr is None:
            object.__setattr__(self, "lagrangian_expr", self.lagrangian_builder())
        return self.lagrangian_expr

    def _body_terms(self):
        """The family's body terms when the Lagrangian is not built (else None)."""
        local = getattr(self.family, "local", None)
        return None if self.lagrangian_expr is not None or local is None else local.bodies

    @property
    def forced(self) -> bool:
        """True when some force component is not identically zero."""
        return any(f.is_zero is not True for f in self.forces)

    @property
    def open_system(self) -> bool:
        """True when the step kernels need the inputs t, u and params: forces that are not
        identically zero, control inputs, runtime parameters or a time-dependent Lagrangian.
        A closed model (zero forces included) derives exactly the conservative step."""
        return bool(self.forced or self.inputs or self.runtime_parameters
                    or self.time_dependent)

    @property
    def time_dependent(self) -> bool:
        """True when the Lagrangian or a force depends on the time t."""
        from .symbols import TIME_SYMBOL
        terms = self._body_terms()
        lag = [t.expr for t in terms] if terms is not None else [self.lagrangian]
        return any(TIME_SYMBOL in e.free_symbols for e in (*lag, *self.forces))

    @property
    def left_invariant(self) -> bool:
        """True when l does not depend on g (the Euler-Poincare case)."""
        gs = {s for row in self.g_symbols for s in row}
        terms = self._body_terms()
        if terms is not None:        # a body term's g symbols are g_a_b of one body
            return not any(str(s).startswith("g_") for t in terms for s in t.expr.free_symbols)
        return not (self.lagrangian.free_symbols & gs)
