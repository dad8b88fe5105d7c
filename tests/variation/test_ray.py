"""Structural variants on a local Ray cluster started here are those built in this process
and on local processes. Ray is an optional extra: `nox -s ray` installs it and runs this
module (slow: starting Ray takes seconds)."""

from __future__ import annotations

import importlib.util
from collections.abc import Iterator

import pytest

from tests.variation.builders import failing_at_world_3, table_scene
from typed_mjcf.variation import VariantError, generate

pytestmark = pytest.mark.skipif(importlib.util.find_spec("ray") is None,
                                reason="Ray is not installed here (the `ray` extra): "
                                       "`nox -s ray` runs these tests")


@pytest.fixture(scope="module")
def cluster() -> Iterator[None]:
    import ray  # (seconds to import: only where the tests run)

    # (workers find the build functions, tests.variation.builders, on the driver's sys.path)
    ray.init(num_cpus=1, include_dashboard=False, log_to_driver=False)
    try:
        yield
    finally:
        ray.shutdown()


def test_variants_on_ray_are_those_of_local_processes(cluster: None) -> None:
    local = generate(table_scene, seed=21, n=8, processes=2, compile=True)
    on_ray = generate(table_scene, seed=21, n=8, ray=True, chunk=3, compile=True,
                      keep_model=True)
    assert [v.xml for v in on_ray] == [v.xml for v in local]
    assert len({v.xml for v in on_ray}) == 8
    for variant in on_ray:
        assert variant.model is not None and variant.model.to_xml_string() == variant.xml
        assert variant.compiled is not None and variant.compiled.nbody > 1


def test_a_failing_world_is_named_from_ray(cluster: None) -> None:
    with pytest.raises(VariantError, match=r"world 3 \(seed 0\): CompileError"):
        generate(failing_at_world_3, seed=0, n=5, ray=True, chunk=2, compile=True)
