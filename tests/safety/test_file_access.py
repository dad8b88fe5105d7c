"""A model read from MJCF reads files only inside its own folder (symbolic links resolved)
unless its loader allows more (typed_mjcf.FileAccess); a model from a zip reads only the
archive; a model built in Python reads what its author names."""

from __future__ import annotations

import copy
import os
import zipfile
from collections.abc import Callable
from pathlib import Path

import mujoco
import pytest

import typed_mjcf as mjcf
from tests.support.meshes import box_stl
from typed_mjcf._core import tree as _tree  # pyright: ignore[reportPrivateUsage]

SECRET = b"secret contents outside the model's folder"


@pytest.fixture
def layout(tmp_path: Path) -> Path:
    """``tmp_path/model/`` (the model's folder, empty) beside ``tmp_path/secret.stl``."""
    (tmp_path / "model").mkdir()
    (tmp_path / "secret.stl").write_bytes(SECRET)
    (tmp_path / "secret.xml").write_text("<mujoco><worldbody><geom size='1'/></worldbody></mujoco>")
    return tmp_path


def write_model(layout: Path, text: str, name: str = "main.xml") -> Path:
    path = layout / "model" / name
    path.write_text(text)
    return path


def no_secret_anywhere(*where: Path) -> None:
    for folder in where:
        for path in folder.rglob("*"):
            if path.is_file() and not path.is_symlink():
                assert SECRET not in path.read_bytes(), path


def file_attributes() -> list[tuple[str, str, str]]:
    """(class name, tag, attribute) of every file attribute in the grammar."""
    found: list[tuple[str, str, str]] = []
    for name, cls in sorted(_tree.element_classes().items()):
        found += [(name, cls.spec.tag, a.name) for a in cls.spec.attributes.values()
                  if a.kind == "file"]
    return found


def test_every_kind_of_file_attribute_is_covered() -> None:
    assert {tag for _, tag, _ in file_attributes()} >= {"mesh", "texture", "hfield", "skin",
                                                        "model", "flexcomp"}


@pytest.mark.parametrize(("name", "tag", "attribute"), file_attributes())
def test_a_file_outside_the_folder_is_refused_wherever_it_is_read(
        layout: Path, name: str, tag: str, attribute: str) -> None:
    required = " size='1 1 1 1'" if tag == "hfield" else ""  # compile() validates first
    element = f"<{tag} name='x'{required} {attribute}='../secret.stl'/>"
    in_asset = tag in mjcf.AssetSection.spec.children
    text = (f"<mujoco><asset>{element}</asset></mujoco>" if in_asset else
            f"<mujoco><worldbody><body>{element}</body></worldbody></mujoco>")
    path = write_model(layout, text)
    model = mjcf.from_path(path)
    expected = (rf"main.xml:1: .*{attribute}='../secret.stl': {layout / 'secret.stl'} is "
                rf"outside the model's folder {layout / 'model'}; pass files=")
    with pytest.raises(mjcf.FileAccessError, match=expected):
        model.get_assets()
    with pytest.raises(mjcf.FileAccessError, match=expected):
        model.compile()
    with pytest.raises(mjcf.FileAccessError, match=expected):
        mjcf.export_with_assets(model, layout / "out")
    with pytest.raises(mjcf.FileAccessError, match=expected):
        mjcf.export_with_assets_as_zip(model, layout / "out")
    assert not (layout / "out").exists() or not os.listdir(layout / "out")
    # allowed explicitly, the same file is read
    allowed = mjcf.from_path(path, files=mjcf.FileAccess(roots=[layout]))
    if tag == "model":  # not MJCF: MuJoCo would read what it names anywhere (test below)
        with pytest.raises(mjcf.FileAccessError, match="secret.stl is not MJCF"):
            allowed.get_assets()
        allowed = mjcf.from_path(path, files=mjcf.FileAccess(anywhere=True))
    assert SECRET in allowed.get_assets().values()


def test_the_error_is_every_kind_the_library_promises(layout: Path) -> None:
    model = mjcf.from_path(write_model(
        layout, "<mujoco>\n<asset>\n<mesh file='../../../../../../etc/passwd'/></asset></mujoco>"))
    with pytest.raises(mjcf.FileAccessError) as info:
        model.get_assets()
    error = info.value
    assert isinstance(error, mjcf.MjcfError) and isinstance(error, mjcf.ParseError)
    assert isinstance(error, PermissionError) and isinstance(error, ValueError)
    assert error.source == str(layout / "model" / "main.xml") and error.line == 3
    assert error.detail.startswith("asset/mesh[0]: file='../../../../../../etc/passwd': "
                                   "/etc/passwd is outside the model's folder ")


def test_absolute_paths_and_folders_outside_are_refused(layout: Path) -> None:
    cases = [
        "<compiler meshdir='/etc'/><asset><mesh file='passwd'/></asset>",
        "<compiler meshdir='..'/><asset><mesh file='secret.stl'/></asset>",
        "<compiler assetdir='../'/><asset><mesh file='secret.stl'/></asset>",
        f"<asset><mesh file='{layout / 'secret.stl'}'/></asset>",
        "<asset><mesh file='/proc/self/environ'/></asset>",
        "<asset><texture type='2d' file='/etc/hostname'/></asset>",
    ]
    for case in cases:
        model = mjcf.from_path(write_model(layout, f"<mujoco>{case}</mujoco>"))
        with pytest.raises(mjcf.FileAccessError, match="is outside the model's folder"):
            mjcf.export_with_assets(model, layout / "out")
    assert not (layout / "out").exists() or not os.listdir(layout / "out")


def test_includes_outside_the_folder_are_refused_at_load(layout: Path) -> None:
    for file in ["../secret.xml", str(layout / "secret.xml"), "sub/../../secret.xml",
                 "/proc/self/environ", "/etc/passwd"]:
        path = write_model(layout, f"<mujoco>\n<include file='{file}'/></mujoco>")
        with pytest.raises(mjcf.FileAccessError) as info:
            mjcf.from_path(path)
        assert info.value.line == 2 and info.value.source == str(path)
        assert f"cannot read included file {file!r}" in info.value.detail
        assert "is outside the model's folder" in info.value.detail
    # nested: an included file's own include resolves against the main file's folder
    (layout / "model" / "parts").mkdir()
    (layout / "model" / "parts" / "a.xml").write_text(
        "<mujoco>\n\n<include file='../secret.xml'/></mujoco>")
    path = write_model(layout, "<mujoco><include file='parts/a.xml'/></mujoco>")
    with pytest.raises(mjcf.FileAccessError, match=r"a.xml:3: cannot read included file "
                                                   r"'../secret.xml'.*outside"):
        mjcf.from_path(path)
    allowed = mjcf.from_path(path, files=mjcf.FileAccess(roots=[layout]))
    assert len(allowed.find_all("geom")) == 1


def test_dot_dot_that_stays_inside_is_allowed(layout: Path) -> None:
    folder = layout / "model"
    (folder / "assets").mkdir()
    (folder / "assets" / "box.stl").write_bytes(box_stl())
    (folder / "parts").mkdir()
    (folder / "parts" / "p.xml").write_text("<mujoco><worldbody><geom size='1'/></worldbody></mujoco>")
    path = write_model(layout, "<mujoco><compiler meshdir='parts/../assets'/>"
                               "<include file='assets/../parts/p.xml'/>"
                               "<asset><mesh file='../assets/box.stl'/></asset></mujoco>")
    model = mjcf.from_path(path)
    assert model.get_assets() == {"box.stl": box_stl()}
    model.compile()


def test_symbolic_links_are_resolved(layout: Path) -> None:
    folder = layout / "model"
    (folder / "link.stl").symlink_to(layout / "secret.stl")
    (folder / "dir").symlink_to(layout)
    (folder / "inside.stl").write_bytes(box_stl())
    (folder / "good.stl").symlink_to(folder / "inside.stl")
    for file in ["link.stl", "dir/secret.stl"]:
        model = mjcf.from_path(write_model(layout, f"<mujoco><asset><mesh file='{file}'/>"
                                                   f"</asset></mujoco>"))
        with pytest.raises(mjcf.FileAccessError, match=rf"{file} \(really "
                                                       rf"{layout / 'secret.stl'}\) is outside"):
            model.get_assets()
    (folder / "inc.xml").symlink_to(layout / "secret.xml")
    with pytest.raises(mjcf.FileAccessError, match="outside"):
        mjcf.from_path(write_model(layout, "<mujoco><include file='inc.xml'/></mujoco>"))
    model = mjcf.from_path(write_model(layout, "<mujoco><asset><mesh file='good.stl'/></asset>"
                                               "</mujoco>"))
    assert model.get_assets() == {"good.stl": box_stl()}  # a link that stays inside is fine


def test_a_model_folder_reached_through_a_link_is_the_folder(layout: Path) -> None:
    (layout / "model" / "box.stl").write_bytes(box_stl())
    (layout / "alias").symlink_to(layout / "model")
    path = write_model(layout, "<mujoco><asset><mesh file='box.stl'/></asset></mujoco>")
    assert mjcf.from_path(layout / "alias" / path.name).get_assets() == {"box.stl": box_stl()}


def test_symlink_loops_and_odd_paths_are_errors_not_hangs(layout: Path) -> None:
    folder = layout / "model"
    (folder / "loop").symlink_to(folder / "loop")
    for file in ["loop", "loop/x.stl", "a\\..\\..\\secret.stl", "..\\secret.stl"]:
        model = mjcf.from_path(write_model(layout, f"<mujoco><asset><mesh file='{file}'/>"
                                                   f"</asset></mujoco>"))
        with pytest.raises(mjcf.MjcfError):
            model.get_assets()
    # a NUL in a path given in Python to a parsed model: refused, not a crash
    model = mjcf.from_path(write_model(layout, "<mujoco><asset><mesh name='m' file='x.stl'/>"
                                               "</asset></mujoco>"))
    try:
        model.asset.mesh[0].file = "a\0b.stl"
    except mjcf.MjcfError:
        return  # refused at assignment
    with pytest.raises(mjcf.FileAccessError, match="not a path a file can have"):
        model.get_assets()


def test_a_model_asset_reads_as_its_owner_may(layout: Path) -> None:
    folder = layout / "model"
    (folder / "sub").mkdir()
    (folder / "sub" / "inner.xml").write_text(
        "<mujoco><asset><mesh name='s' file='../../secret.stl'/></asset>"
        "<worldbody><geom type='mesh' mesh='s'/></worldbody></mujoco>")
    path = write_model(layout, "<mujoco><asset><model name='inner' file='sub/inner.xml'/>"
                               "</asset></mujoco>")
    with pytest.raises(mjcf.FileAccessError, match=r"file='../../secret.stl'.*outside"):
        mjcf.from_path(path).get_assets()
    assets = mjcf.from_path(path, files=mjcf.FileAccess(roots=[layout])).get_assets()
    assert SECRET in assets.values()
    path = write_model(layout, "<mujoco><asset><model name='o' file='../secret.xml'/>"
                               "</asset></mujoco>")
    with pytest.raises(mjcf.FileAccessError, match=r"file='../secret.xml'.*outside"):
        mjcf.from_path(path).get_assets()


@pytest.mark.parametrize(("name", "text"), [
    # MuJoCo's XML reader takes a "<" in an attribute value; libxml2 does not
    ("sub.xml", ("<mujoco model='a<b'><include file='{outside}/secret.xml'/><asset>"
                "<mesh file='{outside}/secret.stl'/></asset></mujoco>")),
    # MuJoCo reads a URDF model asset (and its meshes, anywhere); it is no MJCF
    ("r.urdf", ("<robot name='r'><link name='l'><collision><geometry>"
               "<mesh filename='{outside}/secret.stl'/></geometry></collision></link></robot>")),
])
def test_a_model_asset_the_library_cannot_read_is_refused(layout: Path, name: str,
                                                          text: str) -> None:
    """Passed on unread, MuJoCo would read every file it names, anywhere."""
    (layout / "model" / name).write_text(text.format(outside=layout))
    path = write_model(layout, f"<mujoco><asset><model name='sub' file='{name}'/></asset>"
                               f"<worldbody><attach model='sub' prefix='s'/></worldbody>"
                               f"</mujoco>")
    model = mjcf.from_path(path)
    expected = (rf"main.xml:1: asset/model\[sub\]: file='{name}': .*{name} is not MJCF "
                rf"typed-mjcf can read \(well-formed XML whose root is <mujoco>\), so the "
                rf"files it names cannot be kept to the model's folder {layout / 'model'}; pass")
    for read in (model.get_assets, model.compile, lambda: mjcf.Physics.from_mjcf_model(model),
                 lambda: mjcf.export_with_assets(model, layout / "out")):
        with pytest.raises(mjcf.FileAccessError, match=expected):
            read()
    no_secret_anywhere(layout / "model")
    trusted = mjcf.from_path(path, files=mjcf.FileAccess(anywhere=True))
    assert trusted.get_assets() == {name: (layout / "model" / name).read_bytes()}


def test_text_without_a_folder_is_confined_to_the_current_folder(
        layout: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(layout / "model")
    (layout / "model" / "box.stl").write_bytes(box_stl())
    inside = mjcf.from_xml_string("<mujoco><asset><mesh file='box.stl'/></asset></mujoco>")
    assert inside.get_assets() == {"box.stl": box_stl()}
    outside = mjcf.from_xml_string("<mujoco><asset><mesh file='../secret.stl'/></asset></mujoco>")
    with pytest.raises(mjcf.FileAccessError, match="outside the model's folder"):
        outside.get_assets()
    given = mjcf.from_xml_string("<mujoco><asset><mesh file='secret.stl'/></asset></mujoco>",
                                 model_dir=layout)
    assert given.get_assets() == {"secret.stl": SECRET}  # model_dir is the model's folder


def test_files_given_in_memory_are_not_on_disk(layout: Path) -> None:
    """``assets=`` and ``FileAccess(model_folder=False)``: only the given files are read."""
    (layout / "model" / "box.stl").write_bytes(box_stl())
    path = write_model(layout, "<mujoco><asset><mesh file='box.stl'/><mesh file='m.stl'/>"
                               "</asset></mujoco>")
    only_memory = mjcf.FileAccess(model_folder=False)
    model = mjcf.from_path(path, assets={"m.stl": b"given"}, files=only_memory)
    with pytest.raises(mjcf.FileAccessError, match="box.stl.*reads none from disk"):
        model.get_assets()
    model = mjcf.from_path(path, assets={"m.stl": b"given", "box.stl": b"also"},
                           files=only_memory)
    assert model.get_assets() == {"box.stl": b"also", "m.stl": b"given"}


def test_models_built_in_python_read_what_their_author_names(layout: Path) -> None:
    model = mjcf.RootElement(model="m")
    model.asset.add_mesh(name="s", file=str(layout / "secret.stl"))
    assert model.get_assets() == {"secret.stl": SECRET}


def test_attached_models_keep_their_own_folder(layout: Path) -> None:
    (layout / "other").mkdir()
    (layout / "other" / "box.stl").write_bytes(box_stl())
    child = mjcf.from_path(write_model(layout, "<mujoco model='c'><asset><mesh name='b' "
                                               "file='box.stl'/></asset></mujoco>", "c.xml"))
    (layout / "model" / "box.stl").write_bytes(box_stl(0.3))
    parent = mjcf.from_xml_string("<mujoco model='p'><asset><mesh file='../other/box.stl'/>"
                                  "</asset><worldbody><site name='s'/></worldbody></mujoco>",
                                  model_dir=layout / "model")
    site = parent.find("site", "s")
    assert site is not None
    site.attach(child)
    with pytest.raises(mjcf.FileAccessError, match="other/box.stl is outside"):
        parent.get_assets()
    trusting = mjcf.RootElement(model="p")  # built in Python: reads anywhere
    trusting.worldbody.add_site(name="s").attach(copy.deepcopy(child))
    assert sorted(trusting.get_assets().values()) == [box_stl(0.3)]
    sneaky = mjcf.from_path(write_model(layout, "<mujoco model='x'><asset><mesh name='b' "
                                                "file='../secret.stl'/></asset></mujoco>", "x.xml"))
    trusting.worldbody.add_site(name="t").attach(sneaky)
    with pytest.raises(mjcf.FileAccessError, match="secret.stl is outside"):
        trusting.get_assets()  # the attached model keeps its own confinement


def test_a_copy_keeps_the_confinement(layout: Path) -> None:
    model = mjcf.from_path(write_model(layout, "<mujoco><asset><mesh file='../secret.stl'/>"
                                               "</asset></mujoco>"))
    with pytest.raises(mjcf.FileAccessError):
        copy.deepcopy(model).get_assets()


def test_include_copy_and_paste_keep_the_confinement(layout: Path) -> None:
    """A copy reads its files as its original may: refused at once, nothing copied."""
    model = mjcf.from_path(write_model(layout, f"<mujoco><asset><mesh name='p' "
                                               f"file='{layout / 'secret.stl'}'/></asset></mujoco>"))
    outside = rf"file='.*secret.stl': {layout / 'secret.stl'} is outside"
    with pytest.raises(mjcf.FileAccessError, match=rf"asset/mesh\[p\]: {outside}"):
        model.get_assets()
    copies: list[tuple[Callable[[mjcf.RootElement], object], str]] = [
        (lambda root: root.include_copy(model), r"asset/mesh\[p\]"),
        (lambda root: root.asset.paste(model.asset.mesh[0]), r"asset/mesh\[p\]"),
        (lambda root: root.asset.paste(copy.deepcopy(model.asset.mesh[0])), "<mesh>")]  # detached
    for copy_into, where in copies:
        root = mjcf.RootElement()
        with pytest.raises(mjcf.FileAccessError, match=rf"{where}: {outside}"):
            copy_into(root)
        assert root.find_all("mesh") == []
    # a file inside goes along with the copy (an absolute path too), as its original read it
    (layout / "model" / "box.stl").write_bytes(box_stl())
    inside = mjcf.from_path(write_model(layout, f"<mujoco><asset><mesh name='b' "
                                                f"file='{layout / 'model' / 'box.stl'}'/>"
                                                f"</asset></mujoco>", "inside.xml"))
    root = mjcf.RootElement()
    root.asset.paste(inside.asset.mesh[0])
    assert root.get_assets() == {"box.stl": box_stl()}
    # a model asset's own files would be read as the copy's new model may: attach it instead
    (layout / "model" / "sub.xml").write_text("<mujoco/>")
    owner = mjcf.from_path(write_model(layout, "<mujoco><asset><model name='s' file='sub.xml'/>"
                                               "</asset></mujoco>", "owner.xml"))
    with pytest.raises(mjcf.FileAccessError, match=r"file='sub.xml': a copy of a model asset "
                                                   r".*; attach the model instead"):
        mjcf.RootElement().include_copy(owner)


def test_file_access_is_checked() -> None:
    for bad in [{"roots": "/etc"}, {"roots": [3]}, {"anywhere": 1}, {"max_bytes": 0},
                {"max_bytes": 1.5}]:
        with pytest.raises(mjcf.MjcfError):
            mjcf.FileAccess(**bad)  # type: ignore[arg-type]
    with pytest.raises(mjcf.InvalidTypeError, match="FileAccess"):
        mjcf.from_xml_string("<mujoco/>", files=True)  # type: ignore[arg-type]
    assert mjcf.FileAccess(roots=[Path("rel")]).roots == (os.path.abspath("rel"),)


def test_a_huge_sparse_file_is_refused_by_size(layout: Path) -> None:
    big = layout / "model" / "big.stl"
    with open(big, "wb") as f:
        f.truncate(1 << 40)  # 1 TiB, sparse: nothing on disk
    path = write_model(layout, "<mujoco><asset><mesh file='big.stl'/></asset></mujoco>")
    with pytest.raises(mjcf.FileAccessError, match=r"1099511627776 bytes, more than .*"
                                                   r"FileAccess.max_bytes"):
        mjcf.from_path(path).get_assets()
    small = mjcf.from_path(write_model(layout, "<mujoco><asset><mesh file='a.stl'/>"
                                               "<mesh file='b.stl'/></asset></mujoco>"),
                           files=mjcf.FileAccess(max_bytes=150))
    (layout / "model" / "a.stl").write_bytes(b"a" * 100)
    (layout / "model" / "b.stl").write_bytes(b"b" * 100)
    with pytest.raises(mjcf.FileAccessError, match="100 bytes, more than the 50 left"):
        small.get_assets()  # counted over all the model's files


def test_a_zip_model_reads_only_the_archive(layout: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(layout / "model")
    (layout / "model" / "here.stl").write_bytes(SECRET)
    (layout / "model" / "here.xml").write_text("<mujoco><worldbody/></mujoco>")
    archive = layout / "m.zip"
    with zipfile.ZipFile(archive, "w") as z:
        z.writestr("m/model.xml", "<mujoco><asset><mesh file='here.stl'/></asset></mujoco>")
    with pytest.raises(mjcf.FileAccessError, match=r"here.stl': not among the files of the archive .*m.zip"):
        mjcf.from_zip(archive).get_assets()
    with zipfile.ZipFile(archive, "w") as z:
        z.writestr("m/model.xml", "<mujoco><include file='here.xml'/></mujoco>")
    with pytest.raises(mjcf.FileAccessError, match="cannot read included file 'here.xml'"):
        mjcf.from_zip(archive)
    with zipfile.ZipFile(archive, "w") as z:
        z.writestr("m/model.xml", "<mujoco><include file='p.xml'/>"
                                  "<asset><mesh file='b.stl'/></asset></mujoco>")
        z.writestr("m/p.xml", "<mujoco><worldbody/></mujoco>")
        z.writestr("m/b.stl", box_stl())
    assert mjcf.from_zip(archive).get_assets() == {"b.stl": box_stl()}


def test_a_model_from_a_spec_reads_what_the_spec_names(layout: Path) -> None:
    """A spec is the caller's own object: its files are read wherever they are (here outside
    the current folder, which would confine text without a folder)."""
    spec = mujoco.MjSpec.from_string(
        f"<mujoco><asset><mesh name='b' file='{layout / 'model' / 'box.stl'}'/></asset>"
        f"<worldbody><geom type='mesh' mesh='b'/></worldbody></mujoco>")
    (layout / "model" / "box.stl").write_bytes(box_stl())
    model = mjcf.from_spec(spec)
    assert model.get_assets() == {"box.stl": box_stl()}  # read from wherever the spec says
