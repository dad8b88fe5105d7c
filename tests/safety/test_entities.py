"""Safe by default: no entity expansion, no external entities or DTDs, no network."""

from __future__ import annotations

import json
import socket
import subprocess
import sys
import textwrap
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

import typed_mjcf as mjcf


def billion_laughs(levels: int = 10) -> str:
    entities = '<!ENTITY lol0 "lol">' + "".join(
        f'<!ENTITY lol{i} "{f"&lol{i - 1};" * 10}">' for i in range(1, levels))
    return f'<?xml version="1.0"?><!DOCTYPE mujoco [{entities}]><mujoco model="&lol{levels - 1};"/>'


def quadratic_blowup(size: int = 100_000) -> str:
    return (f'<!DOCTYPE mujoco [<!ENTITY a "{"x" * size}">]>'
            f'<mujoco><worldbody><body name="{"&a;" * size}"/></worldbody></mujoco>')


BOMBS = {
    "billion laughs": billion_laughs(),
    "billion laughs in content": billion_laughs().replace(
        'model="&lol9;"/>', "><worldbody>&lol9;</worldbody></mujoco>"),
    "quadratic blowup": quadratic_blowup(),
    "parameter entities": ('<!DOCTYPE mujoco [<!ENTITY % p "<!ENTITY q \'x\'>"> %p;]>'
                           '<mujoco model="&q;"/>'),
}


@pytest.mark.parametrize("name", sorted(BOMBS))
@pytest.mark.parametrize("encoding", ["utf-8", "utf-16", "str"])
def test_entity_bombs_are_refused_fast(name: str, encoding: str) -> None:
    text = BOMBS[name]
    data: str | bytes = text if encoding == "str" else text.encode(encoding)
    start = time.perf_counter()
    with pytest.raises(mjcf.ParseError, match=r"line 1: entity declarations"):
        mjcf.from_xml_string(data)
    assert time.perf_counter() - start < 0.5


def test_entity_bombs_use_no_memory() -> None:
    """In a fresh process, refusing every bomb (and one in an included file) raises the
    peak memory by less than a few MB (expanded, the billion laughs is 3 GB)."""
    script = textwrap.dedent("""
        import json, os, resource, sys, tempfile
        import typed_mjcf as mjcf
        bombs = json.load(sys.stdin)
        mjcf.from_xml_string("<mujoco><worldbody><body/></worldbody></mujoco>")
        before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        folder = tempfile.mkdtemp()
        with open(os.path.join(folder, "bomb.xml"), "w") as f:
            f.write(bombs[0])
        for bomb in bombs * 3:
            for data in (bomb, bomb.encode("utf-16")):
                try:
                    mjcf.from_xml_string(data)
                except mjcf.ParseError:
                    pass
                else:
                    raise SystemExit("a bomb was read")
        try:
            mjcf.from_xml_string('<mujoco><include file="bomb.xml"/></mujoco>', base_dir=folder)
        except mjcf.ParseError as error:
            assert "entity declarations" in str(error), error
        after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        print((after - before) // 1024)  # kilobytes on Linux: MB
    """)
    if sys.platform != "linux":
        pytest.skip("ru_maxrss is in kilobytes on Linux only")
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                            input=json.dumps(list(BOMBS.values())), timeout=120, check=False)
    assert result.returncode == 0, result.stderr
    assert int(result.stdout.strip()) < 8, f"peak memory grew by {result.stdout.strip()} MB"


def test_external_entities_are_not_read(tmp_path: Path) -> None:
    secret = tmp_path / "secret.txt"
    secret.write_text("TOP-SECRET")
    for xml in (
        f'<!DOCTYPE m [<!ENTITY s SYSTEM "file://{secret}">]><mujoco model="&s;"/>',
        f'<!DOCTYPE m [<!ENTITY s SYSTEM "{secret}">]><mujoco><worldbody>&s;</worldbody></mujoco>',
        f'<!DOCTYPE m [<!ENTITY % s SYSTEM "{secret}"> %s;]><mujoco/>',
    ):
        with pytest.raises(mjcf.ParseError, match="entity declarations") as info:
            mjcf.from_xml_string(xml)
        assert "TOP-SECRET" not in str(info.value)


@pytest.fixture
def listener() -> Iterator[socket.socket]:
    """A local TCP server that records whether anything connected."""
    server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    server.bind(("127.0.0.1", 0))
    server.listen(8)
    server.setblocking(False)
    yield server
    server.close()


def test_no_network_access(listener: socket.socket, tmp_path: Path) -> None:
    port = listener.getsockname()[1]
    url = f"http://127.0.0.1:{port}/model"
    # An external DTD (not loaded), XInclude (not processed; its tag is not MJCF), and an
    # <include> of a URL (a file name to MuJoCo, which does not exist).
    model = mjcf.from_xml_string(f'<!DOCTYPE mujoco SYSTEM "{url}.dtd"><mujoco model="m"/>')
    assert model.model == "m"
    with pytest.raises(mjcf.ParseError, match="not a legal child"):
        mjcf.from_xml_string(f'<mujoco xmlns:xi="http://www.w3.org/2001/XInclude">'
                             f'<xi:include href="{url}.xml"/></mujoco>')
    with pytest.raises(mjcf.ParseError, match="cannot read included file"):
        mjcf.from_xml_string(f'<mujoco><include file="{url}.xml"/></mujoco>', base_dir=tmp_path)
    with pytest.raises(mjcf.ParseError, match="entity declarations"):
        mjcf.from_xml_string(f'<!DOCTYPE m [<!ENTITY e SYSTEM "{url}.ent">]><mujoco/>')
    with pytest.raises(BlockingIOError):
        listener.accept()  # nobody connected


def test_predefined_entities_and_character_references_still_work() -> None:
    model = mjcf.from_xml_string('<mujoco model="a&amp;b&#x41;&lt;"/>')
    assert model.model == "a&bA<"
    again = mjcf.from_xml_string(model.to_xml_string())
    assert again.model == "a&bA<"
