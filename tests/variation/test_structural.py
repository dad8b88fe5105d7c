"""Structural variants: built from a seeded generator per world, the same in this process
and on local processes (Ray: test_ray.py)."""

from __future__ import annotations

import pickle
import sys

import mujoco
import pytest

import typed_mjcf as mjcf
from tests.variation.builders import failing_at_world_3, table_scene
from typed_mjcf.variation import VariantError, generate, structure_rng, variants


def test_variants_are_seeded_per_world() -> None:
    first = [m.to_xml_string() for m in variants(table_scene, seed=4, n=6)]
    again = [m.to_xml_string() for m in variants(table_scene, seed=4, n=6)]
    later = [m.to_xml_string() for m in variants(table_scene, seed=4, n=3, first=3)]
    other = [m.to_xml_string() for m in variants(table_scene, seed=5, n=6)]
    assert first == again and first[3:] == later
    assert len(set(first)) == 6 and set(first).isdisjoint(other)  # structure differs
    assert first[2] == table_scene(structure_rng(4, 2), 2).to_xml_string()


def test_variants_are_the_same_in_this_process_and_on_one_or_two_processes() -> None:
    here = generate(table_scene, seed=9, n=10, processes=0, compile=True, keep_model=True)
    one = generate(table_scene, seed=9, n=10, processes=1, compile=True, keep_model=True)
    two = generate(table_scene, seed=9, n=10, processes=2, chunk=3, compile=True,
                   keep_model=True)
    texts = [v.xml for v in here]
    assert [v.world for v in here] == list(range(10))
    assert [v.xml for v in one] == texts == [v.xml for v in two]
    assert len(set(texts)) == 10
    for variant in two:  # what crossed the process boundary: a typed model, a MuJoCo model
        assert isinstance(variant.model, mjcf.RootElement)
        assert variant.model.to_xml_string() == variant.xml
        assert isinstance(variant.compiled, mujoco.MjModel)
        assert variant.compiled.nbody == len(variant.model.find_all("body")) + 1
        assert variant.warnings == ()


def test_only_what_is_asked_for_is_kept() -> None:
    (variant,) = generate(table_scene, seed=0, n=1, processes=0, xml=False)
    assert (variant.xml, variant.model, variant.compiled) == (None, None, None)


def test_a_failing_world_is_named_from_a_worker() -> None:
    with pytest.raises(VariantError) as raised:
        generate(failing_at_world_3, seed=0, n=6, processes=2, chunk=2, compile=True)
    message = str(raised.value)
    assert message.startswith("world 3 (seed 0): CompileError: MuJoCo could not compile")
    assert "(the element is worldbody/body[object0]/geom[geom0])" in message
    assert pickle.loads(pickle.dumps(raised.value)).args == raised.value.args


def test_arguments_are_checked() -> None:
    for kwargs in [{"processes": -1}, {"chunk": 0}, {"seed": -1}, {"n": -1}]:
        arguments: dict[str, object] = {"seed": 0, "n": 2, **kwargs}
        with pytest.raises(mjcf.InvalidValueError):
            generate(table_scene, **arguments)  # type: ignore[arg-type]


def test_ray_missing_is_a_clear_error(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "ray", None)  # as if not installed
    with pytest.raises(ImportError, match=r"pip install 'typed-mjcf\[ray\]'"):
        generate(table_scene, seed=0, n=1, ray=True)
