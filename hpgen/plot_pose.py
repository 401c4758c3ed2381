"""The pose figure of a saved run: attitude and position read from the recorded g.

Which blocks of g are a rotation or a position follows from the group (the file's ``group``,
as the module's meta.json spells it: "SO3", "SE3", "[SO3, R3]", ...; files without it are
read by g's shape: 2 x 2 SO2, 3 x 3 SE2 when every last row is (0, 0, 1) else SO3, 4 x 4 SE3
when every last row is (0, 0, 0, 1)):
- a 3-D rotation R (SO3, the R of SE3): three panels, the columns R e_1, R e_2, R e_3 (the
  body axes in the space frame), continuous where a rotation vector would jump at pi;
- a 2-D rotation (SO2, the R of SE2): the angle atan2(R[1,0], R[0,0]) unwrapped, in rad;
- a position (SE2, SE3, R<n>): the translation column x of its block.
Product groups [G1, G2, ...] have g = blockdiag(g1, g2, ...); each factor gives its panels.
"""
from __future__ import annotations

import re

import numpy as np

#: matrix size of each group's block (R<n>: n + 1)
_SIZE = {"SO2": 2, "SO3": 3, "SE2": 3, "SE3": 4}
MAX_PANELS = 8


def factors(group: str) -> list:
    """[(name, first row, size)] of the blocks of g; [] for a name this module cannot read."""
    names = [s.strip() for s in group.strip().strip("[]").split(",") if s.strip()]
    out, row = [], 0
    for name in names:
        m = re.fullmatch(r"R(\d+)", name)
        size = _SIZE.get(name) or (int(m.group(1)) + 1 if m else None)
        if size is None:
            return []
        out.append((name, row, size))
        row += size
    return out


def guess_group(g) -> str:
    """The group of a file without ``group``, from g's shape and its last row."""
    n = g.shape[-1]
    affine = bool(np.all(np.asarray(g[:, -1, :], dtype=float) == np.eye(n)[-1]))
    return {2: "SO2", 3: "SE2" if affine else "SO3", 4: "SE3" if affine else ""}.get(n, "")


def panels(g, group: str) -> list:
    """[(label, (K, c) values, legend labels or None)] of the pose of g (K, n, n)."""
    out = []
    blocks = factors(group) if group else []
    for name, r, size in blocks:
        block = g[:, r:r + size, r:r + size]
        pre = f"{name}: " if len(blocks) > 1 else ""
        if name in ("SO3", "SE3"):
            for j in range(3):
                out.append((f"{pre}R e_{j + 1}\n(body axis {j + 1})", block[:, :3, j],
                            ["x", "y", "z"]))
        elif name in ("SO2", "SE2"):
            angle = np.unwrap(np.arctan2(block[:, 1, 0], block[:, 0, 0]))
            out.append((f"{pre}angle (rad)", angle[:, None], None))
        if name in ("SE2", "SE3") or name.startswith("R"):
            k = size - 1
            out.append((f"{pre}position x", block[:, :k, k], ["x", "y", "z"][:k]
                        if k <= 3 else [f"x{i}" for i in range(k)]))
    return out[:MAX_PANELS]


def pose_figure(plt, t, g, group: str, title: str):
    """The figure of the pose panels, or None when g has no block this module reads."""
    g = np.asarray(g, dtype=float)
    rows = panels(g, group or guess_group(g))
    if not rows:
        return None
    fig, axes = plt.subplots(len(rows), 1, figsize=(7.6, 1.2 + 1.8 * len(rows)),
                             sharex=True, squeeze=False)
    for ax, (label, v, legend) in zip(axes[:, 0], rows):
        for i in range(v.shape[1]):
            ax.plot(t, v[:, i], lw=0.9, label=legend[i] if legend else None)
        ax.set_ylabel(label, fontsize=8)
        ax.grid(True, alpha=0.3)
        if legend:
            ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.005, 1.0),
                      borderaxespad=0.0)
    axes[-1, 0].set_xlabel("t")
    axes[0, 0].set_title(f"{title}: attitude and position from g", fontsize=9)
    fig.tight_layout()
    return fig
