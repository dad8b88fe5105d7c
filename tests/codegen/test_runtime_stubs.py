"""The runtime's stubs (``codegen/runtime_stubs.py``): in sync with ``src/``, and what each
rule of the generator keeps and drops, on small modules.

Whether they agree with the implementation (mypy's stubtest) and whether user code checks the
same against them is ``tests/typing/test_runtime_stubs.py``.
"""

from __future__ import annotations

import textwrap
from functools import cache
from pathlib import Path

import pytest

from codegen import runtime_stubs


@cache
def fresh() -> dict[str, str]:
    return runtime_stubs.render()  # about 2 s of CPU: once per process


def test_generated_stubs_equal_a_fresh_generation() -> None:
    stale = runtime_stubs.stale(fresh())
    assert not stale, (f"generated/runtime-pyi/ is out of date with src/: {', '.join(stale)}; "
                       "run `python -m codegen render`")


def test_every_runtime_module_has_a_stub() -> None:
    files = fresh()
    modules = {p.relative_to(runtime_stubs.SOURCE_DIR).with_suffix(".pyi").as_posix()
               for p in runtime_stubs.SOURCE_DIR.rglob("*.py")
               if p.relative_to(runtime_stubs.SOURCE_DIR).parts[0] not in runtime_stubs.SKIPPED}
    assert set(files) == modules
    assert {"_core/tree.pyi", "_base.pyi", "types.pyi", "__init__.pyi", "io.pyi"} <= modules


def stubs(tmp_path: Path, modules: dict[str, str], generated: str = "") -> dict[str, str]:
    """The stubs of a package made of ``modules`` (their bodies after the header line)."""
    source = tmp_path / "src"
    source.mkdir()
    for name, text in modules.items():
        (source / name).write_text(textwrap.dedent(text), encoding="utf-8")
    made = tmp_path / "generated"
    made.mkdir()
    (made / "elements.pyi").write_text(textwrap.dedent(generated), encoding="utf-8")
    files = runtime_stubs.render(source, made)
    return {name: text.split("\n", 1)[1] for name, text in files.items()}


def test_bodies_become_ellipses_and_docstrings_stay(tmp_path: Path) -> None:
    (stub,) = stubs(tmp_path, {"m.py": '''\
        """The module."""
        from __future__ import annotations

        import os

        def f(x: int = 3,  # a comment in the signature
              *, y: str | None = None) -> int:
            """Its doc."""
            return x + len(os.sep)

        def g() -> None:
            print("run time")
        ''',
    }).values()
    assert stub == textwrap.dedent('''\
        """The module."""
        from __future__ import annotations

        def f(x: int = 3,  # a comment in the signature
              *, y: str | None = None) -> int:
            """Its doc."""
            ...

        def g() -> None: ...
        ''')


def test_aliases_are_kept_as_written_and_type_checking_is_read_as_checkers_do(
        tmp_path: Path) -> None:
    (stub,) = stubs(tmp_path, {"m.py": '''\
        from typing import TYPE_CHECKING, TypeAlias

        import numpy as np

        if TYPE_CHECKING:
            from numpy.typing import NDArray

            Image = NDArray[np.uint8]
        else:
            Image = object

        Floats: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.float64]]
        """What a double array reads as."""
        TABLE: dict[str, int] = {"a": 1, "b": 2}
        LIMIT: int = 5

        def show(image: Image) -> Floats: ...

        class C:
            if not TYPE_CHECKING:
                def __getattr__(self, name: str) -> object: ...
        ''',
    }).values()
    assert "Image = NDArray[np.uint8]" in stub and "Image = object" not in stub
    assert "from numpy.typing import NDArray" in stub
    assert ('Floats: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.float64]]\n'
            '"""What a double array reads as."""') in stub
    assert "TABLE: dict[str, int] = ...\n" in stub and "LIMIT: int = 5\n" in stub
    assert "__getattr__" not in stub and "class C:\n    ...\n" in stub
    assert stub.count("TYPE_CHECKING") == 1  # its import, kept whole for TypeAlias


def test_unused_private_names_and_imports_go(tmp_path: Path) -> None:
    files = stubs(tmp_path, {
        "a.py": '''\
            import json
            import re
            from collections.abc import Mapping

            class _Hidden: ...
            class _Named: ...
            class _Imported: ...
            _PATTERN = re.compile("x")

            def public(x: _Named) -> Mapping[str, int]:
                return json.loads(x)

            def _helper() -> None: ...
            ''',
        "b.py": '''\
            from m.a import _Imported

            def uses(x: _Imported) -> None: ...
            ''',
    })
    a = files["a.pyi"]
    assert "class _Named" in a and "class _Imported" in a  # named by a kept signature
    assert "_Hidden" not in a and "_helper" not in a and "_PATTERN" not in a
    assert "import json" not in a and "import re" not in a  # only bodies used them
    assert "from collections.abc import Mapping" in a


def test_private_fields_stay(tmp_path: Path) -> None:
    (stub,) = stubs(tmp_path, {"m.py": '''\
        from dataclasses import dataclass, field

        @dataclass
        class Record:
            name: str
            _seen: int = 0
            _cache: dict[str, int] = field(default_factory=lambda: {}, init=False)

            def _unused(self) -> None: ...
        ''',
    }).values()
    assert "    _seen: int = 0\n" in stub  # a parameter of __init__
    assert "_cache: dict[str, int] = field(default_factory=lambda: {}, init=False)" in stub
    assert "_unused" not in stub


def test_names_the_generated_modules_import_stay(tmp_path: Path) -> None:
    files = stubs(tmp_path, {"a.py": "class _Base: ...\nclass _Other: ...\n"},
                  generated="from typed_mjcf.a import _Base as _B\n")
    assert "class _Base" in files["a.pyi"] and "_Other" not in files["a.pyi"]


def test_reexports_stay(tmp_path: Path) -> None:
    (stub,) = stubs(tmp_path, {"__init__.py": '''\
        from m.a import Thing as Thing
        from m.b import *
        from m.c import Listed, Unlisted

        __all__ = ["Listed"]
        ''',
    }).values()
    assert "from m.a import Thing as Thing" in stub and "from m.b import *" in stub
    assert "from m.c import Listed, Unlisted" in stub  # kept whole for Listed


def test_overloads_lose_their_implementation_not_its_docstring(tmp_path: Path) -> None:
    (stub,) = stubs(tmp_path, {"m.py": '''\
        from typing import overload

        class C:
            @overload
            def get(self, x: int) -> int: ...
            @overload
            def get(self, x: str) -> str:
                """Its own."""
            def get(self, x: int | str) -> int | str:
                """What get does."""
                return x
        ''',
    }).values()
    assert stub.count("def get") == 2 and "int | str" not in stub
    assert '    def get(self, x: int) -> int:\n        """What get does."""\n' in stub
    assert '"""Its own."""' in stub


def test_a_method_that_makes_attributes_keeps_its_body(tmp_path: Path) -> None:
    (stub,) = stubs(tmp_path, {"m.py": '''\
        import re

        class Codec:
            __slots__ = ("pattern", "declared", "_private")
            declared: int

            def __init__(self, text: str) -> None:
                self.pattern = re.compile(text)  # typed from the value, as in the module
                self.declared = 1
                self._private = 2

            def other(self) -> None:
                self.declared = 3
        ''',
    }).values()
    assert "        self.pattern = re.compile(text)" in stub and "import re" in stub
    assert "    def other(self) -> None: ...\n" in stub
    assert "__slots__" not in stub


@pytest.mark.parametrize("statement", [
    "for x in range(3):\n    pass\n",
    "if VERSION > 2:\n    X = 1\n",
    "x.y = 1\n",
    "try:\n    import foo\nexcept ImportError:\n    foo = None\n",
])
def test_a_statement_the_generator_does_not_know_is_an_error(tmp_path: Path,
                                                               statement: str) -> None:
    with pytest.raises(runtime_stubs.StubError, match=r"src/typed_mjcf/m\.py:\d+: "):
        stubs(tmp_path, {"m.py": "VERSION = 3\n" + statement})


def test_write_makes_the_folder_hold_exactly_the_files(tmp_path: Path) -> None:
    folder = tmp_path / "out"
    assert runtime_stubs.write({"a.pyi": "x: int\n", "sub/b.pyi": "y: int\n"}, folder) == [
        "a.pyi", "sub/b.pyi"]
    assert runtime_stubs.write({"a.pyi": "x: int\n", "sub/b.pyi": "y: int\n"}, folder) == []
    assert runtime_stubs.write({"a.pyi": "x: str\n"}, folder) == ["a.pyi", "sub/b.pyi"]
    assert sorted(p.name for p in folder.rglob("*.pyi")) == ["a.pyi"]
