"""The files a model uses: gathering them for MuJoCo's VFS and writing them beside the XML.

Every file attribute (a path, or an in-memory :class:`~typed_mjcf.Asset`) gets one flat,
readable name: the file's own name, or the element's name for in-memory contents, with a
numeric suffix only when two different files would collide (also when the names differ only
in case, as they would collide on a case-insensitive file system). Names are made safe to
write into a folder: no path separators, no leading dots, no characters or device names
Windows refuses (see :func:`safe_file_name`). The XML written for the VFS or for a folder
uses those names and drops the compiler's folder attributes.

:func:`export_with_assets` writes only into its folder, each file atomically, and refuses to
replace a different file of the same name unless asked to.
"""

from __future__ import annotations

import errno
import os
import re
import stat
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
    folded: dict[str, str] = field(default_factory=lambda: {})  # casefolded name -> name
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


_UNSAFE = re.compile(r'[\x00-\x1f\x7f/\\:*?"<>|]')  # separators, controls, Windows' reserved
_DEVICES = frozenset({"con", "prn", "aux", "nul", *(f"com{i}" for i in range(10)),
                      *(f"lpt{i}" for i in range(10))})
_MAX_NAME_BYTES = 200  # file systems allow 255; room for a "-n" suffix and temporary names


def safe_file_name(stem: str, extension: str = "") -> str:
    """``stem + extension`` as a plain file name that stays in the folder it is written to.

    Path separators, control characters and the characters Windows refuses become ``_``;
    leading dots and spaces go (no ``..``, no hidden files), and so do trailing ones of the
    extension; Windows device names (``con``, ``nul``, ...) get a ``_`` prefix; long stems
    are shortened. Ordinary names are unchanged.
    """
    stem = _UNSAFE.sub("_", stem).lstrip(". ").rstrip(" ")
    extension = _UNSAFE.sub("_", extension).strip(". ")
    extension = "." + extension if extension else ""
    if not extension:
        stem = stem.rstrip(". ")  # Windows drops trailing dots and spaces
    if not stem:
        stem = "file"
    if stem.split(".")[0].lower() in _DEVICES:
        stem = "_" + stem
    room = _MAX_NAME_BYTES - len(extension.encode("utf-8"))
    if len(stem.encode("utf-8")) > room:
        stem = stem.encode("utf-8")[:max(room, 1)].decode("utf-8", "ignore").rstrip(". ") or "file"
    return stem + extension


def is_plain_file_name(name: str) -> bool:
    """Whether ``name`` names a file directly inside a folder (what :func:`safe_file_name`
    gives)."""
    return bool(name) and safe_file_name(*_split(name)) == name


def _split(name: str) -> tuple[str, str]:
    """A file name's stem and extension (``".stl"`` is an extension, not a hidden stem)."""
    dot = name.rfind(".")
    if dot <= 0 or dot == len(name) - 1:
        return name, ""
    return name[:dot], name[dot:]


def _unique(name: str, contents: bytes, collected: CollectedAssets) -> str:
    """``name``, or ``name`` with a numeric suffix when a different file (of that name, or of
    a name differing in case only) is taken already."""
    files, folded = collected.files, collected.folded
    stem, extension = _split(name)
    candidate, n = name, 1
    while True:
        taken = folded.get(candidate.casefold())
        if taken is None or (taken == candidate and files.get(candidate) == contents):
            break
        n += 1
        candidate = f"{stem}-{n}{extension}"
    folded[candidate.casefold()] = candidate
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
                name, contents = safe_file_name(stem, value.extension), value.contents
            else:
                assert isinstance(value, str)
                path = resolve_path(model, attribute, value, folders)
                try:
                    if not stat.S_ISREG(os.stat(path).st_mode):  # a FIFO or /dev/zero: no end
                        raise OSError(errno.EINVAL, "not a regular file")
                    with open(path, "rb") as f:
                        contents = f.read()
                except OSError as error:
                    raise InvalidValueError(
                        f"{element.path}: {attribute.py_name}={value!r}: cannot read {path}: "
                        f"{error.strerror}") from None
                name = safe_file_name(*_split(os.path.basename(path)))
                if _is_model_file(name, contents):
                    contents = _model_file_contents(element, attribute, path, collected,
                                                    (*models, path))
            name = _unique(name, contents, collected)
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
    sub_collected = CollectedAssets(files=collected.files, folded=collected.folded)
    _collect(submodel, sub_collected, models)
    return xml_with_assets(submodel, sub_collected).encode("utf-8")


def _element_stem(element: Element) -> str:
    id_attribute = element.spec.id_attribute
    name = None if id_attribute is None else element._attrs.get(id_attribute.name)  # pyright: ignore[reportPrivateUsage]
    return name if isinstance(name, str) else element.tag


def xml_with_assets(model: ModelRoot, collected: CollectedAssets, *,
                    pretty_print: bool = True) -> str:
    """The model's XML with file attributes replaced by their flat names."""
    from typed_mjcf._export import Formatter, write_text

    formatter = Formatter(file_namer=collected.name_of,
                          skip_attributes=collected.directory_attributes)
    return write_text(model, formatter, pretty_print)


def export_with_assets(model: ModelRoot, directory: str, model_filename: str | None = None,
                       *, overwrite: bool = False) -> str:
    """Write the XML and its files into ``directory``; return the XML's path.

    Only plain file names inside ``directory`` are written (the collected names are safe by
    construction; ``model_filename`` must be plain). Every file is checked before any is
    written: one already there with other contents (or that is not a regular file) is an
    :class:`ExportError` unless ``overwrite``; identical files are left untouched. Each file
    is written to a temporary file in ``directory`` and renamed over its name, so a reader
    never sees half a file; the model's XML is written last.
    """
    collected = collect_assets(model)
    xml = xml_with_assets(model, collected)
    if model_filename is None:
        attribute = model.get_attributes().get("model")
        stem = attribute if isinstance(attribute, str) and attribute else "model"
        name = _unique(safe_file_name(stem, ".xml"), xml.encode("utf-8"), collected)
    else:
        name = model_filename
        if not is_plain_file_name(name):
            raise ExportError(f"model_filename must be a plain file name (no folders, no "
                              f"leading dot, no characters file systems refuse), got {name!r}; "
                              f"e.g. {safe_file_name(*_split(name))!r}")
        if name.casefold() in collected.folded:
            raise ExportError(f"model_filename {name!r} is also the name of a file the model "
                              f"uses ({collected.folded[name.casefold()]!r}); choose another")
    outputs = [*collected.files.items(), (name, xml.encode("utf-8"))]
    for file_name, _ in outputs:
        if not is_plain_file_name(file_name):  # pragma: no cover - names are made safe
            raise ExportError(f"refusing to write {file_name!r}: not a plain file name")
    try:
        os.makedirs(directory, exist_ok=True)
    except OSError as error:
        raise ExportError(f"cannot create the folder {directory}: "
                          f"{error.strerror or error}") from error
    pending = _changed_files(directory, outputs, overwrite)
    for file_name, contents in pending:
        path = os.path.join(directory, file_name)
        try:
            _write_atomically(path, contents, replace=overwrite)
        except FileExistsError:
            raise ExportError(f"{path} appeared while exporting and has other contents; "
                              f"pass overwrite=True to replace it") from None
        except OSError as error:
            raise ExportError(f"cannot write {path}: {error.strerror or error}") from error
    return os.path.join(directory, name)


def _changed_files(directory: str, outputs: list[tuple[str, bytes]],
                   overwrite: bool) -> list[tuple[str, bytes]]:
    """The outputs whose file is missing or differs; refuses replacing files that differ
    (unless ``overwrite``) and anything that is not a regular file."""
    pending: list[tuple[str, bytes]] = []
    conflicts: list[str] = []
    for file_name, contents in outputs:
        path = os.path.join(directory, file_name)
        try:
            mode = os.lstat(path).st_mode
        except FileNotFoundError:
            pending.append((file_name, contents))
            continue
        except OSError as error:
            raise ExportError(f"cannot check {path}: {error.strerror or error}") from error
        if stat.S_ISDIR(mode):
            raise ExportError(f"cannot write {path}: a folder of that name is in the way")
        if stat.S_ISREG(mode) and _same_contents(path, contents):
            continue
        if not overwrite:
            kind = "" if stat.S_ISREG(mode) else (
                " (a symbolic link)" if stat.S_ISLNK(mode) else " (not a regular file)")
            conflicts.append(file_name + kind)
        pending.append((file_name, contents))
    if conflicts:
        raise ExportError(
            f"export_with_assets would replace {len(conflicts)} file(s) in {directory} that "
            f"differ from what the model needs: {', '.join(conflicts)}; nothing was written. "
            f"Pass overwrite=True to replace them, or export into another folder")
    return pending


def _same_contents(path: str, contents: bytes) -> bool:
    try:
        if os.path.getsize(path) != len(contents):
            return False
        with open(path, "rb") as f:
            return f.read() == contents
    except OSError:
        return False


def _file_mode() -> int:
    """The permissions ``open()`` would give a new file (``0o666`` less the umask)."""
    try:
        with open("/proc/self/status", encoding="ascii") as f:
            for line in f:
                if line.startswith("Umask:"):
                    return 0o666 & ~int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    return 0o644


def _write_atomically(path: str, contents: bytes, *, replace: bool = True) -> None:
    """Write ``path`` through a temporary file in its folder, renamed into place.

    With ``replace=False`` the rename does not replace a file that appeared meanwhile
    (``FileExistsError``) unless it has the same contents.
    """
    folder = os.path.dirname(path)
    fd, temporary = tempfile.mkstemp(dir=folder, prefix=".typed-mjcf-", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(contents)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(temporary, _file_mode())  # mkstemp makes it private (0o600)
        if replace:
            os.replace(temporary, path)
            return
        try:
            os.link(temporary, path)  # fails if the name is taken: no silent replacement
        except FileExistsError:
            if not _same_contents(path, contents):
                raise
        except OSError:  # no hard links on this file system
            if os.path.lexists(path) and not _same_contents(path, contents):
                raise FileExistsError(path) from None
            os.replace(temporary, path)
    finally:
        if os.path.lexists(temporary):
            os.unlink(temporary)
