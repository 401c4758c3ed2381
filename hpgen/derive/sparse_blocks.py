"""Sparse matrices of a family's chain rule (hpgen.derive.family_jacobian) built from blocks
with static index arrays, so that the generated code moves each nonzero a bounded number of
times and multiplies small dense blocks in straight-line SX code.

- ``Entries``: values (a dense MX column) placed at fixed (row, col) positions;
- ``assemble``: the sparse MX sum of Entries by static gathers; ``Sum``: the same sum kept
  as its terms' sources and an index, read in place by the products' gathers;
- ``block_products``: C = sum over entities e and slots s of X_{e,s} Y[rows_{e,s}, :] at
  rows out_e (negated or divided by a scalar inside the product), with each X_{e,s} a map's
  block output and the product one mapped SX function over the entities (Y's rows gathered
  per entity into a dense block, padded with zeros to the widest entity); its Entries point
  into the map's output.

All index arrays are computed once when the kernel is built; an entity's columns are those
where its rows of Y have a structural nonzero, and C's pattern is the structural product's
(as casadi.mtimes would give it).
"""
from __future__ import annotations

import casadi as ca
import numpy as np


class Entries:
    """Values placed at fixed positions of a sparse matrix: ``values`` an MX column (dense),
    entry q at (rows[q], cols[q]). Sums of Entries are assembled by static gathers
    (``assemble``); the chain rule's sparse matrices pass between the products as Entries,
    so that no sum or concatenation of differently patterned MX (CasADi's project and
    transpose of whole matrices) is generated."""

    def __init__(self, values, rows, cols, index=None, zero=None):
        """``index`` given: the values are values[index] (values an MX column), gathered
        only where the Entries are used alone; a sum reads them from values directly.
        ``zero``: a position of values that holds 0 (for the blocks' padding), or None."""
        self.base, self.rows, self.cols = values, np.asarray(rows), np.asarray(cols)
        self.zero = zero
        self.index = (np.arange(len(self.rows)) if index is None
                      else np.asarray(index, dtype=int))
        self._values = values if index is None else None

    @property
    def values(self):
        if self._values is None:
            self._values = self.base[self.index.tolist()]
        return self._values

    def shifted(self, row0: int = 0, col0: int = 0) -> Entries:
        """The same values at (rows + row0, cols + col0)."""
        out = Entries(self.base, self.rows + row0, self.cols + col0, self.index, self.zero)
        out._values = self._values
        return out

    def columns_from(self, c0: int) -> Entries:
        """The entries in the columns c0, c0 + 1, ... (the same positions and values)."""
        keep = self.cols >= c0
        if keep.all():
            return self
        return Entries(self.base, self.rows[keep], self.cols[keep], self.index[keep],
                       self.zero)

    @classmethod
    def of(cls, M, row0: int = 0, col0: int = 0, scale: float = 1.0):
        """The structural nonzeros of the sparse MX M, shifted by (row0, col0), times scale
        (1 or -1, or an MX scalar it is divided by when ``scale`` is an MX)."""
        sp = M.sparsity()
        v = ca.sparsity_cast(M, ca.Sparsity.dense(sp.nnz(), 1))
        if isinstance(scale, ca.MX):
            v = v / scale
        elif scale == -1.0:
            v = -v
        return cls(v, row0 + np.asarray(sp.row(), dtype=int),
                   col0 + np.asarray(sp.get_col(), dtype=int))

    @classmethod
    def blocks(cls, M, sp_blk, places):
        """The blocks B_t of M = [B_0, B_1, ...] (each of pattern sp_blk, a map's output) at
        the offsets places[t] = (row, col)."""
        e = sp_blk.nnz()
        br, bc = np.asarray(sp_blk.row(), dtype=int), np.asarray(sp_blk.get_col(), dtype=int)
        rows = np.concatenate([r + br for r, _ in places]) if places else br[:0]
        cols = np.concatenate([c + bc for _, c in places]) if places else bc[:0]
        assert M.nnz() == e * len(places)
        return cls(ca.sparsity_cast(M, ca.Sparsity.dense(M.nnz(), 1)), rows, cols)


def assemble(terms, shape):
    """Sparse MX of ``shape``: the sum of the Entries ``terms`` (entries at the same
    position add up, in the terms' order). Its pattern is the union of the terms' positions;
    its nonzeros (CCS order) are a gather of the first entry at each position from cat (the
    terms' values one after the other), to which the positions with a k-th entry add it
    (k = 2, 3, ...: a gather and an addition over those positions only)."""
    return Sum(terms, shape).mx()


class Sum:
    """The sum of Entries (as ``assemble``) kept as source vectors and an index: the terms'
    values are read from their own sources (the products' outputs: no gather per term), and
    the chain rule's intermediates, read only by Gathered blocks, are materialized only
    where a position repeats (the sums); the zero the blocks pad with is one more entry of
    the sources' concatenation instead of a copy of the whole matrix."""

    def __init__(self, terms, shape):
        terms = [t for t in terms if len(t.rows)]
        self.terms, self.shape = terms, shape
        self._src: dict = {}
        if not terms:
            self._sp = ca.Sparsity(*shape)
            return
        rows = np.concatenate([t.rows for t in terms])
        cols = np.concatenate([t.cols for t in terms])
        key = cols * shape[0] + rows
        order = np.lexsort((np.arange(len(key)), key))  # CCS, terms' order within a place
        ks = key[order]
        first = np.r_[True, ks[1:] != ks[:-1]]
        place = np.cumsum(first) - 1                  # position of each entry in the pattern
        rank = np.arange(len(ks)) - np.flatnonzero(first)[place]
        unique = ks[first]
        self._sp = ca.Sparsity.triplet(shape[0], shape[1], (unique % shape[0]).tolist(),
                                       (unique // shape[0]).tolist())
        self._plan = (order, place, rank)
        self.summed = bool(rank.max() > 0)
        # the distinct sources, and each entry's position in their concatenation
        bases: dict = {}
        for t in terms:
            bases.setdefault(id(t.base), t.base)
        self._bases = list(bases.values())
        offset = dict(zip(bases, np.cumsum([0] + [b.nnz() for b in self._bases])))
        self._at = np.concatenate([offset[id(t.base)] + t.index for t in terms])
        # a zero some source already holds (a product's), else one appended for the padding
        self._zero = next((int(offset[id(t.base)] + t.zero) for t in terms
                           if t.zero is not None), None)

    def columns_from(self, c0: int) -> Sum:
        """The sum's entries in the columns c0, c0 + 1, ... (the same shape)."""
        return Sum([t.columns_from(c0) for t in self.terms], self.shape)

    def sparsity(self):
        return self._sp

    def nnz(self) -> int:
        return int(self._sp.nnz())

    def source(self, zero: bool):
        """(v, index, z): nonzero q of the sum is v[index[q]], v an MX column; ``zero``: z a
        position of v that holds 0, for the blocks' padding (else None)."""
        if not self.terms:
            return ca.MX.zeros(1, 1), np.zeros(0, int), 0
        if zero not in self._src:
            order, place, rank = self._plan
            pad = [ca.MX.zeros(1, 1)] if zero and self._zero is None else []
            if len(self._bases) == 1 and not pad:
                cat = self._bases[0]
            else:
                cat = ca.vertcat(*self._bases, *pad)
            z = None if not zero else cat.nnz() - 1 if pad else self._zero
            at = self._at[order]
            if not self.summed:
                self._src[zero] = (cat, at, z)
            else:
                ext = [] if z is None else [z]             # the zero becomes the last entry
                out = cat[at[rank == 0].tolist() + ext]     # the first entry at each position
                for k in range(1, int(rank.max()) + 1):     # then those with a k-th entry
                    sel = rank == k
                    q = place[sel].tolist()
                    out.nz[q] = out.nz[q] + cat[at[sel].tolist()]
                self._src[zero] = (out, np.arange(self.nnz()), None if z is None
                                   else self.nnz())
        return self._src[zero]

    def mx(self):
        """The sum as a sparse MX of the pattern."""
        if not self.terms:
            return ca.MX(*self.shape)
        src, index, _ = self.source(False)
        if src.nnz() == len(index) and np.array_equal(index, np.arange(len(index))):
            return ca.sparsity_cast(src, self._sp)
        return ca.sparsity_cast(src[index.tolist()], self._sp)


class Gathered:
    """Y's rows per entity (Y a sparse MX or a Sum) as blocks, shared by the products that
    read the same rows: block e
    (kept rows x width, of the pattern ``sparsity`` common to all entities: the union of
    their nonzeros) holds Y[rows[e][s][k], cols[e][c]] at (k, c) for the slots' kept local
    rows k (those with a structural nonzero for some entity; the others are dropped), zeros
    where the entity has none."""

    def __init__(self, Y, yrows):
        spY = Y.sparsity()
        by_row: dict[int, list] = {}
        for q, (r, c) in enumerate(zip(spY.row(), spY.get_col())):
            by_row.setdefault(int(r), []).append((int(c), q))
        K = len(yrows[0]) if yrows else 0
        self.kept = [[k for k in range(len(yrows[0][s]))
                      if any(int(rs[s][k]) in by_row for rs in yrows)] for s in range(K)]
        self.cols = []
        for rs in yrows:
            self.cols.append(sorted({c for s in range(K) for k in self.kept[s]
                                     for c, _ in by_row.get(int(rs[s][k]), [])}))
        self.width = max([1] + [len(c) for c in self.cols])
        self.rows = sum(len(k) for k in self.kept)
        zero = Y.nnz()
        idx = np.full((len(yrows), self.width, self.rows), zero)
        for e, rs in enumerate(yrows):
            at = {c: k for k, c in enumerate(self.cols[e])}
            local = [int(rs[s][k]) for s in range(K) for k in self.kept[s]]
            for k, r in enumerate(local):
                for c, q in by_row.get(r, []):
                    idx[e, at[c], k] = q
        self.nonzero = idx != zero            # (entity, column, kept row)
        # the blocks' common pattern: the union of the entities' nonzeros, so that the
        # products skip the zeros every entity has
        union = self.nonzero.any(axis=0)
        cs, rs = np.nonzero(union)            # column-major (CCS) order
        self.sparsity = ca.Sparsity.triplet(self.rows, self.width, rs.tolist(), cs.tolist())
        take = idx[:, union].ravel()
        pad = bool((take == zero).any())      # an entity without a union entry: a zero
        if isinstance(Y, Sum):                # gathered from the sum's source directly
            # (a sum materialized once, with the zero, for all its readers)
            yv, at, z = Y.source(pad or Y.summed)
            take = np.where(take == zero, z if pad else 0, at[np.minimum(take, zero - 1)])
        else:
            yv = ca.sparsity_cast(Y, ca.Sparsity.dense(zero, 1))
            if pad:
                yv = ca.vertcat(yv, ca.MX.zeros(1, 1))
        self.blocks = ca.sparsity_cast(yv[take.tolist()],
                                       ca.horzcat(*[self.sparsity] * len(yrows)))


def _disjoint_slots(Y, yrows) -> bool:
    """Whether every entity's slots read Y rows whose columns do not overlap."""
    spY = Y.sparsity()
    cols_of: dict[int, set] = {}
    for r, c in zip(spY.row(), spY.get_col()):
        cols_of.setdefault(int(r), set()).add(int(c))
    for ys in yrows:
        seen: set = set()
        for rs in ys:
            cs = set().union(*[cols_of.get(r, set()) for r in rs])
            if cs & seen:
                return False
            seen |= cs
    return True


def block_products(xs, entities, Y, name: str, cache: dict | None = None,
                   scale=None) -> Entries:
    """Entries of sum_e sum_s X_{e,s} Y[yrows[e][s], :] at rows out[e] (Y a sparse MX),
    negated (scale -1) or divided by the MX scalar ``scale`` inside the mapped product (the
    same values as negating or dividing its result, without a pass over the entries).

    xs[s] = (M, sp): the blocks X_{0,s}, X_{1,s}, ... side by side in M (a map's output),
    each of pattern sp; entities[e] = (out (a rows of C), [yrows[e][s] (b_s rows of Y) per
    slot s]). When the slots' rows of Y have disjoint columns in every entity, each slot's
    block is gathered on its own (no padding to the other slots' columns); else one block
    over the union. ``cache``: Gathered blocks by (Y, rows), for products reading the same
    rows."""
    sp_x = [sp for _, sp in xs]
    a = sp_x[0].size1()
    if not entities or all(sp.nnz() == 0 for sp in sp_x) or Y.nnz() == 0:
        return Entries(ca.MX(0, 1), [], [])
    yrows = [[tuple(int(r) for r in rs) for rs in ys] for _, ys in entities]
    K = len(sp_x)
    groups = ([[s] for s in range(K)] if K > 1 and _disjoint_slots(Y, yrows)
              else [list(range(K))])
    cache = {} if cache is None else cache
    gys = []
    for grp in groups:
        rows_g = [[ys[s] for s in grp] for ys in yrows]
        key = (id(Y), tuple(tuple(ys) for ys in rows_g))
        if key not in cache:
            cache[key] = (Y, Gathered(Y, rows_g))  # Y kept alive: its id stays unique
        gys.append(cache[key][1])
    Xs = [ca.SX.sym(f"x{s}", sp) for s, sp in enumerate(sp_x)]
    Ybs = [ca.SX.sym(f"y{g}", gy.sparsity) for g, gy in enumerate(gys)]
    prods = []
    for grp, gy, Yb in zip(groups, gys, Ybs):
        offs = np.cumsum([0] + [len(k) for k in gy.kept])
        prod = ca.SX(a, gy.width)
        for q, s in enumerate(grp):
            if gy.kept[q]:
                prod = prod + ca.mtimes(Xs[s][:, gy.kept[q]],
                                        Yb[int(offs[q]):int(offs[q + 1]), :])
        prods.append(prod)
    prod = ca.horzcat(*prods)
    div = [ca.SX.sym("d")] if isinstance(scale, ca.MX) else []
    if div:
        prod = prod / div[0]
    elif scale is not None:
        assert scale == -1.0
        prod = -prod
    sp_o = prod.sparsity()
    # the nonzeros (CCS order) and a 0 after them: a zero the sums' padding can point to
    f = ca.Function(name, [*Xs, *Ybs, *div],
                    [ca.vertcat(ca.sparsity_cast(prod, ca.Sparsity.dense(sp_o.nnz(), 1)),
                                ca.SX.zeros(1, 1))], {"never_inline": True})
    stride = sp_o.nnz() + 1
    where = {(int(r), int(c)): q for q, (r, c) in enumerate(zip(sp_o.row(), sp_o.get_col()))}
    args = [*[M for M, _ in xs], *[gy.blocks for gy in gys]]
    fm = (f.map(f"{name}_map", "serial", len(entities), [len(args)], [])
          if div else f.map(len(entities)))
    out_nz = ca.sparsity_cast(fm(*args, *([scale] if div else [])),
                              ca.Sparsity.dense(stride * len(entities), 1))
    src, rows, cols = [], [], []
    col0 = 0
    for grp, gy in zip(groups, gys):
        xpat = np.hstack([(np.array(ca.DM(sp_x[s], 1.0)) != 0)[:, k]
                          for s, k in zip(grp, gy.kept)])
        for e, (out, _) in enumerate(entities):
            ecols = gy.cols[e]
            ypat = gy.nonzero[e, :len(ecols), :].T.astype(int)
            pat = (xpat.astype(int) @ ypat) > 0
            for c in range(len(ecols)):       # C's entries in column-major order per entity
                for r in np.flatnonzero(pat[:, c]):
                    src.append(e * stride + where[int(r), col0 + c])
                    rows.append(int(out[r]))
                    cols.append(ecols[c])
        col0 += gy.width
    if not src:
        return Entries(ca.MX(0, 1), [], [])
    return Entries(out_nz, rows, cols, src, stride - 1)
