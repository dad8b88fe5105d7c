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

import functools
import hashlib
import os
import re
from collections.abc import Callable
from dataclasses import dataclass, field

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.access import Refused, read_file
from typed_mjcf._core.behaviour import FLAGS
from typed_mjcf._core.errors import FileAccessError, InvalidValueError, MjcfError
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
from typed_mjcf._text.skin import scope_bone_names
from typed_mjcf.assets import Asset

# elements whose rows have attributes that name files, each with those attributes
FileElements = list[tuple[Element, tuple[AttributeSpec, ...]]]


@dataclass
class CollectedFiles:
    """Flat file names and contents of every file a model uses."""

    files: dict[str, bytes] = field(default_factory=lambda: {})
    names: dict[tuple[int, str], str] = field(default_factory=lambda: {})
    folded: dict[str, str] = field(default_factory=lambda: {})  # casefolded name -> name
    keys: dict[str, object] = field(default_factory=lambda: {})  # name -> what file it is
    # every file attribute named: (its model, element, attribute, value, name, scope prefix)
    uses: list[tuple[ModelBase, Element, AttributeSpec, object, str, str]] = field(
        default_factory=lambda: [])
    directory_attributes: frozenset[str] = frozenset()
    # how to read the contents of the file each name was first given to (files whose
    # contents may be shared: not MJCF files, nor skins whose bones are renamed)
    readers: dict[str, Callable[[], bytes]] = field(default_factory=lambda: {})
    digests: dict[object, str | None] = field(default_factory=lambda: {})  # key -> SHA-256
    # the files kept apart by a folder in their name (different files of one base name):
    # path -> name, and whether the base names were looked at yet
    apart: dict[str, str] = field(default_factory=lambda: {})
    apart_found: bool = False
    # the model and each model attached to it, by id(), with its elements of a row with file
    # attributes (and those attributes): found in one walk of each
    file_elements: dict[int, tuple[ModelBase, FileElements]] = field(default_factory=lambda: {})

    def digest(self, key: object, read: Callable[[], bytes]) -> str | None:
        """The SHA-256 of the file ``key`` (read once); None when it cannot be read."""
        if key not in self.digests:
            try:
                self.digests[key] = hashlib.sha256(read()).hexdigest()
            except MjcfError:  # unreadable: told apart by its path, as before reading
                self.digests[key] = None
        return self.digests[key]

    def same_contents(self, name: str, key: object, read: Callable[[], bytes]) -> bool:
        """Whether the file named ``name`` holds the same bytes as the file ``key``."""
        first = self.readers.get(name)
        if first is None:
            return False
        mine = self.digest(key, read)
        return mine is not None and mine == self.digest(self.keys.get(name), first)

    bytes_read: int = 0  # from disk, against the model's FileAccess.max_bytes

    def name_of(self, element: Element, attribute: AttributeSpec) -> str:
        """The flat name of the file ``element``'s ``attribute`` holds."""
        return self.names[(id(element), attribute.name)]


# An MJCF file the model uses, rewritten to find its files among those collected: (the model
# that uses it, path, contents, files collected so far, the MJCF files being read) ->
# contents (None when the file is not MJCF the library reads).
ModelFileWriter = Callable[[ModelBase, str, bytes, CollectedFiles, tuple[str, ...]],
                           bytes | None]


def compiler_folders(model: ModelBase) -> dict[str, str]:
    """Values of the root's folder attributes (meshdir, texturedir, assetdir, strippath),
    as ``"compiler@meshdir"`` -> text."""
    folders: dict[str, str] = {}
    for section in _tree.children(model):
        for name, value in _tree.values(section).items():
            if isinstance(value, str | bool):
                folders[f"{section.spec.tag}@{name}"] = str(value)
    return folders


def resolve_path(model: ModelBase, attribute: AttributeSpec, file: str,
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
    base = _tree.base_dir(model) or os.getcwd()
    return os.path.normpath(os.path.join(base, folder, file))


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
    if source is target:
        return {}
    confined = _tree.file_access(source).roots is not None
    folders = compiler_folders(source)
    given = _tree.memory_files(source)
    collected = CollectedFiles()
    found: dict[tuple[int, str], bytes] = {}
    for element in original.iter_elements():
        for name, value in _tree.values(element).items():
            attribute = element.spec.by_name[name]
            if attribute.kind != "file" or not isinstance(value, str):
                continue
            if confined and is_model_asset(element, attribute):
                raise FileAccessError(
                    f"{element.path}: {attribute.py_name}={value!r}: a copy of a model asset "
                    f"of a model that may read only {_tree.file_access(source).where} would "
                    f"read the files that model names as this model may; attach the model "
                    f"instead (an attached model keeps its own rules)",
                    *(_tree.source_of(element) or (None, None)))
            if not confined and os.path.isabs(value):
                continue
            try:
                contents = _read(element, attribute, value, source, folders, given, collected)[0]
            except MjcfError:
                if confined:
                    raise
                continue
            found[(id(element), name)] = contents
    return found


def rebase_files(copy: Element, original: Element, files: dict[tuple[int, str], bytes],
                 target: ModelBase) -> None:
    """A copy of ``original`` (now in ``target``) keeps naming the files it named (``files``:
    see :func:`copied_files`). As dm_control's copy holds the file itself, ``target`` is
    given the file's contents in memory under the name the copy keeps; where it holds other
    contents by that name, under that name with a ``-2`` (``-3``...) suffix, which the copy
    then names."""
    if not files:
        return
    taken = _tree.memory_files(target)
    for element, mine in zip(original.iter_elements(), copy.iter_elements(), strict=True):
        for name, value in list(_tree.values(mine).items()):
            contents = files.get((id(element), name))
            if contents is None or not isinstance(value, str):
                continue
            key, stem, extension, n = value, *os.path.splitext(value), 1
            while taken.get(key, contents) != contents:  # another file by that name here
                n += 1
                key = f"{stem}-{n}{extension}"
            taken[key] = contents
            if key != value:
                _tree.assign(mine, mine.spec.by_name[name], key)


def absolute_file(model: ModelBase, attribute: AttributeSpec, file: str) -> str:
    """An attached model's file, as a path that does not depend on the parent's folders."""
    return resolve_path(model, attribute, file, compiler_folders(model))


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
    return bool(name) and safe_file_name(*split_name(name)) == name


def split_name(name: str) -> tuple[str, str]:
    """A file name's stem and extension (``".stl"`` is an extension, not a hidden stem)."""
    dot = name.rfind(".")
    if dot <= 0 or dot == len(name) - 1:
        return name, ""
    return name[:dot], name[dot:]


def unique_name(name: str, key: object, collected: CollectedFiles,
                read: Callable[[], bytes] | None = None) -> str:
    """``name``, or ``name`` with a numeric suffix when another file (``key`` tells files
    apart: a path, or in-memory contents) has it already, or a name differing in case only
    (MuJoCo's in-memory loader and case-insensitive file systems would mix them up). With
    ``read`` (the file's contents, read only when its name is taken), a file with the same
    contents as the one that has the name shares it."""
    stem, extension = split_name(name)
    candidate, n = name, 1
    while True:
        taken = collected.folded.get(candidate.casefold())
        if taken is None or (taken == candidate and collected.keys.get(candidate) == key):
            break
        if read is not None and collected.same_contents(taken, key, read):
            return taken
        n += 1
        candidate = f"{stem}-{n}{extension}"
    collected.folded[candidate.casefold()] = candidate
    if candidate not in collected.keys:
        collected.keys[candidate] = key
        if read is not None:
            collected.readers[candidate] = read
    return candidate


def is_skin_file(element: Element, attribute: AttributeSpec) -> bool:
    """Whether the attribute holds a binary skin file (whose bones name bodies)."""
    return f"{element.spec.row}@{attribute.name}" == grammar_facts().skin_file


def name_files(model: ModelBase, collected: CollectedFiles | None = None,
               prefix: str = "") -> CollectedFiles:
    """A flat, unique name for every file the model (and the models attached to it) uses,
    without reading any: files are told apart by their path, in-memory ones by contents
    (and an attached model's skin files by its scope too: their bones are renamed)."""
    collected = CollectedFiles() if collected is None else collected
    if not collected.apart_found:
        collected.apart_found = True
        collected.file_elements = _file_elements(model)
        collected.apart.update(_kept_apart(model, collected))
    folders = compiler_folders(model)
    directories: set[str] = set()
    for element, files in collected.file_elements[id(model)][1]:
        stored = _tree.values(element)
        if not stored:
            continue
        for attribute in files:
            directories.update(attribute.directory)
            value = stored.get(attribute.name)
            if value is None:
                continue
            read: Callable[[], bytes] | None
            if FLAGS.hashed_file_names:  # dm_control's names: <stem>-<sha1 of contents>
                name = _hashed_name(model, element, attribute, value, folders, collected)
                key: object = name
                read = None
            elif isinstance(value, Asset):
                stem = value.name or element_stem(element)
                name = safe_file_name(stem, value.extension)
                key = (value.digest, value.extension)
                read = functools.partial(bytes, value.contents)
            else:
                assert isinstance(value, str)
                path = resolve_path(model, attribute, value, folders)
                # the source's own name (MuJoCo names an unnamed mesh after it), or its
                # folders too where another file has its base name
                name, key = collected.apart.get(path, os.path.basename(path)), path
                # an MJCF file is rewritten for its own folder: its contents are not shared
                read = None if is_model_file_name(path) else functools.partial(
                    file_contents, element, attribute, value, model, folders, collected)
            scoped = prefix if prefix and is_skin_file(element, attribute) else ""
            if scoped:  # its bones are renamed for its scope: its contents are its own
                key, read = (key, scoped), None
            name = unique_name(name, key, collected, read)
            collected.names[(id(element), attribute.name)] = name
            collected.uses.append((model, element, attribute, value, name, scoped))
    collected.directory_attributes = collected.directory_attributes | frozenset(directories)
    for attached in _tree.attached_models(model):  # each resolves files in its own folders
        name_files(attached, collected, f"{prefix}{_tree.scope_of(attached).name}/")
    return collected


def _file_elements(model: ModelBase) -> dict[int, tuple[ModelBase, FileElements]]:
    """``model`` and the models attached to it (by ``id()``), each with its elements whose
    rows have attributes that name files, and those attributes."""
    found: dict[int, tuple[ModelBase, FileElements]] = {}
    # a row's file attributes, found once per row for this walk (not kept longer: a release
    # may change a row's attributes when the grammar loads)
    rows: dict[int, tuple[AttributeSpec, ...]] = {}
    models = [model]
    while models:
        owner = models.pop()
        models.extend(_tree.attached_models(owner))
        elements: FileElements = []
        found[id(owner)] = (owner, elements)
        for element in owner.iter_elements():
            spec = type(element).spec
            files = rows.get(id(spec))
            if files is None:
                files = rows[id(spec)] = tuple(
                    a for a in spec.attributes.values() if a.kind == "file")
            if files:
                elements.append((element, files))
    return found


def _kept_apart(model: ModelBase, collected: CollectedFiles) -> dict[str, str]:
    """A name with folders for each file whose base name a file with other contents has too
    (MuJoCo's loader from a dict finds files by base name alone, and renaming one with a
    suffix renames the mesh MuJoCo names after it): its path below the model's folder
    (what MuJoCo makes of the source's text), else its last folders as far as they tell it
    from the others."""
    if FLAGS.hashed_file_names:
        return {}
    by_base: dict[str, dict[str, Callable[[], bytes]]] = {}
    for owner, elements in collected.file_elements.values():
        folders = compiler_folders(owner)
        for element, files in elements:
            stored = _tree.values(element)
            for attribute in files:
                value = stored.get(attribute.name)
                if not isinstance(value, str):
                    continue
                path = resolve_path(owner, attribute, value, folders)
                by_base.setdefault(os.path.basename(path).casefold(), {})[path] = (
                    functools.partial(file_contents, element, attribute, value, owner, folders,
                                      collected))
    base = _tree.base_dir(model) or os.getcwd()
    apart: dict[str, str] = {}
    for paths in by_base.values():
        if len(paths) < 2 or len({collected.digest(p, read) for p, read in paths.items()}) < 2:
            continue  # one file, or one contents in several folders: one name
        for path in paths:
            try:
                relative = os.path.relpath(path, base).replace(os.sep, "/")
            except ValueError:  # another drive (Windows)
                relative = "../"
            if relative.startswith("../"):
                relative = _telling_suffix(path, list(paths))
            apart[path] = relative
    return apart


def _telling_suffix(path: str, paths: list[str]) -> str:
    """The last folders of ``path`` and its name, as many as tell it from ``paths``."""
    parts = path.replace(os.sep, "/").split("/")
    others = [p.replace(os.sep, "/").casefold() for p in paths if p != path]
    for count in range(2, len(parts) + 1):
        tail = "/".join(parts[-count:])
        if not any(o.endswith("/" + tail.casefold()) or o == tail.casefold() for o in others):
            return tail
    return "/".join(parts).lstrip("/")


def _hashed_name(model: ModelBase, element: Element, attribute: AttributeSpec, value: object,
                 folders: dict[str, str], collected: CollectedFiles) -> str:
    """dm_control's flat name of a file: its stem (an in-memory asset's name, if it has
    one), ``-`` and the SHA-1 of its contents, and its extension."""
    if isinstance(value, Asset):
        contents, stem, extension = value.contents, value.name or "", value.extension
    else:
        assert isinstance(value, str)
        contents, path = _read(element, attribute, value, model, folders,
                               _tree.memory_files(model), collected)
        stem, extension = split_name(os.path.basename(path))
    digest = hashlib.sha1(contents, usedforsecurity=False).hexdigest()
    return safe_file_name(f"{stem}-{digest}" if stem else digest, extension)


def collect_files(model: ModelBase, model_file: ModelFileWriter,
                  collected: CollectedFiles | None = None,
                  models: tuple[str, ...] = ()) -> CollectedFiles:
    """Name (see :func:`name_files`) and read every file the model uses; ``models`` are
    the MJCF files being read (to refuse one that uses itself)."""
    collected = name_files(model, collected)
    for owner, element, attribute, value, name, scoped in collected.uses:
        if name in collected.files:
            continue
        if isinstance(value, Asset):
            contents = value.contents
            collected.files[name] = scope_bone_names(contents, scoped, element.path) if (
                scoped) else contents
            continue
        assert isinstance(value, str)
        folders = compiler_folders(owner)
        contents, path = _read(element, attribute, value, owner, folders,
                               _tree.memory_files(owner), collected)
        model_asset = is_model_asset(element, attribute)
        if model_asset or is_model_file_name(name):
            if path in models:
                raise InvalidValueError(
                    f"{element.path}: {attribute.py_name}: {path} uses itself "
                    f"(through {' -> '.join(models)})")
            rewritten = model_file(owner, path, contents, collected, (*models, path))
            if rewritten is None and model_asset:
                _unread_model(owner, element, attribute, value, path)
            contents = contents if rewritten is None else rewritten
        if scoped:
            contents = scope_bone_names(contents, scoped, element.path)
        collected.files[name] = contents
    return collected


def is_model_asset(element: Element, attribute: AttributeSpec) -> bool:
    """Whether the attribute holds a model MuJoCo reads (an ``<asset><model file>``)."""
    return (attribute.kind == "file"
            and element.spec.namespace in grammar_facts().named_from_contents)


def _unread_model(owner: ModelBase, element: Element, attribute: AttributeSpec, value: str,
                  path: str) -> None:
    """A model file the library cannot read is refused unless ``owner`` reads anywhere:
    passed on unread, MuJoCo would read every file it names, wherever it is."""
    access = _tree.file_access(owner)
    if access.roots is None:
        return
    source, line = _tree.source_of(element) or (None, None)
    raise FileAccessError(
        f"{element.path}: {attribute.py_name}={value!r}: {path} is not MJCF typed-mjcf can "
        f"read (well-formed XML whose root is <{owner.spec.tag}>), so the files it names "
        f"cannot be kept to {access.where}; {access.hint}", source, line)


def file_contents(element: Element, attribute: AttributeSpec, value: str, model: ModelBase,
              folders: dict[str, str], collected: CollectedFiles) -> bytes:
    """A file's contents, read as :func:`collect_files` reads it."""
    return _read(element, attribute, value, model, folders, _tree.memory_files(model),
                 collected)[0]


def _read(element: Element, attribute: AttributeSpec, value: str, model: ModelBase,
          folders: dict[str, str], memory: dict[str, bytes],
          collected: CollectedFiles) -> tuple[bytes, str]:
    """A file's contents (given in memory, else read from disk where the model may read)
    and its path."""
    path = resolve_path(model, attribute, value, folders)
    base = _tree.base_dir(model) or os.getcwd()
    try:
        relative = os.path.relpath(path, base)
    except ValueError:  # another drive (Windows)
        relative = value
    for key in (value, relative, os.path.basename(value)):
        given = memory.get(key)  # (an archive's files are not all in the dict: always ask)
        if given is not None:
            return given, path
    access = _tree.file_access(model)
    try:
        contents = read_file(path, access, access.max_bytes - collected.bytes_read)
    except Refused as refused:
        source, line = _tree.source_of(element) or (None, None)
        raise FileAccessError(f"{element.path}: {attribute.py_name}={value!r}: {refused}",
                              source, line) from None
    except OSError as error:
        raise InvalidValueError(
            f"{element.path}: {attribute.py_name}={value!r}: cannot read {path}: "
            f"{error.strerror or error}") from None
    collected.bytes_read += len(contents)
    return contents, path


def file_stem(file: str) -> str:
    """A file's name without folders and extension (what MuJoCo names an unnamed mesh)."""
    base = file.replace("\\", "/").rsplit("/", 1)[-1]
    return base.rsplit(".", 1)[0] if "." in base.lstrip(".") else base


def element_file_stem(element: Element, attribute: str) -> str | None:
    """The name MuJoCo gives an unnamed element that reads a file: the file's stem (an
    in-memory asset: the stem the asset writer gives it); None without a file."""
    file = _tree.values(element).get(attribute)
    if isinstance(file, str):
        return file_stem(file)
    if isinstance(file, Asset):
        return file.name or element_stem(element)
    return None


def is_model_file_name(name: str) -> bool:
    return name.lower().endswith(".xml")


def element_stem(element: Element) -> str:
    """The stem of an in-memory file's name: the element's name, else its tag."""
    return _tree.element_name(element) or element.spec.tag
