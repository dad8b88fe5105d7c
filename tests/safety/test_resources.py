"""Memory and time of reading untrusted text: peak memory a small multiple of the input, and
every default limit reached in time linear in the input (each case below ran for minutes, or
took gigabytes, before it was fixed; none asserts a time: the subprocess timeout only stops a
hang).

Memory is measured in a fresh interpreter (``ru_maxrss``, the peak resident size, grows
only), after the text is built, so the growth is what reading it cost.
"""

from __future__ import annotations

import random
import re
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf._core import tree as _tree
from typed_mjcf._core.codecs import _DOUBLE, _FLOAT, _INTEGER, _PIECE, ArrayCodec, Format, Rejected
from typed_mjcf.io import ParseLimits

HANG_GUARD = 120  # seconds: a stuck child fails the test instead of stalling the suite


def _run(code: str) -> str:
    done = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], capture_output=True,
                          text=True, timeout=HANG_GUARD, check=False)
    assert done.returncode == 0, done.stderr
    return done.stdout


# ------------------------------------------------------------------------------ memory

_GROWTH = """
    import resource
    import typed_mjcf as mjcf

    numbers = "0.125 -7 1e-3 " * {count}
    xml = '<mujoco><asset><mesh name="m" vertex="' + numbers + '"/></asset></mujoco>'
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    model = mjcf.from_xml_string(xml)
    {then}
    after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    print(len(xml), (after - before) * 1024)  # ru_maxrss is in KiB on Linux
"""


@pytest.mark.skipif(sys.platform != "linux", reason="ru_maxrss is in KiB on Linux only")
@pytest.mark.parametrize("then", [
    "",  # the load: the list is checked and kept as text
    "assert model.asset.mesh[0].vertex.shape == (3 * {count},)",  # then read as an array
    "assert len(model.to_xml_string(canonical=True)) > len(numbers)",  # then written anew
])
def test_a_long_number_list_loads_in_memory_a_small_multiple_of_its_text(then: str) -> None:
    count = 500_000  # 7 MB of text; it took 1.6 GB to load (~600 bytes a number)
    text_size, growth = map(int, _run(_GROWTH.format(
        count=count, then=then.format(count=count))).split())
    assert growth < 20 * text_size, f"{growth / text_size:.1f}x the text"


# ------------------------------------------------------------------------------ numbers


def _plain(number: str, lo: int, hi: int | None) -> re.Pattern[str]:
    """The check as it was before it was made possessive (its memory grew with the list)."""
    low, high = max(lo - 1, 0), "" if hi is None else str(max(hi - 1, 0))
    return re.compile(f"\\s*{number}(?:\\s+{number}){{{low},{high}}}\\s*", re.ASCII)


_WORDS = ["1", "1.5", "-2e3", ".5", "5.", "1e-12", "1E+5", "+3", "1e15", "1e123", "9" * 21,
          "9" * 201, "1.e5", "e5", "-", ".", "0x1p3", "inf", "1_0", "", "1e", "++1", "1.2.3"]


def test_the_number_list_check_accepts_exactly_what_it_did() -> None:
    rng = random.Random(21)
    for kind, dtype, number in (("real", "double", _DOUBLE), ("real", "float", _FLOAT),
                                ("int", "int", _INTEGER)):
        for lo, hi in ((0, None), (1, 1), (3, 3), (1, 3), (2, None), (4, 4)):
            codec, plain = ArrayCodec(kind, dtype, lo, hi), _plain(number, lo, hi)
            for _ in range(3000):
                words = [rng.choice(_WORDS) if rng.random() < 0.7 else
                         "".join(rng.choice("0123456789.eE+-x") for _ in range(rng.randint(1, 5)))
                         for _ in range(rng.randint(0, 6))]
                text = rng.choice(["", " ", "\t"]) + rng.choice([" ", "  ", "\n"]).join(words)
                assert (codec.pattern.fullmatch(text) is None) == (plain.fullmatch(text) is None), (
                    kind, dtype, lo, hi, text)


def test_a_list_longer_than_a_piece_converts_as_a_short_one_does() -> None:
    codec = ArrayCodec("real", "float", 0, None)
    rng = np.random.default_rng(0)
    values = rng.standard_normal(3 * _PIECE // 10)
    text = "\n".join(f"{x!r}\t" for x in values.tolist())
    assert len(text) > 2 * _PIECE
    array = codec.from_text(text)
    assert array.dtype == np.float32 and array.shape == values.shape
    whole = codec._from_parts(text.split(), text)  # in one piece  # pyright: ignore[reportPrivateUsage]
    assert np.array_equal(array, whole)
    canonical = Format(canonical=True)
    assert codec.write(array, canonical) == " ".join(
        codec.write(whole[i:i + 1000], canonical) for i in range(0, len(whole), 1000))
    # A bad word anywhere is refused as in a short list; so is one number too many.
    with pytest.raises(Rejected, match="number"):
        codec.from_text(text + " 1_0")
    with pytest.raises(Rejected, match="float32"):
        codec.from_text("1e39 " + text)
    bounded = ArrayCodec("real", "double", 0, len(values) - 1)
    with pytest.raises(Rejected, match=rf"0 to {len(values) - 1} numbers, got at least"):
        bounded.from_text(text)


# ------------------------------------------------------------------------------ time


def test_a_line_of_many_start_tags_is_located_in_linear_time() -> None:
    """Each message asks where its element's start tag begins; the answer for a line is found
    once (it was a scan of the line per "<", per question: quadratic)."""
    sites = "<site/>" * 200_000
    with pytest.raises(mjcf.ParseError, match=r"^line 1: <bad> is not a legal child"):
        mjcf.from_xml_string(f"<mujoco><worldbody>{sites}<bad/></worldbody></mujoco>")
    comments = "<!-- <site/> -->" * 100_000
    with pytest.raises(mjcf.ParseError, match=r"^line 2: <bad> is not a legal child"):
        mjcf.from_xml_string(f"<mujoco><worldbody>{comments}\n{sites}<bad/></worldbody></mujoco>")


def test_many_includes_on_one_line(tmp_path: Path) -> None:
    count = 10_000  # 1,000 took 6 s, 10,000 did not finish
    for i in range(count):
        (tmp_path / f"p{i}.xml").write_text("<mujoco/>")
    includes = "".join(f'<include file="p{i}.xml"/>' for i in range(count))
    (tmp_path / "main.xml").write_text(f"<mujoco>{includes}</mujoco>")
    (tmp_path / "bad.xml").write_text(f"<mujoco>{includes}<include file='none.xml'/></mujoco>")
    _run(f"""
        import typed_mjcf as mjcf
        assert mjcf.from_path({str(tmp_path / "main.xml")!r}) is not None
        try:
            mjcf.from_path({str(tmp_path / "bad.xml")!r})
        except mjcf.ParseError as error:
            assert "bad.xml:1: cannot read included file 'none.xml'" in str(error), error
        else:
            raise AssertionError("a missing include was read")
    """)


def test_the_element_limit_on_one_line() -> None:
    """One element over the default limit, all on one line (7.6 MB): refused, at its line
    (it did not answer in 120 s). test_limits.py checks that the limit is exact."""
    _run("""
        import typed_mjcf as mjcf
        limit = mjcf.ParseLimits().max_elements
        sites = "<site/>" * (limit - 1)  # with <mujoco> and <worldbody>: one over the limit
        try:
            mjcf.from_xml_string(f"<mujoco><worldbody>{sites}</worldbody></mujoco>")
        except mjcf.ParseError as error:
            assert str(error).startswith("line 1: the model has more than 1000000 elements"), error
        else:
            raise AssertionError("the limit was not applied")
    """)


def test_the_byte_limit_refuses_before_reading_further(tmp_path: Path) -> None:
    limit = ParseLimits().max_bytes
    big = tmp_path / "big.xml"
    with big.open("wb") as file:  # a valid model one byte over the limit
        file.write(b"<mujoco>")
        file.write(b" " * (limit - len(b"<mujoco></mujoco>") + 1))
        file.write(b"</mujoco>")
    with pytest.raises(mjcf.ParseError, match=r"ParseLimits\.max_bytes"):
        mjcf.from_path(big)
    with pytest.raises(mjcf.ParseError, match=r"ParseLimits\.max_bytes"):
        mjcf.from_xml_string(big.read_bytes())
    with big.open("r+b") as file:  # at the limit: read
        file.truncate(limit)
        file.seek(limit - len(b"</mujoco>"))
        file.write(b"</mujoco>")
    assert mjcf.from_path(big).to_xml_string() == "<mujoco/>\n"


def test_the_depth_limit_and_beyond() -> None:
    limit = ParseLimits().max_depth
    for depth in (limit, limit + 1, 2049, 100_000):
        xml = ("<mujoco><worldbody>" + "<body>" * (depth - 2) + "</body>" * (depth - 2)
               + "</worldbody></mujoco>")
        if depth <= limit:
            assert mjcf.from_xml_string(xml)
        else:
            with pytest.raises(mjcf.ParseError, match=r"nested"):
                mjcf.from_xml_string(xml)


@pytest.mark.parametrize(("tag", "expected", "warnings"), [
    ("site", "line 1: worldbody/site[0]: <site> has no attribute 'pos0' (did you mean 'pos'?)",
     0),
    # frame ignores attributes it does not know: each is a warning, then pos is refused
    ("frame", "line 1: worldbody/frame[0]: invalid pos='x' on <frame>", 100_000),
])
def test_an_element_with_100000_attributes(tag: str, expected: str, warnings: int) -> None:
    """lxml reads attributes by name, in time quadratic in their number (100,000: minutes)."""
    _run(f"""
        import warnings
        import typed_mjcf as mjcf
        attributes = " ".join(f'pos{{i}}="1"' for i in range(100_000))
        xml = f'<mujoco><worldbody><{tag} {{attributes}} pos="x"/></worldbody></mujoco>'
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                mjcf.from_xml_string(xml)
            except mjcf.ParseError as error:
                assert str(error).startswith({expected!r}), error
            else:
                raise AssertionError("accepted")
        assert len(caught) == {warnings}, len(caught)
    """)


def test_validate_names_many_unnamed_findings_in_linear_time() -> None:
    """A finding names its element by path, and an unnamed element's path counts its siblings:
    counted once per parent (100,000 sensors with a reference to nothing took minutes)."""
    out = _run("""
        import typed_mjcf as mjcf
        sensors = "".join(f'<jointpos joint="missing{i}"/>' for i in range(100_000))
        model = mjcf.from_xml_string(f"<mujoco><sensor>{sensors}</sensor></mujoco>")
        findings = model.validate()
        print(len(findings), findings[-1].path)
    """)
    assert out.split() == ["100000", "sensor/jointpos[99999]"]


def test_paths_of_many_elements_are_their_paths() -> None:
    model = mjcf.RootElement()
    body = model.worldbody.add_body(name="b")
    elements = [body.add_geom(), body.add_site(), body.add_geom(name="g"), body.add_geom(),
                model.worldbody.add_geom(), body, model.compiler]
    assert _tree.paths(elements) == [element.path for element in elements]
    assert _tree.paths(elements)[3] == "worldbody/body[b]/geom[2]"
