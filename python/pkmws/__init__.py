"""pkmws: exact workspaces of planar parallel mechanisms, from Python.

Units, everywhere in this module:

* lengths (poses, coordinates, prismatic joints, areas in length²) are in the
  mechanism file's unit (``Mechanism.units``: ``"mm"`` or ``"m"``);
* every angle is in **radians**: the orientation ``phi``, angle joints,
  pressure angles, arc sweeps. Only the file's own fields (``document``,
  ``parameters``, e.g. ``legs[0].guide_angle_deg``) keep the file's degrees.

Every input error (missing file, unknown field, bad value, wrong array shape)
raises ``ValueError`` with the command line's one-line message.

    >>> import pkmws
    >>> m = pkmws.load("datasets/moma_m1_g0_l250.json")
    >>> round(m.workspace().area, 4)
    36202.1833
"""
from __future__ import annotations

import json as _json
import os as _os
import tempfile as _tempfile
from typing import Any, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple, Union

from . import _pkmws
from ._pkmws import Component, Curve, Loop, Mechanism, Region

__all__ = ["load", "sweep", "optimize", "metric_names", "Mechanism", "Region", "Component", "Loop", "Curve", "Parameters"]
__version__ = "0.1.0"


def load(source: Union[str, "_os.PathLike[str]", Mapping[str, Any]]) -> Mechanism:
    """Load a mechanism file (a path) or a mechanism document (a dict).

    The document is validated by the library's loader, exactly as
    ``pkmws info FILE``: a bad file raises ``ValueError`` with the loader's
    one-line message naming the file (``"<dict>"`` for a dict) and the field,
    e.g. ``m.json: legs[0].rod_length: must be positive (got -250.0)``.
    """
    if isinstance(source, Mapping):
        try:
            text = _json.dumps(source, allow_nan=False)
        except (TypeError, ValueError) as e:
            raise ValueError(f"<dict>: not a JSON document ({e})") from None
        return _pkmws._load_document(text, "<dict>")
    if isinstance(source, (str, bytes, _os.PathLike)):
        path = _os.fsdecode(_os.fspath(source))
        return _pkmws._load_path(path)
    raise ValueError(f"load: expected a file path or a dict, got {type(source).__name__}")


class Parameters:
    """The numbers of a mechanism's file by field path (``"legs[1].rod_length"``).

    Reading gives the file's value (``int``, ``float`` or ``None`` for a
    null). Assigning **updates the mechanism in place**: the file's document
    with the new value is validated again by the loader; on error a
    ``ValueError`` with the loader's one-line message is raised and the
    mechanism is unchanged. ``Mechanism.with_parameters`` gives a new
    mechanism instead. Values are in the file's units (lengths in its unit,
    ``*_deg`` fields in degrees).
    """

    def __init__(self, mechanism: Mechanism) -> None:
        self._m = mechanism

    def __getitem__(self, path: str) -> Optional[Union[int, float]]:
        return self._m._get(path)

    def __setitem__(self, path: str, value: Union[int, float]) -> None:
        self._m._assign(self._m._with({path: value}))

    def update(self, values: Mapping[str, Union[int, float]]) -> None:
        """Set several values at once (one validation: they may depend on each other)."""
        self._m._assign(self._m._with(dict(values)))

    def keys(self) -> List[str]:
        """Every numeric field path of the document (``source`` left out), keys in sorted order."""
        return [p[0] for p in self._m._parameters()]

    def units(self) -> Dict[str, str]:
        """The unit of every numeric field: the file's length unit, ``deg``, ``N``, ``N m``, ``mm/s`` or ``1``."""
        return {p[0]: p[3] for p in self._m._parameters()}

    def info(self) -> List[Dict[str, Any]]:
        """Every numeric field as ``{"path", "value", "type", "unit"}`` (type ``number`` or ``integer``)."""
        return [dict(zip(("path", "value", "type", "unit"), p)) for p in self._m._parameters()]

    def __iter__(self) -> Iterator[str]:
        return iter(self.keys())

    def __len__(self) -> int:
        return len(self.keys())

    def __contains__(self, path: object) -> bool:
        return path in self.keys()

    def items(self) -> List[Tuple[str, Union[int, float]]]:
        return [(k, self[k]) for k in self.keys()]  # type: ignore[misc]

    def as_dict(self) -> Dict[str, Union[int, float]]:
        return dict(self.items())

    def __repr__(self) -> str:
        return f"Parameters({self.as_dict()!r})"


def _parameters(self: Mechanism) -> Parameters:
    return Parameters(self)


def _with_parameters(self: Mechanism, values: Optional[Mapping[str, Union[int, float]]] = None,
                     **kwargs: Union[int, float]) -> Mechanism:
    """A new, validated mechanism with the values set (``self`` is unchanged)."""
    merged = dict(values or {})
    merged.update(kwargs)
    return self._with(merged)


def _mechanism_repr(self: Mechanism) -> str:
    return f"<pkmws.Mechanism {self.kind} {self.name!r} ({self.units}, {self.dof} DOF)>"


def _largest(items: List[Dict[str, Any]], key: str) -> Optional[Dict[str, Any]]:
    return max(items, key=lambda d: d[key]) if items else None


def _inscribed_circle(self: Region, precision: Optional[float] = None) -> Optional[Dict[str, Any]]:
    """The largest inscribed circle over the components: ``center``, ``radius``
    (a circle of that radius fits) and ``radius_upper`` (none larger fits), in
    the file's unit; ``None`` for an empty region."""
    return _largest(self.inscribed_circles(precision), "radius")


def _inscribed_rectangle(self: Region, precision: float = 1e-6, aspect: Optional[float] = None,
                         width: Optional[float] = None, any_angle: bool = False) -> Optional[Dict[str, Any]]:
    """The largest inscribed rectangle over the components: ``min``, ``max``,
    ``width``, ``height``, ``area`` (certified lower bound, the rectangle is
    inside), ``area_upper`` (no larger rectangle fits), ``verified``. Axis-aligned,
    or with ``any_angle=True`` at any orientation: then also ``angle`` (radians,
    of the ``width`` side) and ``corners``, and ``min``/``max`` are in the frame
    turned by the angle."""
    return _largest(self.inscribed_rectangles(precision, aspect, width, any_angle), "area")


def _geo(self: Region) -> Dict[str, Any]:
    return self.geo_interface()


def _region_repr(self: Region) -> str:
    if self.empty:
        return "<pkmws.Region empty>"
    unit = f" {self.units}²" if self.units else ""
    return f"<pkmws.Region area {self.area:.10g}{unit}, {len(self.components())} component(s)>"


Mechanism.parameters = property(_parameters, doc=Parameters.__doc__)  # type: ignore[attr-defined]
Mechanism.with_parameters = _with_parameters  # type: ignore[attr-defined]
Mechanism.__repr__ = _mechanism_repr  # type: ignore[method-assign]
Region.inscribed_circle = _inscribed_circle  # type: ignore[attr-defined]
Region.inscribed_rectangle = _inscribed_rectangle  # type: ignore[attr-defined]
Region.__geo_interface__ = property(_geo, doc="GeoJSON MultiPolygon (valid in GEOS's model) at the default tolerance")  # type: ignore[attr-defined]
Region.__repr__ = _region_repr  # type: ignore[method-assign]


def metric_names() -> List[str]:
    """The metrics a sweep can compute (``pkmws sweep``'s ``metrics``)."""
    return list(_pkmws._metric_names())


def _base_file(base: Union[Mapping[str, Any], Mechanism], tmp: str) -> str:
    """A base mechanism given as a dict or a ``Mechanism``, written to a file in ``tmp``."""
    if isinstance(base, Mechanism):
        base = base.document
    path = _os.path.join(tmp, "base.json")
    with open(path, "w", encoding="utf-8") as f:
        _json.dump(base, f, allow_nan=False)
    return path


def sweep(base: Union[str, "_os.PathLike[str]", Mapping[str, Any], Mechanism, None] = None,
          parameters: Optional[Sequence[Mapping[str, Any]]] = None, *,
          metrics: Optional[Sequence[str]] = None, sampling: Optional[str] = None,
          samples: Optional[int] = None, task: Optional[Mapping[str, Any]] = None,
          rectangle_precision: Optional[float] = None, criteria_tolerance: Optional[float] = None,
          interference_depth: Optional[int] = None, spec: Union[str, "_os.PathLike[str]", None] = None,
          threads: int = 0) -> List[Dict[str, Any]]:
    """Evaluate metrics over a design space, as ``pkmws sweep`` does.

    ``base`` is the mechanism every design starts from (a path, a dict or a
    ``Mechanism``); ``parameters`` are the sweep file's parameters, e.g.
    ``{"name": "rod", "path": ["legs[0].rod_length", "legs[1].rod_length"],
    "from": 150, "to": 300, "steps": 16}`` or ``{"path": "...", "values": [...]}``
    (values in the file's units). The other keywords are the sweep file's
    fields (docs/design_space.md). Alternatively ``spec`` names a sweep file.

    Returns one dict per design, ordered by index, with the CSV's columns
    (``index``, the parameters, ``status``, metric columns -- ``None`` where
    not computed --, ``time_ms``, ``reason``): ``pandas.DataFrame(rows)``
    accepts it. A bad design is a row with its status, never an exception; a
    bad sweep (unknown field or metric, path not in the file) raises
    ``ValueError`` with the command line's message.
    """
    if spec is not None:
        if base is not None or parameters is not None:
            raise ValueError("sweep: give either spec or base and parameters")
        return _pkmws._run_sweep(_os.fsdecode(_os.fspath(spec)), threads)[1]
    if base is None or parameters is None:
        raise ValueError("sweep: base and parameters are required")
    doc: Dict[str, Any] = {"parameters": list(parameters)}
    for key, value in (("metrics", metrics), ("sampling", sampling), ("samples", samples), ("task", task),
                       ("rectangle_precision", rectangle_precision),
                       ("criteria_tolerance", criteria_tolerance), ("interference_depth", interference_depth)):
        if value is not None:
            doc[key] = list(value) if key == "metrics" else value
    with _tempfile.TemporaryDirectory(prefix="pkmws-sweep-") as tmp:
        doc["base"] = _base_file(base, tmp) if isinstance(base, (Mechanism, Mapping)) else \
            _os.path.abspath(_os.fsdecode(_os.fspath(base)))
        spec_path = _os.path.join(tmp, "sweep.json")
        try:
            text = _json.dumps(doc, allow_nan=False)
        except (TypeError, ValueError) as e:
            raise ValueError(f"sweep: not a JSON document ({e})") from None
        with open(spec_path, "w", encoding="utf-8") as f:
            f.write(text)
        try:
            return _pkmws._run_sweep(spec_path, threads)[1]
        except ValueError as e:
            # Name the sweep as the caller gave it, not the scratch file.
            raise ValueError(str(e).replace(spec_path, "<sweep>").replace(tmp + _os.sep, "")) from None


def optimize(spec: Union[str, "_os.PathLike[str]", Mapping[str, Any]], *,
             history: bool = False) -> Dict[str, Any]:
    """Design synthesis, as ``pkmws optimize SPEC --json`` (docs/design_space.md).

    ``spec`` is an optimisation file (a path; its ``base`` is relative to the
    file) or its content as a dict (``base`` relative to the current
    directory, or a dict / ``Mechanism`` of the base mechanism itself), e.g.
    ``{"base": "m.json", "parameters": [{"name": "rod", "path":
    ["legs[0].rod_length", "legs[1].rod_length"], "from": 150, "to": 300}],
    "objective": {"minimize": "rod"}, "constraints": ["task_margin >= 5"],
    "task": {"center": [0, -300], "size": [80, 40]}}``.

    Returns the report as a dict (``status``, ``objective``, ``parameters``
    with the optimum's ``value``, ``constraints`` with their ``margin``,
    ``evaluations``, ``phases``, ``document``: the optimum's mechanism file);
    with ``history=True`` also ``history``: every evaluation as a dict with the
    sweep's columns. A bad spec raises ``ValueError`` with the command line's
    one-line message; an infeasible problem is ``status == "infeasible"``.
    """
    with _tempfile.TemporaryDirectory(prefix="pkmws-optimize-") as tmp:
        if isinstance(spec, Mapping):
            doc = dict(spec)
            base = doc.get("base")
            if isinstance(base, (Mechanism, Mapping)):
                doc["base"] = _base_file(base, tmp)
            try:
                text = _json.dumps(doc, allow_nan=False)
            except (TypeError, ValueError) as e:
                raise ValueError(f"<dict>: not a JSON document ({e})") from None
            directory, name = _os.getcwd(), "<dict>"
        elif isinstance(spec, (str, bytes, _os.PathLike)):
            name = _os.fsdecode(_os.fspath(spec))
            try:
                with open(name, encoding="utf-8") as f:
                    text = f.read()
            except OSError:
                raise ValueError(f"{name}: cannot open the optimisation file") from None
            directory = _os.path.dirname(_os.path.abspath(name))
        else:
            raise ValueError(f"optimize: expected a file path or a dict, got {type(spec).__name__}")
        report, csv_text = _pkmws._optimize(text, directory, name)
    result: Dict[str, Any] = _json.loads(report)
    if history:
        import csv as _csv
        import io as _io
        rows = []
        for row in _csv.DictReader(_io.StringIO(csv_text)):
            out: Dict[str, Any] = {}
            for key, value in row.items():
                if key in ("status", "reason"):
                    out[key] = value
                elif key == "index":
                    out[key] = int(value)
                else:
                    out[key] = float(value) if value != "" else None
            rows.append(out)
        result["history"] = rows
    return result
