"""A minimal Language Server Protocol client for pyright's language server.

``pyright-langserver --stdio`` (the engine of VS Code's Pylance; it ships with the ``pyright``
package of the dev extra), driven the way an editor drives it: requests, notifications,
replies to the server's own requests (its configuration is this interpreter), in-memory
documents. Used by ``tests/typing/test_ide.py`` (what an editor shows) and
``tests/bench/editor.py`` (what it costs).
"""

from __future__ import annotations

import itertools
import json
import os
import queue
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import IO, cast

JSON = dict[str, object]


class LanguageServer:
    """``pyright-langserver --stdio`` in ``root`` (its configuration applies to documents
    under it); each request waits at most ``timeout`` seconds. The environment whose packages
    it reads is ``python``'s (this interpreter's by default)."""

    def __init__(self, root: Path, timeout: float = 60.0, python: str | None = None) -> None:
        self.timeout = timeout
        self.python = python or sys.executable
        self._process = subprocess.Popen(
            [sys.executable, "-c", "from pyright.langserver import entrypoint; entrypoint()",
             "--stdio"],
            cwd=root, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
        )
        self._ids = itertools.count(1)
        self._replies: queue.Queue[JSON] = queue.Queue()
        threading.Thread(target=self._read_loop, daemon=True).start()
        self.request("initialize", {
            "processId": os.getpid(),  # the server exits when this process does
            "rootUri": root.as_uri(),
            "workspaceFolders": [{"uri": root.as_uri(), "name": root.name}],
            "capabilities": {
                "workspace": {"configuration": True, "workspaceFolders": True},
                "textDocument": {
                    "completion": {"completionItem": {
                        "documentationFormat": ["markdown", "plaintext"]}},
                    "hover": {"contentFormat": ["markdown", "plaintext"]},
                    "signatureHelp": {"signatureInformation": {
                        "documentationFormat": ["markdown", "plaintext"],
                        "parameterInformation": {"labelOffsetSupport": True}}},
                },
            },
        })
        self.notify("initialized", {})

    @property
    def pid(self) -> int:
        """The launcher's process id (node and its workers run below it)."""
        return self._process.pid

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
            return [{"pythonPath": self.python} if item.get("section") == "python"
                    else {} for item in items]
        return None  # client/registerCapability, window/workDoneProgress/create, ...

    def notify(self, method: str, params: JSON) -> None:
        self._send({"method": method, "params": params})

    def request(self, method: str, params: JSON) -> object:
        number = next(self._ids)
        self._send({"id": number, "method": method, "params": params})
        while True:
            try:
                reply = self._replies.get(timeout=self.timeout)
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

    def open(self, path: Path, text: str, version: int = 1) -> str:
        uri = path.as_uri()
        self.notify("textDocument/didOpen", {"textDocument": {
            "uri": uri, "languageId": "python", "version": version, "text": text}})
        return uri

    def change(self, uri: str, text: str, version: int) -> None:
        """The whole text again, as a new version (what an editor sends after an edit)."""
        self.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": version},
                                               "contentChanges": [{"text": text}]})

    def close_document(self, uri: str) -> None:
        self.notify("textDocument/didClose", {"textDocument": {"uri": uri}})

    def _at(self, method: str, uri: str, line: int, character: int) -> object:
        return self.request(method, {"textDocument": {"uri": uri},
                                     "position": {"line": line, "character": character}})

    def completion(self, uri: str, line: int, character: int) -> list[JSON]:
        result = self._at("textDocument/completion", uri, line, character)
        if isinstance(result, dict):
            return cast(list[JSON], cast(JSON, result)["items"])
        return cast(list[JSON], result or [])

    def hover(self, uri: str, line: int, character: int) -> str:
        result = self._at("textDocument/hover", uri, line, character)
        if not isinstance(result, dict):
            return ""
        contents = cast(JSON, result)["contents"]
        if isinstance(contents, dict):
            return str(cast(JSON, contents)["value"])
        return str(contents)

    def signature_help(self, uri: str, line: int, character: int) -> tuple[str, str]:
        """The active signature's label and the active parameter's documentation ("" when
        there is none)."""
        result = self._at("textDocument/signatureHelp", uri, line, character)
        if not isinstance(result, dict):
            return "", ""
        help_ = cast(JSON, result)
        signatures = cast(list[JSON], help_.get("signatures") or [])
        if not signatures:
            return "", ""
        signature = signatures[cast(int, help_.get("activeSignature") or 0)]
        parameters = cast(list[JSON], signature.get("parameters") or [])
        active = cast(int | None, signature.get("activeParameter",
                                                help_.get("activeParameter")))
        if active is None or not 0 <= active < len(parameters):
            return str(signature["label"]), ""
        doc = parameters[active].get("documentation", "")
        if isinstance(doc, dict):
            doc = cast(JSON, doc)["value"]
        return str(signature["label"]), str(doc)
