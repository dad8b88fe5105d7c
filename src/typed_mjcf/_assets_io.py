"""The files a model uses: gathering them for MuJoCo's VFS and writing them beside the XML.

Every file attribute (a path, or an in-memory :class:`~typed_mjcf.Asset`) gets one flat,
readable name: the file's own name, or the element's name for in-memory contents, with a
numeric suffix only when two different files would collide. The XML written for the VFS or
for a folder uses those names and drops the compiler's folder attributes.
"""

from __future__ import annotations

import os
import tempfile
from dataclasses import dataclass, field

from typed_mjcf._element import Element
from typed_mjcf._root import ModelRoot
from typed_mjcf._spec import AttributeSpec
from typed_mjcf.assets import Asset
from typed_mjcf.errors import ExportError, InvalidValueError


@dataclass
class CollectedAssets:
    """Flat file names and contents of every file a model uses."""

    files: dict[str, bytes] = field(default_factory=lambda: {})
    names: dict[tuple[int, str], str] = field(default_factory=lambda: {})
    directory_attributes: frozenset[str] = frozenset()

    def name_of(self, element: Element, attribute: AttributeSpec, value: object) -> str:
        return self.names[(id(element), attribute.name)]


def compiler_folders(model: ModelRoot) -> dict[str, str]:
    """Values of the root's folder attributes (meshdir, texturedir, assetdir, strippath)."""
    folders: dict[str, str] = {}
    for child in model.get_children():
        for name, value in child._attrs.items():  # pyright: ignore[reportPrivateUsage]
            if isinstance(value, str | bool):
                folders[f"{child.tag}@{name}"] = str(value)
    return folders


def resolve_path(model: ModelRoot, attribute: AttributeSpec, file: str,
                 folders: dict[str, str]) -> str:
    """Where MuJoCo finds ``file``: absolute as given, else under the compiler's folder
    (absolute, or relative to the model's directory)."""
    if folders.get("compiler@strippath") == "True":
        file = os.path.basename(file)
    if os.path.isabs(file):
        return file
    folder = ""
    for name in attribute.directory:
        value = folders.get(f"compiler@{name}")
        if value:
            folder = value
            break
    base = model.base_dir or os.getcwd()
    return os.path.normpath(os.path.join(base, folder, file))


def _unique(name: str, contents: bytes, files: dict[str, bytes]) -> str:
    stem, extension = os.path.splitext(name)
    candidate, n = name, 1
    while candidate in files and files[candidate] != contents:
        n += 1
        candidate = f"{stem}-{n}{extension}"
    return candidate


def collect_assets(model: ModelRoot) -> CollectedAssets:
    """Read every file the model uses and give each a flat name."""
    collected = CollectedAssets()
    _collect(model, collected, ())
    return collected


def _collect(model: ModelRoot, collected: CollectedAssets, models: tuple[str, ...]) -> None:
    """Add ``model``'s files to ``collected``; ``models`` are the MJCF files being read."""
    folders = compiler_folders(model)
    directories: set[str] = set()
    for element in model.iter_elements():
        attrs = element._attrs  # pyright: ignore[reportPrivateUsage]
        if not attrs:
            continue
        for attribute in element.spec.attributes:
            if attribute.kind != "file":
                continue
            directories.update(attribute.directory)
            value = attrs.get(attribute.name)
            if value is None:
                continue
            if isinstance(value, Asset):
                stem = value.name or _element_stem(element)
                name, contents = stem + value.extension, value.contents
            else:
                assert isinstance(value, str)
                path = resolve_path(model, attribute, value, folders)
                try:
                    with open(path, "rb") as f:
                        contents = f.read()
                except OSError as error:
                    raise InvalidValueError(
                        f"{element.path}: {attribute.py_name}={value!r}: cannot read {path}: "
                        f"{error.strerror}") from None
                name = os.path.basename(path)
                if _is_model_file(name, contents):
                    contents = _model_file_contents(element, attribute, path, collected,
                                                    (*models, path))
            name = _unique(name, contents, collected.files)
            collected.files[name] = contents
            collected.names[(id(element), attribute.name)] = name
    collected.directory_attributes = collected.directory_attributes | frozenset(directories)
    from typed_mjcf._compose import attachments

    for _, attached in attachments(model):  # each resolves its files in its own folders
        _collect(attached, collected, models)


def _is_model_file(name: str, contents: bytes) -> bool:
    """Whether a file is an MJCF model (an ``<asset><model>``, say)."""
    from typed_mjcf._parse import is_model_text

    return name.lower().endswith(".xml") and is_model_text(contents)


def _model_file_contents(element: Element, attribute: AttributeSpec, path: str,
                         collected: CollectedAssets, models: tuple[str, ...]) -> bytes:
    """An MJCF file the model uses, rewritten to find its own files among ``collected``.

    MuJoCo resolves the files of such a model against its own folder and ``<compiler>``;
    in a virtual file system they get flat names like the main model's.
    """
    from typed_mjcf._parse import parse_path

    if path in models[:-1]:
        raise InvalidValueError(f"{element.path}: {attribute.py_name}: {path} uses itself "
                                f"(through {' -> '.join(models)})")
    submodel = parse_path(path)
    sub_collected = CollectedAssets(files=collected.files)
    _collect(submodel, sub_collected, models)
    return xml_with_assets(submodel, sub_collected).encode("utf-8")


def _element_stem(element: Element) -> str:
    id_attribute = element.spec.id_attribute
    name = None if id_attribute is None else element._attrs.get(id_attribute.name)  # pyright: ignore[reportPrivateUsage]
    return name if isinstance(name, str) else element.tag


def xml_with_assets(model: ModelRoot, collected: CollectedAssets, *,
                    pretty_print: bool = True) -> str:
    """The model's XML with file attributes replaced by their flat names."""
    from typed_mjcf._export import Formatter, build

    formatter = Formatter(file_namer=collected.name_of,
                          skip_attributes=collected.directory_attributes)
    from lxml import etree

    return etree.tostring(build(model, formatter), pretty_print=pretty_print, encoding="unicode")


def export_with_assets(model: ModelRoot, directory: str, model_filename: str | None = None) -> str:
    """Write the XML and its files into ``directory``; return the XML's path."""
    collected = collect_assets(model)
    xml = xml_with_assets(model, collected)
    name = model_filename or f"{model.get_attributes().get('model') or 'model'}.xml"
    if os.path.basename(name) != name:
        raise ExportError(f"model_filename must be a plain file name, got {name!r}")
    os.makedirs(directory, exist_ok=True)
    for file_name, contents in [*collected.files.items(), (name, xml.encode("utf-8"))]:
        _write_atomically(os.path.join(directory, file_name), contents)
    return os.path.join(directory, name)


def _write_atomically(path: str, contents: bytes) -> None:
    folder = os.path.dirname(path)
    fd, temporary = tempfile.mkstemp(dir=folder, prefix=".typed-mjcf-")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(contents)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise
