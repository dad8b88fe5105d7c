"""What an element read from a file costs in memory: repeated values share one string, and
the source map keeps no dict entry or int per element (18 MB of ``<geom>``: 392 -> 304 bytes
of Python objects per element; ``python -m tests.bench.memory 20`` prints the peak)."""

from __future__ import annotations

import gc
import tracemalloc

import typed_mjcf as mjcf
from typed_mjcf._core import tree as _tree

ELEMENTS = 20_000


def test_repeated_values_read_from_a_file_share_one_string() -> None:
    m = mjcf.from_xml_string(
        '<mujoco><worldbody><body><joint type="hinge" axis="0 0 1"/><geom size="0.1"/>'
        '</body><body><joint type="hinge" axis="0 0 1"/><geom size="0.1"/></body>'
        '</worldbody></mujoco>')
    first, second = m.find_all("body")
    for tag, name in (("joint", "type"), ("joint", "axis"), ("geom", "size")):
        a, b = (_tree.values(body.find_all(tag)[0])[name] for body in (first, second))
        assert a == b and a is b, (tag, name)


def test_element_dense_text_keeps_few_bytes_of_python_objects_per_element() -> None:
    geoms = '<geom size="0.1"/>' * ELEMENTS
    xml = f"<mujoco><worldbody><body>{geoms}</body></worldbody></mujoco>"
    gc.collect()
    tracemalloc.start()
    try:
        model = mjcf.from_xml_string(xml)
        gc.collect()
        kept, _ = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert len(model.find_all("geom")) == ELEMENTS
    assert kept / ELEMENTS <= 320, kept / ELEMENTS  # 392 before (Python 3.11)


def test_the_source_map_still_finds_each_element_and_its_line() -> None:
    m = mjcf.from_xml_string("<mujoco>\n<worldbody>\n" + '<geom size="0.1"/>\n' * 300
                             + "</worldbody>\n</mujoco>")
    sources = _tree.source_map(m)
    assert sources is not None
    geoms = m.find_all("geom")
    assert [sources.lines[g][1] for g in geoms] == list(range(3, 303))
    assert list(sources.lines)[2:] == geoms and len(sources.lines) == 302
    extra = m.worldbody.add_geom(size=(0.2,))
    assert sources.get(extra) is None
