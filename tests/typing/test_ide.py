"""What an editor shows: completion and hover from pyright's language server.

Drives ``pyright-langserver --stdio`` (the engine of VS Code's Pylance) through the client of
``tests/lsp.py``, with in-memory documents, the way an editor does:

- completion after ``<element>.add_`` lists exactly the legal children of that element;
- completion of keyword arguments inside ``add_geom(`` lists the attributes of ``<geom>``;
- hover on a property (``joint.type``) shows its type and its docstring: the MJCF type,
  the default, the allowed values and the link to MuJoCo's XML reference;
- signature help and hover on a keyword of ``add_<tag>(`` show that keyword's own line, the
  one ``test_docs.py`` predicts for every keyword from the docstring.

One server per module; each request waits at most ``TIMEOUT`` seconds.
"""

from __future__ import annotations

import inspect
from collections.abc import Iterator, Mapping
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from tests.lsp import JSON, LanguageServer
from tests.support.pyright_docs import pyright_parameter_doc
from typed_mjcf import Element

ROOT = Path(__file__).resolve().parents[2]
TIMEOUT = 60.0


@pytest.fixture(scope="module")
def server() -> Iterator[LanguageServer]:
    client = LanguageServer(ROOT, TIMEOUT)
    yield client
    client.close()


# Documents are opened under tests/typing (never written to disk), so the repository's
# pyproject.toml configures them like the rest of the typed code.
PROBES = ROOT / "tests" / "typing"

SOURCE = """\
import typed_mjcf as mjcf

model = mjcf.RootElement()
body = model.worldbody.add_body(name="arm")
joint = body.add_joint(name="shoulder")
geom = body.add_geom(name="upper")
"""

# variable in SOURCE -> its class
ELEMENTS: Mapping[str, type[Element]] = {
    "model": mjcf.RootElement,
    "model.worldbody": mjcf.Worldbody,
    "body": mjcf.Body,
    "joint": mjcf.Joint,
    "geom": mjcf.Geom,
    "model.default": mjcf.Default,
    "model.actuator": mjcf.Actuator,
    "model.sensor": mjcf.Sensor,
}


# add_... methods of the runtime base (not tags), e.g. add_copy(element)
GENERIC_ADDERS = {name for name in dir(Element) if name.startswith("add_")}
ELEMENT_CLASSES = [cls for cls in vars(mjcf).values()
                   if isinstance(cls, type) and issubclass(cls, Element) and "_SPEC" in vars(cls)]


def complete_at_end(server: LanguageServer, name: str, text: str) -> list[JSON]:
    source = SOURCE + text
    last = source.splitlines()[-1]
    uri = server.open(PROBES / f"_ide_probe_{name}.py", source)
    return server.completion(uri, source.count("\n"), len(last))


@pytest.mark.parametrize("expression", list(ELEMENTS))
def test_add_completion_lists_exactly_the_legal_children(
        server: LanguageServer, expression: str) -> None:
    cls = ELEMENTS[expression]
    name = expression.replace(".", "_")
    items = complete_at_end(server, name, f"{expression}.add_")
    offered = {str(item["label"]) for item in items if str(item["label"]).startswith("add_")}
    legal = {"add_" + tag for tag in cls.spec.children}
    offered -= GENERIC_ADDERS
    assert offered == legal, (
        f"completion after {expression}.add_ (<{cls.spec.tag}>):\n"
        f"  missing: {sorted(legal - offered)}\n  not legal: {sorted(offered - legal)}")


def test_generic_adders_do_not_shadow_tags() -> None:
    """``add_<tag>`` belongs to the grammar; a runtime method named ``add_...`` must not
    take a tag's name (it also shows up in every ``.add_`` completion)."""
    tags = {cls.spec.tag for cls in ELEMENT_CLASSES}
    assert not {name.removeprefix("add_") for name in GENERIC_ADDERS} & tags


def test_keyword_completion_lists_the_attributes(server: LanguageServer) -> None:
    items = complete_at_end(server, "kwargs", "body.add_geom(")
    offered = {str(item["label"]).removesuffix("=") for item in items
               if str(item["label"]).endswith("=")}
    attributes = {a.py_name for a in mjcf.Geom.spec.attributes.values()}
    attributes.add("dclass")  # dm_control's spelling of class_, offered alongside it
    assert offered == attributes, (f"missing: {sorted(attributes - offered)}; "
                                   f"extra: {sorted(offered - attributes)}")


def hover_on(server: LanguageServer, name: str, expression: str) -> str:
    source = SOURCE + f"print({expression})\n"
    uri = server.open(PROBES / f"_ide_hover_{name}.py", source)
    line = source.count("\n") - 1
    return server.hover(uri, line, len("print(") + len(expression) - 1)


def test_hover_on_a_property_shows_type_and_docs(server: LanguageServer) -> None:
    text = hover_on(server, "joint_type", "joint.type")
    assert "type: JointType | None" in text, text  # the keyword set by its public name
    assert "one of: free, ball, slide, hinge" in text, text
    assert 'default "hinge"' in text, text
    assert "https://mujoco.readthedocs.io/en/stable/XMLreference.html#body-joint-type" in text


def test_hover_on_an_array_property(server: LanguageServer) -> None:
    text = hover_on(server, "geom_size", "geom.size")
    assert "size: Float64Array | None" in text, text
    assert "1 to 3 values" in text, text
    assert "XMLreference.html#body-geom-size" in text, text


def test_hover_on_an_add_method_names_the_child(server: LanguageServer) -> None:
    text = hover_on(server, "add_geom", "body.add_geom")
    assert "-> Geom" in text, text
    assert "<geom>" in text, text


# (variable in SOURCE, adder, keyword): the entries the issue found wrong (density= showed
# "one is saved."), a name that ends another (range/ctrlrange), a reference union, a keyword set
SIGNATURE_CASES = [
    ("body", "add_geom", "density"),
    ("body", "add_geom", "type"),
    ("body", "add_joint", "range"),
    ("model.actuator", "add_motor", "ctrlrange"),
    ("model.sensor", "add_framepos", "objname"),
    ("model.worldbody", "add_body", "childclass"),
]


@pytest.mark.parametrize(("expression", "adder", "keyword"), SIGNATURE_CASES,
                         ids=[f"{a}-{k}" for _, a, k in SIGNATURE_CASES])
def test_signature_help_and_hover_show_the_keywords_own_line(
        server: LanguageServer, expression: str, adder: str, keyword: str) -> None:
    """What pyright really shows for a keyword (signature help while typing it, hover on it)
    is the line ``tests/typing/test_docs.py`` predicts from the docstring: the keyword's
    own ``Args:`` entry, which starts with its facts."""
    cls = ELEMENTS[expression]
    function = getattr(cls, adder)
    predicted = pyright_parameter_doc(inspect.getdoc(function) or "", keyword)
    assert predicted is not None and predicted.startswith(f"{keyword}: "), predicted
    call = f"{expression}.{adder}({keyword}="
    source = SOURCE + call + ")\n"
    uri = server.open(PROBES / f"_ide_signature_{adder}_{keyword}.py", source)
    line = source.count("\n") - 1
    label, shown = server.signature_help(uri, line, len(call))
    assert f"{keyword}: " in label, label
    assert shown.strip() == predicted, f"signature help for {call}: {shown!r}"
    hover = server.hover(uri, line, len(f"{expression}.{adder}(") + 1)
    assert predicted in hover, f"hover on {keyword}= in {call}: {hover!r}"
