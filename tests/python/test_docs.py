"""The repository explains itself: every relative link of README.md and docs/
resolves (file and heading), every docs/... path named in the sources exists,
the papers cited by key are in docs/references.md, the examples of
docs/format.md load and match their schemas, and nothing points outside the
repository (to the notes and paper copies it was built from)."""
import json
import pathlib
import re
import subprocess
import tempfile

import jsonschema
import pytest

from conftest import SOURCE_DIR, run

THIS = pathlib.Path(__file__).resolve()


def tracked_files():
    out = subprocess.run(["git", "-C", str(SOURCE_DIR), "ls-files", "-z"], capture_output=True, check=True).stdout
    files = [SOURCE_DIR / p for p in out.decode().split("\0") if p]
    return [f for f in files if f.is_file()]


def text_of(path):
    try:
        return path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        return None  # binary


def markdown_files():
    return [SOURCE_DIR / "README.md"] + sorted((SOURCE_DIR / "docs").rglob("*.md"))


def slug(heading):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to '-'."""
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)  # keeps letters (any script), digits, _, -, space
    return s.replace(" ", "-")


def anchors(md_path):
    text = md_path.read_text(encoding="utf-8")
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    found, seen = set(), {}
    for m in re.finditer(r"^#{1,6}\s+(.*?)\s*#*\s*$", text, flags=re.M):
        a = slug(m.group(1))
        n = seen.get(a, 0)
        seen[a] = n + 1
        found.add(a if n == 0 else f"{a}-{n}")
    return found


LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def relative_links(md_path):
    text = re.sub(r"```.*?```", "", md_path.read_text(encoding="utf-8"), flags=re.S)
    text = re.sub(r"`[^`\n]*`", "", text)  # code spans are not links
    for m in LINK.finditer(text):
        target = m.group(1)
        if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
            continue
        yield target


@pytest.mark.parametrize("md", markdown_files(), ids=lambda p: str(p.relative_to(SOURCE_DIR)))
def test_relative_links_resolve(md):
    problems = []
    for target in relative_links(md):
        path, _, anchor = target.partition("#")
        dest = (md.parent / path).resolve() if path else md
        if not dest.exists():
            problems.append(f"{target}: no such file")
            continue
        try:
            dest.relative_to(SOURCE_DIR.resolve())
        except ValueError:
            problems.append(f"{target}: outside the repository")
            continue
        if anchor and dest.suffix == ".md" and anchor not in anchors(dest):
            problems.append(f"{target}: no heading #{anchor} in {dest.name}")
    assert not problems, f"{md.relative_to(SOURCE_DIR)}: " + "; ".join(problems)


DOCS_PATH = re.compile(r"(?<![\w/.])docs/[\w./-]*[\w/]")


def test_docs_paths_named_in_the_repository_exist():
    missing = []
    for f in tracked_files():
        if f == THIS:
            continue
        text = text_of(f)
        if text is None:
            continue
        for m in DOCS_PATH.finditer(text):
            p = m.group(0).rstrip("/")
            p = re.sub(r"\.$", "", p)
            if not (SOURCE_DIR / p).exists():
                missing.append(f"{f.relative_to(SOURCE_DIR)}: {p}")
    assert not missing, "\n".join(sorted(set(missing)))


def test_source_comments_name_docs_files_that_exist():
    """A negative control for the path scan: it does find the references the code makes."""
    found = set()
    for f in tracked_files():
        if f.suffix in (".cpp", ".hpp") and (text := text_of(f)):
            found.update(m.group(0) for m in DOCS_PATH.finditer(text))
    assert "docs/format.md" in found and any(p.startswith("docs/theory/") for p in found), found


# Built from pieces so that this file does not match itself.
FORBIDDEN = [
    re.compile(re.escape("../" + "shared")),
    re.compile(re.escape("SPEC" + ".md")),
    re.compile(re.escape("DESIGN" + ".md")),
    re.compile(re.escape("CGAL" + "-NOTES")),
    re.compile(r"\bs" + r"eeds?[ _/-]?0\d\d", re.I),
    re.compile(r"\b0\d\d_[0-9a-f]{16}\b"),  # the paper copies' file names
]


def test_nothing_points_outside_the_repository():
    hits = []
    for f in tracked_files():
        text = text_of(f)
        if text is None:
            continue
        for pattern in FORBIDDEN:
            for m in pattern.finditer(text):
                line = text.count("\n", 0, m.start()) + 1
                hits.append(f"{f.relative_to(SOURCE_DIR)}:{line}: {m.group(0)}")
    assert not hits, "\n".join(hits)


def test_forbidden_patterns_do_match_what_they_forbid():
    samples = ["see ../" + "shared/x", "SPEC" + ".md", "DESIGN" + ".md", "CGAL" + "-NOTES", "S" + "EED_002", "s" + "eed 004",
               "s" + "eeds/000_x", "003_" + "fe645665c52cfb92.txt"]
    for s in samples:
        assert any(p.search(s) for p in FORBIDDEN), s


KEYS = ["Vasilic", "Mitsi", "Milutinovic", "Strutynskyi", "Briot"]


def test_references_have_every_cited_key_as_a_heading():
    refs = SOURCE_DIR / "docs" / "references.md"
    heads = anchors(refs)
    for key in KEYS:
        assert key.lower() in heads, key
    # Every bracketed capitalised word that is cited like a paper is one of the keys.
    cited = set()
    cite = re.compile(r"\[([A-Z][a-z]+)\](?:'s)?\s+(?:eq|eqs|fig|figs|figure|figures|Table|Tables|§)")
    for f in tracked_files():
        if f.suffix in (".cpp", ".hpp", ".md", ".py", ".json") and (text := text_of(f)):
            cited.update(m.group(1) for m in cite.finditer(text))
    assert cited, "the scan found no citation at all"
    assert cited <= set(KEYS), cited - set(KEYS)


def format_examples(*files):
    """The mechanism files shown in ```json blocks (docs/format.md by default)."""
    out = []
    for f in files or ("docs/format.md",):
        text = (SOURCE_DIR / f).read_text(encoding="utf-8")
        blocks = re.findall(r"```json\n(.*?)```", text, flags=re.S)
        out += [json.loads(b) for b in blocks if '"mechanism"' in b]
    return out


def test_format_md_has_an_example_of_every_kind():
    kinds = {d["mechanism"] for d in format_examples()}
    assert kinds == {"moma", "five_bar", "biglide", "pi_joint", "three_rrp", "three_prp", "three_rpr"}
    assert any("bodies" in d and d["mechanism"] == k for d in format_examples() for k in ("moma", "five_bar"))
    assert any("criteria" in d for d in format_examples())


@pytest.mark.parametrize("example", format_examples("docs/format.md", "README.md"), ids=lambda d: d["mechanism"] + ": " + d["name"][:30])
def test_format_examples_load_and_match_their_schema(example):
    schema = json.loads((SOURCE_DIR / "docs" / "schema" / f"{example['mechanism']}.schema.json").read_text())
    jsonschema.Draft7Validator(schema).validate(example)
    with tempfile.TemporaryDirectory() as d:
        p = pathlib.Path(d) / "example.json"
        p.write_text(json.dumps(example))
        r = run("info", p, check=False)
    assert r.returncode == 0, r.stderr


def test_format_md_lists_every_field_the_schemas_know():
    """Each property of each schema is named in docs/format.md (as `field` or `parent.field`)."""
    text = (SOURCE_DIR / "docs" / "format.md").read_text(encoding="utf-8")
    missing = []

    def walk(schema, kind):
        for key, sub in schema.get("properties", {}).items():
            if not re.search(r"`(?:[\w\[\]]+\.)*" + re.escape(key) + r"`", text):
                missing.append(f"{kind}: {key}")
            walk(sub, kind)
        for k in ("items",):
            if isinstance(schema.get(k), dict):
                walk(schema[k], kind)
        for alt in schema.get("oneOf", []):
            walk(alt, kind)

    for s in sorted((SOURCE_DIR / "docs" / "schema").glob("*.schema.json")):
        walk(json.loads(s.read_text()), s.name)
    assert not missing, missing
