"""The chapter index (docs/chapters.rst): every chapter of the book, 1 to 27, names at least
one object of the library and at least one worked example; every example it links exists in
examples/, every gallery script is linked, and every API target it names can be imported."""

import importlib
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
PAGE = ROOT / "docs" / "chapters.rst"
EXAMPLES = ROOT / "examples"

HEADING = re.compile(r"^Chapter (\d+) -- (.+)\n~+\n", re.M)
API_ROLE = re.compile(r":(class|func|meth|mod|attr|data|obj):`~?([^`<>]+?)`")
EXAMPLE_REF = re.compile(r":ref:`sphx_glr_auto_examples_(plot_\w+)\.py`")


def chapters():
    """{number: section text} of the page, one entry per 'Chapter N -- Title' heading."""
    text = PAGE.read_text(encoding="utf-8")
    heads = list(HEADING.finditer(text))
    sections = {}
    for k, head in enumerate(heads):
        end = heads[k + 1].start() if k + 1 < len(heads) else len(text)
        number = int(head.group(1))
        assert number not in sections, f"chapter {number} appears twice"
        sections[number] = text[head.end():end]
    return sections


def resolve(target):
    """Import the longest module prefix of ``target``, then getattr the rest."""
    parts = target.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        for name in parts[cut:]:
            obj = getattr(obj, name)
        return obj
    raise ImportError(f"no importable module in {target!r}")


def test_every_chapter_has_library_entries_and_examples():
    sections = chapters()
    assert sorted(sections) == list(range(1, 28))
    for number, body in sections.items():
        assert API_ROLE.search(body), f"chapter {number} names no library object"
        assert EXAMPLE_REF.search(body), f"chapter {number} links no example"


def test_linked_examples_exist_and_every_example_is_linked():
    linked = {name for body in chapters().values() for name in EXAMPLE_REF.findall(body)}
    for name in sorted(linked):
        assert (EXAMPLES / f"{name}.py").is_file(), f"{name}.py is not in examples/"
    scripts = {path.stem for path in EXAMPLES.glob("plot_*.py")}
    assert scripts - linked == set(), "gallery scripts missing from the chapter index"


@pytest.mark.parametrize(
    "target",
    sorted({target for _, target in API_ROLE.findall(PAGE.read_text(encoding="utf-8"))}),
)
def test_api_targets_import(target):
    assert target.startswith("rigidmech."), target
    resolve(target)


def test_resolve_refuses_a_missing_name():
    with pytest.raises(AttributeError):
        resolve("rigidmech.vectors.NoSuchThing")
