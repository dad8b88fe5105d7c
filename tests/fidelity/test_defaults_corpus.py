"""``commit_defaults`` and ``resolve`` agree with MuJoCo over every corpus model it compiles.

Committing every element's defaults and then deleting every default class (and every
``class``/``childclass`` naming one) must compile to the model MuJoCo compiles from the
file, field by field: the classes then say nothing the elements do not say themselves.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support import corpus
from tests.support.compare import clear_asset_cache, model_differences
from tests.support.corpus import corpus_files
from typed_mjcf._core import tree as _tree
from typed_mjcf._model.defaults import resolve, resolve_all


@pytest.fixture(autouse=True)
def _fresh_asset_cache() -> None:
    """Each test's compiles read their own files (tests/support/compare.py's clear_asset_cache)."""
    clear_asset_cache()


def _strip_classes(model: mjcf.RootElement) -> int:
    """Remove every default class and every attribute naming one; how many were named."""
    named = 0
    for element in list(model.iter_elements()):
        for attribute in element.spec.attributes.values():
            if attribute.namespace == "default" and attribute.name in _tree.values(element):
                element.set_attributes(**{attribute.py_name: None})
                named += 1
    for section in list(model.default.get_children()):
        section.remove()
    return named


def test_the_corpus_has_models_with_classes() -> None:
    compilable = 0
    for ident, path in corpus.CORPUS:
        try:
            corpus.compiled(ident, path)
        except pytest.skip.Exception:
            continue
        compilable += 1
    assert compilable >= 40


# Every corpus file; those MuJoCo does not compile by itself are skipped at run time (deciding
# that at collection compiled the whole corpus in every pytest process, `-m "not slow"` too).
@pytest.mark.parametrize(("ident", "path"), corpus.corpus_params())
def test_committed_defaults_compile_like_the_classes(ident: str, path: Path) -> None:
    expected = corpus.compiled(ident, path)  # shared with the module's other tests: only read
    model = mjcf.from_path(path, files=corpus_files(ident, path))
    for element in list(model.iter_elements()):
        mjcf.commit_defaults(element)
    _strip_classes(model)
    assert not model.default.get_children()
    actual = model.compile()
    _copy_what_fixed_tendons_cannot_state(expected, actual)
    assert model_differences(expected, actual) == []


def _copy_what_fixed_tendons_cannot_state(expected: mujoco.MjModel,
                                          actual: mujoco.MjModel) -> None:
    """A ``<tendon>`` default sets ``width``, ``rgba`` and ``material``, which a ``<fixed>``
    tendon takes from its class but has no attributes to state itself: those fields of
    fixed tendons are left out of the comparison (taken from MuJoCo's compile)."""
    for tendon in range(expected.ntendon):
        start, count = expected.tendon_adr[tendon], expected.tendon_num[tendon]
        wraps = expected.wrap_type[start:start + count]
        if (wraps == mujoco.mjtWrap.mjWRAP_JOINT).all():
            actual.tendon_width[tendon] = expected.tendon_width[tendon]
            actual.tendon_rgba[tendon] = expected.tendon_rgba[tendon]
            actual.tendon_matid[tendon] = expected.tendon_matid[tendon]


def test_a_shorter_array_keeps_the_rest_from_its_classes_as_mujoco_reads_it() -> None:
    model = mjcf.from_xml_string("""<mujoco>
      <default>
        <geom size="1 2 3" friction="0.7 0.01 0.002"/>
        <default class="outer">
          <geom size="4 5"/>
          <default class="inner"><geom friction="0.3"/></default>
        </default>
      </default>
      <worldbody><body>
        <geom name="a" type="box" size="0.5" friction="0.2"/>
        <geom name="b" type="box" class="inner" size="0.25"/>
        <site name="s" size="0.1"/>
      </body></worldbody>
    </mujoco>""")
    compiled = model.compile()
    for name in ("a", "b"):
        geom = model.find("geom", name)
        assert isinstance(geom, mjcf.Geom)
        index = mujoco.mj_name2id(compiled, mujoco.mjtObj.mjOBJ_GEOM, name)
        size, friction = geom.resolve("size"), geom.resolve("friction")
        assert size is not None and size.tolist() == compiled.geom_size[index].tolist()
        assert friction is not None
        assert friction.tolist() == compiled.geom_friction[index].tolist()
    site = model.find("site", "s")
    assert isinstance(site, mjcf.Site)
    size = site.resolve("size")  # the rest from the grammar's default
    assert size is not None and size.tolist() == compiled.site_size[0].tolist()
    before = list(model.find_all("geom"))
    for geom in before:
        mjcf.commit_defaults(geom)
    b = model.find("geom", "b")
    assert isinstance(b, mjcf.Geom) and b.size is not None and b.size.tolist() == [0.25, 5, 3]


def test_resolve_all_is_resolve_of_each_attribute() -> None:
    """``_defaults.resolve_all`` (what ``typed-mjcf diff --resolved`` reads: each element's
    classes found once) gives what ``resolve`` gives, attribute by attribute, with and
    without the grammar's defaults, over every corpus model with default classes."""
    checked = 0
    for ident, path in corpus.CORPUS:
        try:
            model = mjcf.from_path(path, files=corpus_files(ident, path))
        except mjcf.MjcfError:
            continue
        if not model.default.get_children():
            continue
        for element in model.iter_elements():
            if element.spec.defaults_tag is None:  # no class applies: nothing to find once
                continue
            for grammar_defaults in (True, False):
                try:
                    every = resolve_all(element, grammar_defaults)
                except mjcf.MjcfError as error:  # a class not defined here: resolve says so
                    with pytest.raises(type(error)):
                        for name in element.spec.attributes:
                            resolve(element, name, grammar_defaults)
                    continue
                for name, value in every.items():
                    alone = resolve(element, name, grammar_defaults)
                    assert np.array_equal(value, alone) if isinstance(alone, np.ndarray) else (
                        value is alone or value == alone), (ident, element.path, name)
                    checked += 1
    assert checked > 100_000


def test_an_own_value_resolves_when_the_class_is_not_defined() -> None:
    """A class is looked up only for what the element does not set itself: its own values
    resolve (one by one and all at once) though its class names nothing; the others say
    which class is missing."""
    model = mjcf.RootElement()
    geom = model.worldbody.add_geom(pos=(1, 2, 3), dclass="nosuch")
    assert geom.resolve("pos").tolist() == [1, 2, 3]
    with pytest.raises(mjcf.MjcfError, match="default class 'nosuch' is not defined"):
        geom.resolve("size")
    with pytest.raises(mjcf.MjcfError, match="default class 'nosuch' is not defined"):
        resolve_all(geom)
    model.default.add_default(class_="nosuch").add_geom(size=(0.5,))
    every = resolve_all(geom)
    assert every["pos"].tolist() == [1, 2, 3] and every["size"].tolist() == [0.5]
