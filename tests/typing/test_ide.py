"""What an editor shows: completion and hover from pyright's language server.

Drives ``pyright-langserver --stdio`` (the engine of VS Code's Pylance; it ships with the
``pyright`` package of the dev extra) over the Language Server Protocol, with an in-memory
document, the way an editor does:

- completion after ``<element>.add_`` lists exactly the legal children of that element;
- completion of keyword arguments inside ``add_geom(`` lists the attributes of ``<geom>``;
- hover on a property (``joint.type``) shows its type and its docstring: the MJCF type,
  the default, the allowed values and the link to MuJoCo's XML reference.

One server per module; each request waits at most ``TIMEOUT`` seconds.
"""

from __future__ import annotations

import itertools
import json
import queue
import subprocess
import sys
import threading
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import IO, cast

import pytest

import typed_mjcf as mjcf
from typed_mjcf import Element

ROOT = Path(__file__).resolve().parents[2]
TIMEOUT = 60.0
JSON = dict[str, object]


class LanguageServer:
    """A minimal LSP client: requests, notifications, and replies to the server's requests."""

    def __init__(self, root: Path) -> None:
        self._process = subprocess.Popen(
            [sys.executable, "-c", "from pyright.langserver import entrypoint; entrypoint()",
             "--stdio"],
            cwd=root, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
        )
        self._ids = itertools.count(1)
        self._replies: queue.Queue[JSON] = queue.Queue()
        self._reader = threading.Thread(target=self._read_loop, daemon=True)
        self._reader.start()
        self.request("initialize", {
            "processId": None,
            "rootUri": root.as_uri(),
            "workspaceFolders": [{"uri": root.as_uri(), "name": root.name}],
            "capabilities": {
                "workspace": {"configuration": True, "workspaceFolders": True},
                "textDocument": {
                    "completion": {"completionItem": {
                        "documentationFormat": ["markdown", "plaintext"]}},
                    "hover": {"contentFormat": ["markdown", "plaintext"]},
                },
            },
        })
        self.notify("initialized", {})

    # ------------------------------------------------------------------ transport

    def _send(self, message: JSON) -> None:
        body = json.dumps({"jsonrpc": "2.0", **message}).encode("utf-8")
        stdin = cast(IO[bytes], self._process.stdin)
        stdin.write(f"Content-Length: {len(body)}\r\n\r\n".encode("ascii") + body)
        stdin.flush()

    def _messages(self) -> Iterator[JSON]:
        stdout = cast(IO[bytes], self._process.stdout)
        while True:
            length = 0
            while True:
                header = stdout.readline()
                if not header:
                    return
                if header in (b"\r\n", b"\n"):
                    break
                name, _, value = header.decode("ascii").partition(":")
                if name.strip().lower() == "content-length":
                    length = int(value)
            yield cast(JSON, json.loads(stdout.read(length)))

    def _read_loop(self) -> None:
        for message in self._messages():
            if "method" in message and "id" in message:  # a request from the server
                self._send({"id": message["id"], "result": self._answer(message)})
            elif "id" in message:  # a reply to one of ours
                self._replies.put(message)

    def _answer(self, request: JSON) -> object:
        if request["method"] == "workspace/configuration":
            params = cast(JSON, request["params"])
            items = cast(list[JSON], params["items"])
            return [{"pythonPath": sys.executable} if item.get("section") == "python"
                    else {} for item in items]
        return None  # client/registerCapability, window/workDoneProgress/create, ...

    def notify(self, method: str, params: JSON) -> None:
        self._send({"method": method, "params": params})

    def request(self, method: str, params: JSON) -> object:
        number = next(self._ids)
        self._send({"id": number, "method": method, "params": params})
        while True:
            try:
                reply = self._replies.get(timeout=TIMEOUT)
            except queue.Empty:
                raise TimeoutError(f"pyright-langserver did not answer {method}") from None
            if reply.get("id") == number:
                if "error" in reply:
                    raise RuntimeError(f"{method} failed: {reply['error']}")
                return reply.get("result")

    def close(self) -> None:
        try:
            self.request("shutdown", {})
            self.notify("exit", {})
            self._process.wait(timeout=10)
        except (TimeoutError, OSError, subprocess.TimeoutExpired):
            self._process.kill()
            self._process.wait()

    # ------------------------------------------------------------------ documents

    def open(self, path: Path, text: str) -> str:
        uri = path.as_uri()
        self.notify("textDocument/didOpen", {"textDocument": {
            "uri": uri, "languageId": "python", "version": 1, "text": text}})
        return uri

    def completion(self, uri: str, line: int, character: int) -> list[JSON]:
        result = self.request("textDocument/completion", {
            "textDocument": {"uri": uri}, "position": {"line": line, "character": character}})
        if isinstance(result, dict):
            return cast(list[JSON], cast(JSON, result)["items"])
        return cast(list[JSON], result or [])

    def hover(self, uri: str, line: int, character: int) -> str:
        result = self.request("textDocument/hover", {
            "textDocument": {"uri": uri}, "position": {"line": line, "character": character}})
        if not isinstance(result, dict):
            return ""
        contents = cast(JSON, result)["contents"]
        if isinstance(contents, dict):
            return str(cast(JSON, contents)["value"])
        return str(contents)


@pytest.fixture(scope="module")
def server() -> Iterator[LanguageServer]:
    client = LanguageServer(ROOT)
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
