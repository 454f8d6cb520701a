"""Matplotlib figures of workspaces (matplotlib is imported only when called).

Boundaries are drawn with true arcs: each arc becomes matplotlib's cubic
Bézier approximation of a circle (``Path.arc``, error ~1e-4 of the radius per
quarter turn, invisible at any plot size) rather than a polyline, and
holes are subpaths of the same patch, so they stay empty.
"""
from __future__ import annotations

import math
from typing import Any, List, Optional, Sequence, Tuple, Union

from . import Mechanism, Region

Point = Tuple[float, float]


def _loop_path(loop: Any) -> Tuple[List[Point], List[int]]:
    from matplotlib.path import Path

    verts: List[Point] = []
    codes: List[int] = []
    for curve in loop.curves:
        if not verts:
            verts.append(curve.source)
            codes.append(Path.MOVETO)
        if curve.kind == "segment":
            verts.append(curve.target)
            codes.append(Path.LINETO)
            continue
        cx, cy = curve.center
        r = curve.radius
        a0 = math.atan2(curve.source[1] - cy, curve.source[0] - cx)
        sweep = curve.sweep
        # Path.arc draws counter-clockwise from theta1 to theta2 (degrees).
        lo, hi = (a0, a0 + sweep) if sweep >= 0 else (a0 + sweep, a0)
        arc = Path.arc(math.degrees(lo), math.degrees(hi))
        pts = [(cx + r * x, cy + r * y) for x, y in arc.vertices]
        arc_codes = list(arc.codes)
        if sweep < 0:
            # Reverse a clockwise arc: curve segments keep their control points.
            pts = pts[::-1]
        verts.extend(pts[1:])
        codes.extend(arc_codes[1:])
    if verts:
        verts.append(verts[0])
        codes.append(Path.CLOSEPOLY)
    return verts, codes


def region_path(region: Region) -> Any:
    """The region's boundary as one matplotlib ``Path`` (outer loops and holes)."""
    from matplotlib.path import Path

    verts: List[Point] = []
    codes: List[int] = []
    for loop in region.loops():
        v, c = _loop_path(loop)
        verts.extend(v)
        codes.extend(c)
    if not verts:
        return Path([(0.0, 0.0)], [Path.MOVETO])
    return Path(verts, codes)


def workspace(region_or_mechanism: Union[Region, Mechanism], ax: Any = None, *,
              mechanism: Optional[Mechanism] = None, pose: Optional[Sequence[float]] = None,
              draw_mechanism: bool = True, facecolor: str = "#f4a6a6", edgecolor: str = "#c0392b",
              title: Optional[str] = None) -> Any:
    """Draw a workspace (a ``Region``, or a ``Mechanism``'s exact workspace).

    With a mechanism, it is also drawn at ``pose`` (x, y[, phi]; lengths in
    the file's unit, phi in radians; default: the centre of the largest
    inscribed circle) unless ``draw_mechanism`` is false. Returns the
    matplotlib ``Axes`` (a new figure when ``ax`` is None); axes are equal and
    labelled in the file's unit.
    """
    import matplotlib.pyplot as plt
    from matplotlib.patches import PathPatch

    if isinstance(region_or_mechanism, Mechanism):
        mechanism = region_or_mechanism
        region = mechanism.workspace()
    else:
        region = region_or_mechanism
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 5))
    if not region.empty:
        ax.add_patch(PathPatch(region_path(region), facecolor=facecolor, edgecolor=edgecolor, lw=1.2,
                               label=f"workspace, area {region.area:.6g} {region.units}²".rstrip()))
    if mechanism is not None and draw_mechanism and not region.empty:
        if pose is None:
            c = region.inscribed_circle()
            pose = c["center"] if c else None
        if pose is not None:
            _draw_mechanism(ax, mechanism, pose)
    ax.set_aspect("equal")
    ax.autoscale_view()
    if not region.empty:
        (x0, y0), (x1, y1) = region.bbox
        if mechanism is not None and draw_mechanism:
            (bx0, by0), (bx1, by1) = mechanism.bounds or region.bbox
            x0, y0, x1, y1 = min(x0, bx0), min(y0, by0), max(x1, bx1), max(y1, by1)
        pad = 0.05 * max(x1 - x0, y1 - y0)
        ax.set_xlim(x0 - pad, x1 + pad)
        ax.set_ylim(y0 - pad, y1 + pad)
    unit = region.units or (mechanism.units if mechanism else "")
    ax.set_xlabel(f"x ({unit})" if unit else "x")
    ax.set_ylabel(f"y ({unit})" if unit else "y")
    if title is None and mechanism is not None:
        title = mechanism.name
    if title:
        ax.set_title(title)
    ax.legend(loc="best", fontsize="small")
    return ax


def _draw_mechanism(ax: Any, mechanism: Mechanism, pose: Sequence[float]) -> None:
    phi = pose[2] if len(pose) > 2 else None
    d = mechanism.draw(pose[0], pose[1], phi)
    for a, b in d["guides"]:
        ax.plot([a[0], b[0]], [a[1], b[1]], ls="--", color="0.5", lw=0.8)
    for a, b in d["links"]:
        ax.plot([a[0], b[0]], [a[1], b[1]], color="#1f3a93", lw=2)
    if d["platform"]:
        xs, ys = zip(*d["platform"])
        ax.fill(xs, ys, color="#1f3a93", alpha=0.3)
    for key, marker in (("joints", "o"), ("sliders", "s"), ("base_points", "^")):
        if d[key]:
            xs, ys = zip(*d[key])
            ax.plot(xs, ys, marker, ls="", color="#1f3a93", mfc="white", ms=5)
    for curve in d["singular_curves"]:
        ax.plot(curve[:, 0], curve[:, 1], ls=":", color="k", lw=0.8)
    ax.plot([d["tool"][0]], [d["tool"][1]], "o", color="k", ms=4, label="mechanism at a pose")
