"""Sphinx configuration of the typed-mjcf documentation (``nox -s docs``).

Sphinx with MyST (pages in Markdown, as the README is) and the furo theme: Sphinx's strict
mode (``-W -n``) fails the build on a broken link, a missing page or an API name that does not
resolve, and autodoc reads the runtime's own docstrings and annotations.
"""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from sphinx.util.nodes import make_refnode

if TYPE_CHECKING:
    from docutils.nodes import Element
    from sphinx.addnodes import pending_xref
    from sphinx.application import Sphinx
    from sphinx.environment import BuildEnvironment

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT / "src"), str(ROOT / "generated")]
os.environ.setdefault("MUJOCO_GL", "egl")  # importing typed_mjcf.physics must not need a display

# The MJCF reference is generator output (generated/mjcf-reference/, kept current by
# `python -m codegen render` and tests/codegen/test_reference.py); the site shows it under
# reference/, copied here on each build (docs/reference/ is not committed).
_REFERENCE = Path(__file__).resolve().parent / "reference"
shutil.rmtree(_REFERENCE, ignore_errors=True)
shutil.copytree(ROOT / "generated" / "mjcf-reference", _REFERENCE)

project = "typed-mjcf"
author = "The typed-mjcf authors"
copyright = "2026, The typed-mjcf authors"

extensions = ["myst_parser", "sphinx.ext.autodoc"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build"]
myst_heading_anchors = 3
myst_enable_extensions = ["colon_fence"]
# ```console and ```text blocks are shown as they are
highlight_language = "python"
suppress_warnings = ["myst.xref_missing"] if os.environ.get("DOCS_LOOSE") else []

nitpicky = True
# Names of other packages: no inventory of theirs is reachable from the build (no network),
# so they are shown as written. Every typed_mjcf name must resolve.
# private type variables: Array's, and the root's camera and key (render's parameters)
nitpick_ignore = [("py:obj", "typed_mjcf.types._S"), ("py:class", "_Camera_contra"),
                  ("py:class", "_Key_contra")]
nitpick_ignore_regex = [
    (r"py:.*", (r"(numpy|np|npt|lxml|mujoco|collections|typing|typing_extensions|os|pathlib"
               r"|zipfile|io|builtins|types|_typeshed|enum|dataclasses)(\..*)?")),
    (r"py:.*", (r"(NDArray|Path|PathLike|Any|Self|Iterator|Iterable|Sequence|Mapping|Callable"
               r"|Collection|TypeAlias|Literal|Final|IO|BinaryIO|Buffer|StrPath|float64"
               r"|uint8|int32|bool_|dtype|ndarray|MjModel|MjData|MjSpec|Renderer)")),
]
autodoc_member_order = "bysource"
autodoc_typehints = "signature"
autodoc_typehints_format = "short"
autodoc_preserve_defaults = True



def _public_target(app: Sphinx, env: BuildEnvironment, node: pending_xref,
                   contnode: Element) -> Element | None:
    """A name written by its private module (``typed_mjcf._core.tree.Element``) or bare
    (``Element``, ``Body``) resolved to what users import: the documented public object, else
    the element class's page of the MJCF reference. Anything else stays a warning."""
    if node.get("refdomain") != "py":
        return None
    target = str(node.get("reftarget", ""))
    if not (target.startswith("typed_mjcf.") or "." not in target):
        return None
    name = target.rsplit(".", 1)[-1]
    name = _PUBLIC_BASES.get(name, name)
    domain = env.get_domain("py")
    for public in (f"typed_mjcf.{name}", f"typed_mjcf.types.{name}",
                   f"typed_mjcf.physics.{name}"):
        for kind in (str(node["reftype"]), "obj"):  # a type alias is data, written as a class
            found = domain.resolve_xref(env, node["refdoc"], app.builder, kind, public, node,
                                        contnode)
            if found is not None:
                return found
    page = _ELEMENT_PAGES.get(name)
    if page is None:
        return None
    return make_refnode(app.builder, node["refdoc"], page, None, contnode, name)


# Private bases whose public face is another class: a function taking any model root.
_PUBLIC_BASES = {"ModelBase": "ModelRoot"}
_ELEMENT_PAGES = {
    line.split("`")[3]: "reference/" + line.split("](")[1].split(".md")[0]
    for line in (ROOT / "generated" / "mjcf-reference" / "index.md").read_text(
        encoding="utf-8").splitlines() if line.startswith("| [`<")}


def setup(app: Sphinx) -> None:
    app.connect("missing-reference", _public_target)


html_theme = "furo"
html_title = "typed-mjcf"
html_static_path: list[str] = []
