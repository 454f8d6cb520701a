"""Reading pkmws figures back: elements by class, the plot's px <-> model
mapping (data-transform="X0 Y0 S": px = X0 + S x, py = Y0 - S y), caption
text and numbers, and the area of a path made of M/L/A/Z commands (arcs
converted from SVG's endpoint form to centre form, as in the SVG spec F.6.5)."""
import math
import re
import xml.etree.ElementTree as ET

NS = "{http://www.w3.org/2000/svg}"
NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?")


def load(path):
    return ET.parse(str(path)).getroot()


def by_class(root, name, tag=None):
    out = []
    for el in root.iter():
        if tag and el.tag != NS + tag:
            continue
        if name in (el.get("class") or "").split():
            out.append(el)
    return out


def mapping(root):
    (plot,) = by_class(root, "plot", "g")
    x0, y0, s = map(float, plot.get("data-transform").split())
    return x0, y0, s


def to_model(root, px, py):
    x0, y0, s = mapping(root)
    return (px - x0) / s, (y0 - py) / s


def caption(root):
    return " ".join((t.text or "") for t in by_class(root, "caption", "text"))


def legend_texts(root):
    (g,) = by_class(root, "legend", "g")
    return [t.text or "" for t in g.iter(NS + "text")]


def numbers(text):
    return [float(m) for m in NUMBER.findall(text.replace("\u2212", "-"))]


def points(attr):
    vals = [float(v) for v in re.split(r"[ ,]+", attr.strip()) if v]
    return list(zip(vals[0::2], vals[1::2]))


def _arc_points(x1, y1, rx, ry, large, sweep, x2, y2, n=64):
    # Circular arcs only (rx == ry, no rotation): centre from the endpoint form.
    r = rx
    dx, dy = (x1 - x2) / 2, (y1 - y2) / 2
    d2 = dx * dx + dy * dy
    if d2 == 0:
        return [(x2, y2)]
    r = max(r, math.sqrt(d2))
    f = math.sqrt(max(0.0, r * r - d2) / d2)
    if large == sweep:
        f = -f
    cx = (x1 + x2) / 2 + f * dy
    cy = (y1 + y2) / 2 - f * dx
    a1 = math.atan2(y1 - cy, x1 - cx)
    a2 = math.atan2(y2 - cy, x2 - cx)
    da = a2 - a1
    if sweep and da < 0:
        da += 2 * math.pi
    if not sweep and da > 0:
        da -= 2 * math.pi
    return [(cx + r * math.cos(a1 + da * k / n), cy + r * math.sin(a1 + da * k / n)) for k in range(1, n + 1)]


def path_rings(d):
    """Rings (lists of px points) of a path of absolute M, L, A, Z commands."""
    tokens = re.findall(r"[MLAZ]|[-+]?\d*\.?\d+(?:[eE][-+]?\d+)?", d)
    rings, ring, k, cmd = [], [], 0, None
    while k < len(tokens):
        t = tokens[k]
        if t in "MLAZ":
            cmd = t
            k += 1
            if cmd == "Z":
                if ring:
                    rings.append(ring)
                ring = []
            continue
        if cmd == "M":
            if ring:
                rings.append(ring)
            ring = [(float(tokens[k]), float(tokens[k + 1]))]
            k += 2
            cmd = "L"
        elif cmd == "L":
            ring.append((float(tokens[k]), float(tokens[k + 1])))
            k += 2
        elif cmd == "A":
            rx, ry, _rot, large, sweep, x, y = map(float, tokens[k:k + 7])
            x1, y1 = ring[-1]
            ring += _arc_points(x1, y1, rx, ry, int(large), int(sweep), x, y)
            k += 7
        else:
            raise ValueError("unexpected token " + t)
    if ring:
        rings.append(ring)
    return rings


def ring_area(ring):
    a = 0.0
    for (x1, y1), (x2, y2) in zip(ring, ring[1:] + ring[:1]):
        a += x1 * y2 - x2 * y1
    return a / 2


def path_area_model(root, d):
    """Area (model units²) of an even-odd path whose rings nest without crossing."""
    _, _, s = mapping(root)
    return abs(sum(ring_area(r) for r in path_rings(d))) / (s * s)


def path_geometry(d, rule="evenodd"):
    """The filled set of a path (px) as a shapely geometry: even-odd by
    symmetric differences; nonzero for rings that do not cross (outer loops
    one way, holes the other) as union(outer) - union(holes)."""
    from shapely.geometry import Polygon
    from shapely.ops import unary_union
    rings = [r for r in path_rings(d) if len(r) >= 3]
    polys = [(Polygon(r).buffer(0), ring_area(r)) for r in rings]
    if rule == "evenodd":
        g = Polygon()
        for p, _ in polys:
            g = g.symmetric_difference(p)
        return g
    sign = max(polys, key=lambda pa: abs(pa[1]))[1] > 0
    outer = unary_union([p for p, a in polys if (a > 0) == sign])
    holes = unary_union([p for p, a in polys if (a > 0) != sign])
    return outer.difference(holes)


def clip_path_d(root):
    for cp in root.iter(NS + "clipPath"):
        return cp.find(NS + "path").get("d")
    return None


def drawn_area_model(root, el):
    """Area (model units²) of an overlay path as drawn: clipped to the clip path it names."""
    _, _, s = mapping(root)
    g = path_geometry(el.get("d"), el.get("fill-rule") or "nonzero")
    if el.get("clip-path"):
        g = g.intersection(path_geometry(clip_path_d(root), "evenodd"))
    return g.area / (s * s)
