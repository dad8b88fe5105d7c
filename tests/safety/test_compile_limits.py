"""Compile and render limits: what MuJoCo would allocate from a few bytes (a builtin texture's
size, an hfield's rows and columns, a PNG's declared size) and how long a picture's simulation
runs (steps) are refused before MuJoCo starts, each error naming the element, attribute, value,
limit and how to raise it (CompileLimits, RenderLimits)."""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from tests.support.corpus import CORPUS, compiled, corpus_files
from typed_mjcf._model.resource_limits import check_compile, totals
from typed_mjcf.cli import main
from typed_mjcf.errors import InvalidTypeError


def png(width: int, height: int, pixels: bool = True) -> bytes:
    """A grey RGB PNG; without ``pixels`` only its header is right (what is checked)."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    raw = (b"\x00" + b"\x80" * (3 * width)) * height if pixels else b"?"
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2,
                                                              0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def model(assets: str) -> mjcf.RootElement:
    return mjcf.from_xml_string(f"<mujoco><asset>{assets}</asset></mujoco>")


def test_defaults() -> None:
    limits = mjcf.CompileLimits()
    assert (limits.max_texture_pixels, limits.max_hfield_samples, limits.max_mesh_vertices,
            limits.max_flex_points, limits.max_replicated_elements) == (
        1 << 26, 1 << 26, 1 << 14, 1 << 12, 1 << 17)
    render = mjcf.RenderLimits()
    assert (render.max_steps, render.max_offscreen_pixels, render.compile) == (
        1_000_000, 8192 * 8192, mjcf.CompileLimits())


def test_a_huge_builtin_texture_is_refused_before_mujoco_allocates_it() -> None:
    # 130 bytes of MJCF for 81 M pixels (243 MB in MuJoCo; 40000 x 40000 took 4.7 GB).
    m = model('<texture name="t" type="2d" builtin="checker" width="9000" height="9000"/>')
    with pytest.raises(mjcf.CompileError) as info:
        m.compile()
    assert str(info.value) == (
        "asset/texture[t]: width=9000, height=9000 makes 81,000,000 pixels in the model, more "
        "than the limit of 67,108,864 (CompileLimits.max_texture_pixels); to allow it, pass "
        "limits=typed_mjcf.CompileLimits(max_texture_pixels=...) with a larger value")
    assert info.value.path == "asset/texture[t]"


@pytest.mark.parametrize(("shape", "faces"), [("2d", 0), ("cube", 6), ("skybox", 6)])
def test_texture_pixels_are_counted_as_mujoco_allocates_them(shape: str, faces: int) -> None:
    m = model(f'<texture name="t" type="{shape}" builtin="gradient" width="12" height="5"/>')
    pixels = faces * 12 * 12 if faces else 12 * 5
    compiled = m.compile(limits=mjcf.CompileLimits(max_texture_pixels=pixels))
    assert compiled.ntexdata == 3 * pixels  # RGB: the count is MuJoCo's own
    with pytest.raises(mjcf.CompileError, match=rf"{pixels:,} pixels in the model, more than "
                                                rf"the limit of {pixels - 1:,}"):
        m.compile(limits=mjcf.CompileLimits(max_texture_pixels=pixels - 1))


def test_a_texture_sized_by_its_default_class_is_counted() -> None:
    m = mjcf.from_xml_string(
        '<mujoco><default><texture builtin="flat" width="10" height="10"/></default>'
        '<asset><texture name="t" type="2d"/></asset></mujoco>')
    assert m.compile(limits=mjcf.CompileLimits(max_texture_pixels=100)).ntexdata == 300
    with pytest.raises(mjcf.CompileError, match=r"texture\[t\]: width=10, height=10 makes 100"):
        m.compile(limits=mjcf.CompileLimits(max_texture_pixels=99))


def test_the_limit_counts_all_textures_and_names_the_one_past_it() -> None:
    m = model('<texture name="a" type="2d" builtin="flat" width="10" height="10"/>'
              '<texture name="b" type="2d" builtin="flat" width="10" height="10"/>')
    with pytest.raises(mjcf.CompileError, match=r"^asset/texture\[b\]: .* makes 200 pixels"):
        m.compile(limits=mjcf.CompileLimits(max_texture_pixels=150))


def test_hfield_samples_are_counted_as_mujoco_allocates_them() -> None:
    m = model('<hfield name="h" nrow="30" ncol="40" size="1 1 1 1"/>')
    assert m.compile(limits=mjcf.CompileLimits(max_hfield_samples=1200)).nhfielddata == 1200
    with pytest.raises(mjcf.CompileError, match=r"^asset/hfield\[h\]: nrow=30, ncol=40 makes "
                                                r"1,200 samples .*max_hfield_samples"):
        m.compile(limits=mjcf.CompileLimits(max_hfield_samples=1199))


def test_a_small_png_declaring_a_huge_picture_is_refused_before_decoding() -> None:
    # A 30000 x 30000 PNG of 2.6 MB took 2.7 GB to compile: the header alone is read.
    m = model('<texture name="t" type="2d"/>')
    m.asset.texture[0].file = mjcf.Asset(png(30000, 30000, pixels=False), ".png")
    with pytest.raises(mjcf.CompileError, match=r"^asset/texture\[t\]: file=.* \(a PNG of "
                                                r"30000 x 30000\) makes 900,000,000 pixels .*"
                                                r"CompileLimits\.max_texture_pixels"):
        m.compile()


def test_png_files_on_disk_count_for_textures_and_hfields(tmp_path: Path) -> None:
    (tmp_path / "small.png").write_bytes(png(20, 10))
    (tmp_path / "m.xml").write_text(
        '<mujoco><asset><texture name="t" type="2d" file="small.png"/>'
        '<hfield name="h" file="small.png" size="1 1 1 1"/></asset></mujoco>')
    m = mjcf.from_path(tmp_path / "m.xml")
    compiled = m.compile(limits=mjcf.CompileLimits(max_texture_pixels=200,
                                                   max_hfield_samples=200))
    assert (compiled.ntexdata, compiled.nhfielddata) == (600, 200)  # as MuJoCo decodes it
    with pytest.raises(mjcf.CompileError, match=r"texture\[t\]: file='small.png' \(a PNG of "
                                                r"20 x 10\) makes 200 pixels"):
        m.compile(limits=mjcf.CompileLimits(max_texture_pixels=199))
    with pytest.raises(mjcf.CompileError, match=r"hfield\[h\]: file='small.png' .* 200 samples"):
        m.compile(limits=mjcf.CompileLimits(max_hfield_samples=199))


def test_limits_must_be_positive_whole_numbers_of_the_right_class() -> None:
    with pytest.raises(mjcf.InvalidValueError, match=r"CompileLimits.max_texture_pixels must "
                                                     r"be at least 1"):
        mjcf.CompileLimits(max_texture_pixels=0)
    with pytest.raises(InvalidTypeError, match=r"RenderLimits.max_steps must be an int"):
        mjcf.RenderLimits(max_steps=1.5)  # type: ignore[arg-type]
    with pytest.raises(InvalidTypeError, match=r"limits must be a typed_mjcf.CompileLimits"):
        model("").compile(limits=mjcf.ParseLimits())  # type: ignore[arg-type]


def test_a_tiny_timestep_is_refused_before_rendering_steps_it() -> None:
    # render(time=0.01) stepped 10**7 times; the CLI's --time 1e12 ran until killed.
    m = mjcf.from_xml_string('<mujoco><option timestep="1e-9"/></mujoco>')
    with pytest.raises(mjcf.RenderError) as info:
        m.render(width=8, height=8, time=0.01)
    assert str(info.value) == (
        "render: time=0.01 at the model's timestep of 1e-09 s is 10,000,000 steps, more than "
        "the limit of 1,000,000 (RenderLimits.max_steps); to allow it, pass "
        "limits=typed_mjcf.RenderLimits(max_steps=...) with a larger value")


def test_the_step_limit_is_exact_and_raisable() -> None:
    m = mjcf.from_xml_string('<mujoco><option timestep="0.001"/></mujoco>')
    assert m.render(width=8, height=8, time=0.01, limits=mjcf.RenderLimits(max_steps=10)).shape == (8, 8, 3)
    with pytest.raises(mjcf.RenderError, match=r"is 10 steps, more than the limit of 9"):
        m.render(width=8, height=8, time=0.01, limits=mjcf.RenderLimits(max_steps=9))


def test_a_huge_offscreen_buffer_the_model_asks_for_is_refused() -> None:
    m = mjcf.from_xml_string(
        '<mujoco><visual><global offwidth="100000" offheight="100000"/></visual></mujoco>')
    with pytest.raises(mjcf.RenderError, match=r"model's <visual><global offwidth=100000 "
                                               r"offheight=100000> is 100000 x 100000, "
                                               r"10,000,000,000 pixels, more than the limit of "
                                               r"67,108,864 \(RenderLimits.max_offscreen_pixels\)"):
        m.render(width=8, height=8)
    small = mjcf.from_xml_string('<mujoco/>')
    with pytest.raises(mjcf.RenderError, match=r"is 640 x 480, 307,200 pixels"):
        small.render(width=8, height=8, limits=mjcf.RenderLimits(max_offscreen_pixels=640 * 480 - 1))


def test_render_compiles_within_its_compile_limits() -> None:
    m = model('<texture name="t" type="2d" builtin="flat" width="10" height="10"/>')
    limits = mjcf.RenderLimits(compile=mjcf.CompileLimits(max_texture_pixels=99))
    with pytest.raises(mjcf.CompileError, match=r"max_texture_pixels"):
        m.render(width=8, height=8, limits=limits)


def test_the_render_command_refuses_a_long_simulation_in_one_line(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "m.xml").write_text('<mujoco><option timestep="0.001"/></mujoco>')
    assert main(["render", str(tmp_path / "m.xml"), "-o", str(tmp_path / "m.png"),
                 "--time", "1e12"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1
    assert "1,000,000,000,000,000 steps, more than the limit of 1,000,000" in err


def test_every_corpus_model_compiles_within_the_default_limits() -> None:
    """The defaults are generous: every corpus model MuJoCo compiles uses at most a quarter
    of each (measured: 5,680,374 texture pixels in jumping_ball_with_head.xml, 40,401 hfield
    samples in quadruped.xml; no corpus file has a builtin mesh, a flexcomp or a replicate:
    the examples of MuJoCo's documentation are 625 vertices, 384 points and 2 copies)."""
    limits = mjcf.CompileLimits()
    most = dict.fromkeys(limits.__dataclass_fields__, 0)
    checked = 0
    for ident, path in CORPUS:
        try:
            compiled(ident, path)
        except pytest.skip.Exception:
            continue  # MuJoCo refuses it by itself (test_corpus.py names them)
        m = mjcf.from_path(path, files=corpus_files(ident, path))
        found = totals(m)
        for name in most:
            most[name] = max(most[name], found[name])
        check_compile(m, limits)
        checked += 1
    assert checked > 50
    for name, count in most.items():
        assert count * 4 <= getattr(limits, name), most


def test_check_compile_reports_the_limit_at_the_element(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "m.xml").write_text(
        '<mujoco>\n<asset>\n<texture name="t" type="2d" builtin="checker" width="9000" '
        'height="9000"/>\n</asset>\n</mujoco>\n')
    assert main(["check", "--compile", str(tmp_path / "m.xml")]) == 1
    out = capsys.readouterr().out
    assert ":3: compile: asset/texture[t]: width=9000, height=9000 makes 81,000,000 " \
           "pixels" in out, out


def body(xml: str) -> mjcf.RootElement:
    return mjcf.from_xml_string(f"<mujoco><worldbody>{xml}</worldbody></mujoco>")


def test_a_builtin_mesh_of_many_vertices_is_refused_before_mujoco_makes_it() -> None:
    # 60 bytes of MJCF: a cone of nvert 10000 compiled for more than 100 s (MuJoCo 4.0.0).
    m = model('<mesh name="m" builtin="cone" params="100000 0.5"/>')
    with pytest.raises(mjcf.CompileError) as info:
        m.compile()
    assert str(info.value) == (
        "asset/mesh[m]: params='100000 0.5' (a cone of nvert 100000) makes 200,000 vertices "
        "in the model, more than the limit of 16,384 (CompileLimits.max_mesh_vertices); to "
        "allow it, pass limits=typed_mjcf.CompileLimits(max_mesh_vertices=...) with a "
        "larger value")
    assert info.value.path == "asset/mesh[m]"


@pytest.mark.parametrize(("shape", "params"), [
    ("cone", "7 0.5"), ("supertorus", "7 0.5 1 1"), ("wedge", "7 3 90 45 0"),
    ("plate", "10 20")])
def test_builtin_mesh_vertices_are_counted_as_mujoco_makes_them(shape: str,
                                                                 params: str) -> None:
    m = model(f'<mesh name="m" builtin="{shape}" params="{params}"/>')
    vertices = totals(m)["max_mesh_vertices"]
    assert m.compile(limits=mjcf.CompileLimits(max_mesh_vertices=vertices)).nmeshvert == vertices
    with pytest.raises(mjcf.CompileError, match=rf"a {shape} of .* makes {vertices} vertices"):
        m.compile(limits=mjcf.CompileLimits(max_mesh_vertices=vertices - 1))


def test_a_supersphere_is_counted_at_least_as_mujoco_makes_it() -> None:
    m = model('<mesh name="m" builtin="supersphere" params="7 1 1"/>')
    assert totals(m)["max_mesh_vertices"] == 49
    assert m.compile().nmeshvert == 44  # resolution x (resolution - 1) + 2


def test_a_flexcomp_of_many_points_is_refused_before_mujoco_makes_them() -> None:
    # a 20 x 20 x 20 grid compiled for 45 s, 40 x 40 x 40 for more than 100 s
    m = body('<flexcomp name="f" type="grid" count="40 40 40" spacing="0.1 0.1 0.1" '
             'dim="3"/>')
    with pytest.raises(mjcf.CompileError) as info:
        m.compile()
    assert str(info.value) == (
        "worldbody/flexcomp[f]: count=40 40 40 makes 64,000 points in the model, more than "
        "the limit of 4,096 (CompileLimits.max_flex_points); to allow it, pass "
        "limits=typed_mjcf.CompileLimits(max_flex_points=...) with a larger value")


def test_flexcomp_points_are_counted_as_mujoco_makes_them() -> None:
    m = body('<flexcomp name="f" type="grid" count="5 4 3" spacing="0.1 0.1 0.1" dim="3" '
             'rigid="true"/>')
    assert m.compile(limits=mjcf.CompileLimits(max_flex_points=60)).nflexvert == 60
    with pytest.raises(mjcf.CompileError, match=r"count=5 4 3 makes 60 points"):
        m.compile(limits=mjcf.CompileLimits(max_flex_points=59))


def test_nested_replicates_are_refused_past_the_copies_limit() -> None:
    # 300 copies of 300 copies of a geom: 16 s and 772 MB in MuJoCo 4.0.0
    m = body('<replicate count="400" offset="0 0 1"><replicate count="400" offset="1 0 0">'
             '<geom size="0.1"/></replicate></replicate>')
    with pytest.raises(mjcf.CompileError) as info:
        m.compile()
    assert str(info.value) == (
        "worldbody/replicate[0]/replicate[0]: count=400 (what it holds compiled 160,000 times) "
        "makes 159,999 copied elements in the model, more than the limit of 131,072 "
        "(CompileLimits.max_replicated_elements); to allow it, pass "
        "limits=typed_mjcf.CompileLimits(max_replicated_elements=...) with a larger value")


def test_replicated_elements_are_counted_as_mujoco_copies_them() -> None:
    m = body('<replicate count="3" offset="0 0 1"><replicate count="4" offset="1 0 0">'
             '<body><geom size="0.1"/></body></replicate></replicate>'
             '<replicate count="2" offset="0 1 0"><body name="b"><flexcomp name="f" type="grid" '
             'count="2 2 1" spacing="0.1 0.1 0.1" dim="2" rigid="true"/></body></replicate>')
    copies = totals(m)["max_replicated_elements"]
    compiled = m.compile(limits=mjcf.CompileLimits(max_replicated_elements=copies,
                                                   max_flex_points=8))
    # every element beyond the first of each: the world and two bodies, a geom, a flex
    assert copies == (compiled.nbody - 3) + (compiled.ngeom - 1) + (compiled.nflex - 1)
    assert compiled.nflexvert == 8  # a flexcomp's points count once per copy
    with pytest.raises(mjcf.CompileError, match=r"count=2 \(what it holds compiled 2 times\)"):
        m.compile(limits=mjcf.CompileLimits(max_replicated_elements=copies - 1,
                                            max_flex_points=8))
    with pytest.raises(mjcf.CompileError, match=r"makes 8 points"):
        m.compile(limits=mjcf.CompileLimits(max_flex_points=7))


def test_to_spec_is_bounded_by_the_compile_limits() -> None:
    m = model('<texture name="t" type="2d" builtin="checker" width="9000" height="9000"/>')
    with pytest.raises(mjcf.CompileError, match=r"max_texture_pixels"):
        m.to_spec()
    raised = mjcf.CompileLimits(max_texture_pixels=81_000_000)
    small = model('<texture name="t" type="2d" builtin="flat" width="10" height="10"/>')
    assert small.to_spec(limits=mjcf.CompileLimits(max_texture_pixels=100)).textures
    with pytest.raises(mjcf.CompileError, match=r"makes 100 pixels"):
        small.to_spec(limits=mjcf.CompileLimits(max_texture_pixels=99))
    assert raised.max_texture_pixels == 81_000_000


def composed(assets: str) -> mjcf.RootElement:
    """A model with a keyframe and an attached model: its export compiles a layout."""
    parent = mjcf.from_xml_string(
        f'<mujoco><asset>{assets}</asset><worldbody><site name="s"/></worldbody>'
        '<keyframe><key name="k" time="1"/></keyframe></mujoco>')
    child = mjcf.from_xml_string('<mujoco model="c"><worldbody><body name="b"><joint/>'
                                 '<geom size="0.1"/></body></worldbody></mujoco>')
    site = parent.find("site", "s")
    assert site is not None
    site.attach(child)
    return parent


def test_the_keyframe_layout_of_an_export_is_compiled_within_the_limits() -> None:
    m = composed('<texture name="t" type="2d" builtin="checker" width="9000" height="9000"/>')
    with pytest.raises(mjcf.CompileError, match=r"^asset/texture\[t\]: .* \(CompileLimits"
                                                r"\.max_texture_pixels\)"):
        m.to_xml_string()
    small = composed('<texture name="t" type="2d" builtin="flat" width="10" height="10"/>')
    assert 'key name="k"' in small.to_xml_string()
    with pytest.raises(mjcf.CompileError, match=r"makes 100 pixels"):
        small.compile(limits=mjcf.CompileLimits(max_texture_pixels=99))
    assert small.compile(limits=mjcf.CompileLimits(max_texture_pixels=100)).nkey == 1


def test_physics_compiles_within_the_limits_and_bounds_its_offscreen_buffer() -> None:
    from typed_mjcf.physics import Physics

    big = model('<texture name="t" type="2d" builtin="checker" width="9000" height="9000"/>')
    with pytest.raises(mjcf.CompileError, match=r"max_texture_pixels"):
        Physics.from_mjcf_model(big)
    raised = mjcf.CompileLimits(max_texture_pixels=100)
    small = model('<texture name="t" type="2d" builtin="flat" width="10" height="10"/>')
    assert Physics.from_mjcf_model(small, limits=raised).model.ntex == 1
    wide = mjcf.from_xml_string(
        '<mujoco><visual><global offwidth="100000" offheight="100000"/></visual></mujoco>')
    physics = Physics.from_mjcf_model(wide)
    with pytest.raises(mjcf.RenderError, match=r"offwidth=100000 offheight=100000> is 100000 "
                                               r"x 100000, 10,000,000,000 pixels, more than "
                                               r"the limit of 67,108,864 \(RenderLimits"
                                               r"\.max_offscreen_pixels\)"):
        physics.render(8, 8)
    with pytest.raises(mjcf.RenderError, match=r"is 640 x 480, 307,200 pixels"):
        Physics.from_mjcf_model(mjcf.from_xml_string("<mujoco/>")).render(
            8, 8, limits=mjcf.RenderLimits(max_offscreen_pixels=640 * 480 - 1))


def test_the_render_command_raises_a_limit_with_limit(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "m.xml").write_text('<mujoco><option timestep="0.001"/></mujoco>')
    command = ["render", str(tmp_path / "m.xml"), "-o", str(tmp_path / "m.png"), "--size",
               "8x8", "--time", "0.01"]
    assert main([*command, "--limit", "max_steps=9"]) == 2
    assert "is 10 steps, more than the limit of 9" in capsys.readouterr().err
    assert main([*command, "--limit", "max_steps=10", "--limit",
                 "max-texture-pixels=1_000"]) == 0
    assert (tmp_path / "m.png").read_bytes().startswith(b"\x89PNG")


@pytest.mark.parametrize(("given", "said"), [
    ("max_steps", "'max_steps': expected NAME=VALUE"),
    ("max_stepz=3", ("'max_stepz' is not a limit; limits: max_texture_pixels, "
                     "max_hfield_samples, max_mesh_vertices, max_flex_points, "
                     "max_replicated_elements, max_steps, max_offscreen_pixels")),
    ("max_steps=lots", "'max_steps=lots': 'lots' is not a whole number"),
    ("max_steps=0", "'max_steps=0': RenderLimits.max_steps must be at least 1")])
def test_a_wrong_limit_is_a_usage_error(given: str, said: str, tmp_path: Path,
                                        capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as info:
        main(["render", str(tmp_path / "m.xml"), "-o", str(tmp_path / "m.png"),
              "--limit", given])
    assert info.value.code == 2
    assert said in capsys.readouterr().err


def test_check_compile_raises_a_compile_limit_with_limit(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "m.xml").write_text(
        '<mujoco><asset><texture name="t" type="2d" builtin="flat" width="10" height="10"/>'
        '</asset></mujoco>')
    command = ["check", "--compile", str(tmp_path / "m.xml")]
    assert main([*command, "--limit", "max_texture_pixels=99"]) == 1
    assert "makes 100 pixels in the model, more than the limit of 99" in capsys.readouterr().out
    assert main([*command, "--limit", "max_texture_pixels=100"]) == 0
    with pytest.raises(SystemExit):  # check compiles, it does not render
        main([*command, "--limit", "max_steps=10"])
    assert "'max_steps' is not a limit" in capsys.readouterr().err
