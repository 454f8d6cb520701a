"""Layers point down (docs/architecture.md): every #include of the library,
the command line, the Python module and the benchmarks goes to its own layer
or a lower one; the command line, the Python module and the benchmarks use
public headers only; concrete mechanism headers are included only inside
their module folder and by that module's tests. The few upward edges that are
left are listed here by file, so that no new one appears unnoticed."""
import re

import pathlib
import subprocess
import tempfile

import pytest

from conftest import CLI, SOURCE_DIR

LAYERS = pathlib.Path(CLI).resolve().parents[1] / "lib" / "layers"

# Lower rank = lower layer.
RANK = {"core": 0, "detail": 0, "geometry": 0, "certified": 0, "mechanisms": 1, "grid": 2, "criteria": 2,
        "bodies": 2, "io": 3, "module": 4, "design": 5, "front": 6, "pkmws.hpp": 6, "report": 7, "app": 8}

# No upward include is left (the registry in io reaches the modules' loaders
# through modules.def at link level, not through an include); the layered
# CMake targets make a new one fail to build (test below).
KNOWN_UPWARD = set()
# A module may use another module: the five-bar drives its cranks with Π-joints.
MODULE_USES = {("five_bar", "pi_joint")}


def layer(rel):
    """The layer of a library path relative to lib/include/pkmws or lib/src."""
    parts = rel.split("/")
    if parts[0] == "mechanisms":
        return "module" if len(parts) > 2 else "mechanisms"
    return parts[0]


def includes(path):
    return re.findall(r'^#include "([^"]+)"', path.read_text(), re.M)


def library_files():
    for base in ("lib/include/pkmws", "lib/src"):
        for p in sorted((SOURCE_DIR / base).rglob("*.[ch]pp")):
            yield p, layer(str(p.relative_to(SOURCE_DIR / base)))


def target_layer(inc):
    if inc.startswith("pkmws/"):
        return layer(inc[len("pkmws/"):])
    return layer(inc)


def test_library_includes_point_down():
    upward = set()
    for path, own in library_files():
        for inc in includes(path):
            if "/" not in inc:
                continue  # a sibling file of the same folder
            other = target_layer(inc)
            assert other in RANK, (path, inc)
            if RANK[other] > RANK[own]:
                upward.add((str(path.relative_to(SOURCE_DIR)), inc))
    assert upward == KNOWN_UPWARD, f"new upward includes: {sorted(upward - KNOWN_UPWARD)}; " \
                                   f"gone (remove from KNOWN_UPWARD): {sorted(KNOWN_UPWARD - upward)}"


def test_front_ends_use_public_headers_only():
    for folder in ("apps/pkmws", "python/src", "benchmarks"):
        for path in sorted((SOURCE_DIR / folder).glob("*.[ch]pp")):
            for inc in includes(path):
                local = (path.parent / inc).exists()
                assert inc.startswith("pkmws/") or local, (str(path), inc)


def test_concrete_mechanisms_stay_in_their_modules():
    """Only a module's own folder (and its tests) includes its headers."""
    for path in sorted(SOURCE_DIR.glob("**/*.[ch]pp")):
        rel = str(path.relative_to(SOURCE_DIR))
        if rel.startswith(("build", "tests/")):
            continue
        for inc in includes(path):
            m = re.match(r"mechanisms/([a-z_]+)/", inc)
            if m:
                owner = rel.split("/")[3] if rel.startswith("lib/src/mechanisms/") and rel.count("/") > 3 else None
                assert owner == m.group(1) or (owner, m.group(1)) in MODULE_USES, (rel, inc)


def compiles_in(layer, include):
    """Does a file of `layer` that includes `include` compile in that layer's include tree?"""
    tree = LAYERS / layer
    with tempfile.TemporaryDirectory() as tmp:
        src = pathlib.Path(tmp) / "probe.cpp"
        src.write_text(f'#include "{include}"\n')
        r = subprocess.run(["c++", "-std=c++20", "-fsyntax-only", "-I", str(tree / "include"), "-I", str(tree / "src"),
                            "-I", "/usr/include/eigen3", str(src)], capture_output=True, text=True, timeout=300)
        return r.returncode == 0, r.stderr


@pytest.mark.parametrize("layer, allowed, forbidden", [
    ("core", "pkmws/geometry/region.hpp", "pkmws/mechanisms/mechanism.hpp"),
    ("mechanisms", "pkmws/mechanisms/capability.hpp", "pkmws/criteria/fields.hpp"),
    ("analyses", "pkmws/criteria/fields.hpp", "pkmws/io/export.hpp"),
    ("analyses", "pkmws/grid/sampler.hpp", "mechanisms/five_bar/five_bar.hpp"),
    ("io", "pkmws/io/export.hpp", "pkmws/design/sweep.hpp"),
    ("modules", "mechanisms/five_bar/five_bar.hpp", "pkmws/pkmws.hpp"),
    ("design", "pkmws/design/sweep.hpp", "pkmws/pkmws.hpp"),
    ("front", "pkmws/pkmws.hpp", "pkmws/report/area.hpp"),
    ("report", "pkmws/report/area.hpp", "cli.hpp"),
])
def test_an_upward_include_fails_to_build(layer, allowed, forbidden):
    """Each layer is compiled against a tree of its own and lower layers' headers only."""
    assert (LAYERS / layer).is_dir(), f"no include tree for layer {layer} under {LAYERS}"
    ok, err = compiles_in(layer, allowed)
    assert ok, err[-2000:]
    ok, err = compiles_in(layer, forbidden)
    assert not ok and "No such file" in err, (layer, forbidden, err[-500:])
