# Generated from src/typed_mjcf/_text/files.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The files a model uses: where they are, and a unique name for each.

Every file attribute (a path, or an in-memory :class:`~typed_mjcf.Asset`) gets one readable
name: the file's own name as its source names it (MuJoCo names an unnamed mesh after it), or
the element's name for in-memory contents, with a numeric suffix only when two in-memory
contents would collide. Names collide as MuJoCo's in-memory loader from a dict sees them: it
finds a file by its base name alone and ignores case (``MjModel.from_xml_string(xml,
assets)`` refuses two keys ``a/cube.stl`` and ``b/Cube.stl``; measured with MuJoCo 4.0.0).
Two files with one base name and the same contents (a mesh copied into two folders) share
one name; with other contents, each keeps its folders (:func:`_kept_apart`), which
``MjSpec``'s assets hold apart (:mod:`typed_mjcf._sim.compile`). In-memory contents get names
safe to write into a folder (see :func:`safe_file_name`); a file's own name is checked where
a folder is written (:mod:`typed_mjcf._model.assets_io`).

An MJCF file the model uses (an ``<asset><model file=...>``) is itself rewritten to find its
own files under their flat names: :func:`collect_files` takes the function that does it.
"""
from __future__ import annotations
from collections.abc import Callable
from dataclasses import dataclass, field
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
FileElements = list[tuple[Element, tuple[AttributeSpec, ...]]]

@dataclass
class CollectedFiles:
    """Flat file names and contents of every file a model uses."""
    files: dict[str, bytes] = field(default_factory=lambda: {})
    names: dict[tuple[int, str], str] = field(default_factory=lambda: {})
    folded: dict[str, str] = field(default_factory=lambda: {})
    keys: dict[str, object] = field(default_factory=lambda: {})
    uses: list[tuple[ModelBase, Element, AttributeSpec, object, str, str]] = field(
        default_factory=lambda: [])
    directory_attributes: frozenset[str] = ...
    readers: dict[str, Callable[[], bytes]] = field(default_factory=lambda: {})
    digests: dict[object, str | None] = field(default_factory=lambda: {})
    apart: dict[str, str] = field(default_factory=lambda: {})
    apart_found: bool = False
    file_elements: dict[int, tuple[ModelBase, FileElements]] = field(default_factory=lambda: {})
    def digest(self, key: object, read: Callable[[], bytes]) -> str | None:
        """The SHA-256 of the file ``key`` (read once); None when it cannot be read."""
        ...
    def same_contents(self, name: str, key: object, read: Callable[[], bytes]) -> bool:
        """Whether the file named ``name`` holds the same bytes as the file ``key``."""
        ...
    bytes_read: int = 0
    def name_of(self, element: Element, attribute: AttributeSpec) -> str:
        """The flat name of the file ``element``'s ``attribute`` holds."""
        ...
ModelFileWriter = Callable[[ModelBase, str, bytes, CollectedFiles, tuple[str, ...]],
                           bytes | None]

def compiler_folders(model: ModelBase) -> dict[str, str]:
    """Values of the root's folder attributes (meshdir, texturedir, assetdir, strippath),
    as ``"compiler@meshdir"`` -> text."""
    ...

def resolve_path(model: ModelBase, attribute: AttributeSpec, file: str,
                 folders: dict[str, str]) -> str:
    """Where MuJoCo finds ``file``: absolute as given, else under the compiler's folder
    (absolute, or relative to the model's directory)."""
    ...

def copied_files(original: Element, source: ModelBase,
                 target: ModelBase) -> dict[tuple[int, str], bytes]:
    """The contents of the files that a copy of ``original`` (an element of ``source``, or
    ``source`` itself) into ``target`` takes along (``include_copy``, ``paste``), by (id of
    the element, attribute), read as ``source`` may read them; nothing is copied yet.

    A copy keeps its original's confinement: from a model that may read only some folders,
    every file the copy names is read now, under that model's rules (refused, or missing:
    the error ``get_assets()`` would give), and a ``<model>`` asset, whose own files would be
    read as ``target`` may, is refused. From a model that reads anywhere, a relative file
    that can be read is taken along and any other stays as it was (an error, if any, comes
    when the model is written)."""
    ...

def rebase_files(copy: Element, original: Element, files: dict[tuple[int, str], bytes],
                 target: ModelBase) -> None:
    """A copy of ``original`` (now in ``target``) keeps naming the files it named (``files``:
    see :func:`copied_files`). As dm_control's copy holds the file itself, ``target`` is
    given the file's contents in memory under the name the copy keeps; where it holds other
    contents by that name, under that name with a ``-2`` (``-3``...) suffix, which the copy
    then names."""
    ...

def absolute_file(model: ModelBase, attribute: AttributeSpec, file: str) -> str:
    """An attached model's file, as a path that does not depend on the parent's folders."""
    ...

def safe_file_name(stem: str, extension: str = "") -> str:
    """``stem + extension`` as a plain file name that stays in the folder it is written to.

    Path separators, control characters and the characters Windows refuses become ``_``;
    leading dots and spaces go (no ``..``, no hidden files), and so do trailing ones of the
    extension; Windows device names (``con``, ``nul``, ...) get a ``_`` prefix; long stems
    are shortened. Ordinary names are unchanged.
    """
    ...

def is_plain_file_name(name: str) -> bool:
    """Whether ``name`` names a file directly inside a folder (what :func:`safe_file_name`
    gives)."""
    ...

def split_name(name: str) -> tuple[str, str]:
    """A file name's stem and extension (``".stl"`` is an extension, not a hidden stem)."""
    ...

def unique_name(name: str, key: object, collected: CollectedFiles,
                read: Callable[[], bytes] | None = None) -> str:
    """``name``, or ``name`` with a numeric suffix when another file (``key`` tells files
    apart: a path, or in-memory contents) has it already, or a name differing in case only
    (MuJoCo's in-memory loader and case-insensitive file systems would mix them up). With
    ``read`` (the file's contents, read only when its name is taken), a file with the same
    contents as the one that has the name shares it."""
    ...

def is_skin_file(element: Element, attribute: AttributeSpec) -> bool:
    """Whether the attribute holds a binary skin file (whose bones name bodies)."""
    ...

def name_files(model: ModelBase, collected: CollectedFiles | None = None,
               prefix: str = "") -> CollectedFiles:
    """A flat, unique name for every file the model (and the models attached to it) uses,
    without reading any: files are told apart by their path, in-memory ones by contents
    (and an attached model's skin files by its scope too: their bones are renamed)."""
    ...

def collect_files(model: ModelBase, model_file: ModelFileWriter,
                  collected: CollectedFiles | None = None,
                  models: tuple[str, ...] = ()) -> CollectedFiles:
    """Name (see :func:`name_files`) and read every file the model uses; ``models`` are
    the MJCF files being read (to refuse one that uses itself)."""
    ...

def is_model_asset(element: Element, attribute: AttributeSpec) -> bool:
    """Whether the attribute holds a model MuJoCo reads (an ``<asset><model file>``)."""
    ...

def file_contents(element: Element, attribute: AttributeSpec, value: str, model: ModelBase,
              folders: dict[str, str], collected: CollectedFiles) -> bytes:
    """A file's contents, read as :func:`collect_files` reads it."""
    ...

def file_stem(file: str) -> str:
    """A file's name without folders and extension (what MuJoCo names an unnamed mesh)."""
    ...

def element_file_stem(element: Element, attribute: str) -> str | None:
    """The name MuJoCo gives an unnamed element that reads a file: the file's stem (an
    in-memory asset: the stem the asset writer gives it); None without a file."""
    ...

def is_model_file_name(name: str) -> bool: ...

def element_stem(element: Element) -> str:
    """The stem of an in-memory file's name: the element's name, else its tag."""
    ...
