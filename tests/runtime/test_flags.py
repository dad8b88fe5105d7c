"""Flags attributes that also take one keyword alone, and flags MuJoCo reads only in order.

``input=`` of ``<general>``, ``<pid>`` and ``<dcmotor>`` (and their ``<default>`` rows) is the
case in MuJoCo 4.0.0: a chart keyword (``expmap``, ``quat``), ``none``, or input tokens
(``pos vel ff voltage pressure``) in that order (``pos ff``); a pid takes neither ``none``,
``voltage`` nor ``pressure``, a dcmotor no ``pressure`` (MuJoCo's compiler refuses them on
those tags). Every form a tag takes is read from files, assigned in Python, written, read
back, and given to MuJoCo, which must take it as the same input signature.
"""

from __future__ import annotations

import runpy
from pathlib import Path

import mujoco
import pytest

import typed_mjcf as mjcf
from typed_mjcf._core.codecs import FlagsCodec, Format, Rejected
from typed_mjcf.cli.to_python import to_python

WORLD = ('<worldbody><body name="b"><joint name="j"/><geom size="0.1"/></body>'
         '</worldbody>')
# what each actuator needs besides its transmission for MuJoCo to read it
NEEDS = {"general": "", "pid": "", "dcmotor": ' motorconst="1" resistance="1"'}
ROWS = ("general", "pid", "dcmotor")
ALONE = ("expmap", "quat", "none")
TOKENS = ("pos", "vel", "ff", "voltage", "pressure")
# the tokens and the keywords alone each tag takes
TAKES: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "general": (TOKENS, ALONE), "orientation": (TOKENS, ALONE),
    "pid": (("pos", "vel", "ff"), ("expmap", "quat")),
    "dcmotor": (("pos", "vel", "ff", "voltage"), ALONE),
}
# every form, as written in a file, and as the property reads it
FORMS: dict[str, str | tuple[str, ...]] = {
    "expmap": "expmap", "quat": "quat", "none": "none",
    "pos": ("pos",), "voltage": ("voltage",), "pos ff": ("pos", "ff"),
    "vel ff": ("vel", "ff"), "pos vel ff voltage": ("pos", "vel", "ff", "voltage"),
    "pressure": ("pressure",), "ff voltage pressure": ("ff", "voltage", "pressure"),
}


def takes(tag: str, text: str) -> bool:
    tokens, alone = TAKES[tag]
    return text in alone or set(text.split()) <= set(tokens)


def actuator_doc(tag: str, value: str) -> str:
    return (f'<mujoco>{WORLD}<actuator><{tag} joint="j"{NEEDS[tag]} input="{value}"/>'
            f'</actuator></mujoco>')


def default_doc(tag: str, value: str) -> str:
    return (f'<mujoco><default><{tag}{NEEDS[tag]} input="{value}"/></default>{WORLD}'
            f'<actuator><{tag} joint="j"/></actuator></mujoco>')


def ctrlspec(value: str | tuple[str, ...]) -> int:
    """The input signature MuJoCo makes of a form (``mjModel.actuator_ctrlspec``)."""
    if value in ("expmap", "quat"):
        return int(getattr(mujoco.mjtCtrlChart, f"mjCHART_{str(value).upper()}"))
    words = (value,) if isinstance(value, str) else value
    return sum(int(getattr(mujoco.mjtCtrlInput, f"mjINPUT_{w.upper()}")) for w in words)


def the_actuator(model: mjcf.RootElement) -> mjcf.General | mjcf.Pid | mjcf.Dcmotor:
    actuator = model.actuator.get_children()[0]
    assert isinstance(actuator, mjcf.General | mjcf.Pid | mjcf.Dcmotor)
    return actuator


# ------------------------------------------------------------------------ the schema


def test_the_grammar_tables_say_which_keywords_go_alone() -> None:
    # <orientation> is read by <general>'s reader too (input="vel" compiles on it)
    for cls in (mjcf.General, mjcf.Pid, mjcf.Dcmotor, mjcf.Orientation, mjcf.DefaultGeneral,
                mjcf.DefaultPid, mjcf.DefaultDcmotor, mjcf.DefaultOrientation):
        spec = cls.spec.by_name["input"]
        tokens, alone = TAKES[cls.spec.tag]
        assert (spec.kind, spec.keywords, spec.alone, spec.ordered) == (
            "flags", tokens, alone, True), cls
        assert spec.describe() == f"flags: {'|'.join(tokens)}, or alone: {'|'.join(alone)}"
    camera = mjcf.Camera.spec.by_name["output"]  # MuJoCo reads camera outputs in any order
    assert (camera.alone, camera.ordered) == ((), False)


# --------------------------------------------------------------------- files and MuJoCo


@pytest.mark.parametrize("in_default", [False, True], ids=["element", "default"])
@pytest.mark.parametrize(("tag", "text"), [(tag, text) for tag in ROWS for text in FORMS
                                           if takes(tag, text)])
def test_each_form_reads_writes_and_reads_back(tag: str, text: str, in_default: bool) -> None:
    xml = default_doc(tag, text) if in_default else actuator_doc(tag, text)
    mujoco.MjSpec.from_string(xml)  # MuJoCo reads it ...
    model = mjcf.from_xml_string(xml)  # ... and so do we
    if not in_default:
        assert the_actuator(model).input == FORMS[text]
    else:
        assert the_actuator(model).resolve("input") == FORMS[text]  # through the class
    written = model.to_xml_string()
    assert f'input="{text}"' in written
    again = mjcf.from_xml_string(written)
    assert again.to_xml_string() == written
    assert mujoco.MjSpec.from_string(written).actuators[0].ctrlspec == ctrlspec(FORMS[text])


# Forms each kind of actuator compiles with (MuJoCo 4.0.0; the reader takes every form on
# each, the compiler refuses e.g. a pid with a voltage input or a fixed-gain general with ff).
COMPILES: list[tuple[str, str | tuple[str, ...]]] = [
    ("general", "expmap"), ("general", "quat"), ("general", ("pos",)), ("general", ("vel",)),
    ("general", ("pressure",)),
    ("pid", "expmap"), ("pid", ("pos", "ff")), ("pid", ("vel", "ff")), ("pid", ("ff",)),
    ("dcmotor", "none"), ("dcmotor", "quat"), ("dcmotor", ("voltage",)),
    ("dcmotor", ("pos", "vel", "ff", "voltage")),
]


@pytest.mark.parametrize(("tag", "value"), COMPILES)
def test_mujoco_compiles_what_we_write_for_each_form(tag: str,
                                                     value: str | tuple[str, ...]) -> None:
    model = mjcf.RootElement()
    body = model.worldbody.add_body(name="b")
    body.add_joint(name="j")
    body.add_geom(size=(0.1,))
    if tag == "general":
        actuator: mjcf.General | mjcf.Pid | mjcf.Dcmotor = model.actuator.add_general(
            joint="j", input=value)
    elif tag == "pid":
        actuator = model.actuator.add_pid(joint="j", kp=1, input=value)
    else:
        actuator = model.actuator.add_dcmotor(joint="j", motorconst=1, resistance=1,
                                              input=value)
    assert actuator.input == value
    compiled = model.compile()
    assert compiled.actuator_ctrlspec.tolist() == [ctrlspec(value)]
    assert model.to_spec().actuators[0].ctrlspec == ctrlspec(value)  # the MjSpec bridge


SERVOS = {
    "position": f'<mujoco>{WORLD}<actuator><position joint="j" kp="1"/></actuator></mujoco>',
    "velocity": f'<mujoco>{WORLD}<actuator><velocity joint="j"/></actuator></mujoco>',
    "cylinder": f'<mujoco>{WORLD}<actuator><cylinder joint="j"/></actuator></mujoco>',
    "pid": actuator_doc("pid", "pos ff"),
    "dcmotor": actuator_doc("dcmotor", "none"),
}


@pytest.mark.parametrize("tag", list(SERVOS))
def test_what_mujoco_writes_for_a_servo_reads_back_as_it_compiles(tag: str) -> None:
    # MjSpec.to_xml() writes every actuator as <general input="...">
    spec = mujoco.MjSpec.from_string(SERVOS[tag])
    expected = spec.compile().actuator_ctrlspec.tolist()
    theirs = spec.to_xml()
    assert "<general" in theirs and "input=" in theirs
    model = mjcf.from_xml_string(theirs)
    assert isinstance(the_actuator(model), mjcf.General)
    assert model.compile().actuator_ctrlspec.tolist() == expected


# ---------------------------------------------------------------- refused, with reasons


@pytest.mark.parametrize(("text", "message"), [
    ("ff pos", ("expected 'pos ff' (MuJoCo reads these keywords only in the order pos, vel, "
                "ff, voltage, pressure)")),
    ("pos expmap", ("expected 'expmap' alone (it cannot be combined with other keywords), or "
                    "keywords from 'pos', 'vel', 'ff', 'voltage', 'pressure'")),
    ("none voltage", "expected 'none' alone (it cannot be combined with other keywords)"),
    ("expmap quat", "expected 'expmap' alone"),
    ("pos pos", "expected each keyword once ('pos' is repeated; MuJoCo refuses that)"),
    ("NONE", "expected 'none' (MuJoCo reads keywords only as its grammar spells them)"),
    ("Pos", "expected 'pos' (MuJoCo reads keywords only as its grammar spells them)"),
    ("nnoe", ("expected keywords from 'pos', 'vel', 'ff', 'voltage', 'pressure', or one of "
              "'expmap', 'quat', 'none' alone (did you mean 'none'?)")),
])
@pytest.mark.parametrize("tag", ["general"])
def test_files_mujoco_refuses_are_refused_saying_why(tag: str, text: str, message: str) -> None:
    xml = actuator_doc(tag, text)
    with pytest.raises(ValueError):
        mujoco.MjSpec.from_string(xml)
    with pytest.raises(mjcf.ParseError) as caught:
        mjcf.from_xml_string(xml)
    assert f"actuator/{tag}[0]: invalid input={text!r} on <{tag}>: {message}" in str(
        caught.value)


@pytest.mark.parametrize(("tag", "text"), [(tag, text) for tag in ("pid", "dcmotor")
                                           for text in FORMS if not takes(tag, text)])
def test_forms_a_tag_does_not_compile_with_are_refused(tag: str, text: str) -> None:
    """The reader takes every form on each tag; the compiler refuses these on this tag
    whatever else the actuator says, and so the library refuses them when reading."""
    xml = actuator_doc(tag, text)
    mujoco.MjSpec.from_string(xml)
    with pytest.raises(ValueError, match=f"{tag} inputs are"):
        mujoco.MjModel.from_xml_string(xml)
    with pytest.raises(mjcf.ParseError, match=f"invalid input={text!r} on <{tag}>"):
        mjcf.from_xml_string(xml)


def test_python_takes_any_case_and_order_and_stores_them_canonically() -> None:
    model = mjcf.from_xml_string(actuator_doc("dcmotor", "pos"))
    pid = the_actuator(model)  # a dcmotor, which takes none
    pid.input = "NONE"
    assert pid.input == "none"
    pid.input = ("ff", "pos", "pos")
    assert pid.input == ("pos", "ff")
    pid.input = "Ff  POS"
    assert pid.input == ("pos", "ff")
    pid.input = ("expmap",)  # one keyword that goes alone, in a collection: that keyword
    assert pid.input == "expmap"
    assert 'input="expmap"' in model.to_xml_string()
    pid.input = None
    assert pid.input is None and "input" not in model.to_xml_string()


@pytest.mark.parametrize(("value", "error", "expected"), [
    (("pos", "expmap"), mjcf.InvalidValueError,
     "expected 'expmap' alone (it cannot be combined with other keywords)"),
    ("none pos", mjcf.InvalidValueError, "expected 'none' alone"),
    ("bogus", mjcf.InvalidValueError,
     ("expected keywords from 'pos', 'vel', 'ff', 'voltage', 'pressure', or one of 'expmap', "
      "'quat', 'none' alone")),
    ("qaut", mjcf.InvalidValueError, "(did you mean 'quat'?)"),
    ((), mjcf.InvalidValueError,
     ("expected at least one keyword from 'pos', 'vel', 'ff', 'voltage', 'pressure', or one "
      "of 'expmap', 'quat', 'none' alone")),
    (3, mjcf.InvalidTypeError, "invalid input=3 on <general>: expected keywords from"),
    (["pos", 1], mjcf.InvalidTypeError, "expected keywords from"),
])
def test_python_refuses_mixing_and_unknown_words(value: object, error: type[Exception],
                                                 expected: str) -> None:
    model = mjcf.from_xml_string(actuator_doc("general", "quat"))
    general = the_actuator(model)
    with pytest.raises(error) as caught:
        setattr(general, "input", value)
    assert expected in str(caught.value)
    assert str(caught.value).startswith("actuator/general[0]: invalid input=")
    assert general.input == "quat"  # a refused value leaves the element as it was


def test_unordered_flags_read_in_any_order_but_each_once() -> None:
    camera = '<mujoco><worldbody><camera output="{}"/></worldbody></mujoco>'
    model = mjcf.from_xml_string(camera.format("depth rgb"))
    cam = model.worldbody.camera[0]
    assert cam.output == ("rgb", "depth")
    assert 'output="rgb depth"' in model.to_xml_string()
    with pytest.raises(mjcf.ParseError, match=r"expected each keyword once \('rgb' is repeated"):
        mjcf.from_xml_string(camera.format("rgb rgb"))
    with pytest.raises(ValueError, match="duplicate keyword"):
        mujoco.MjSpec.from_string(camera.format("rgb rgb"))


def test_the_codec_without_keywords_alone() -> None:
    codec = FlagsCodec(("a", "b"))
    assert codec.accept("B a") == ("a", "b")
    assert codec.parse("b a") == ("a", "b")  # not ordered: any order
    with pytest.raises(Rejected) as caught:
        codec.accept("none")
    assert caught.value.expected == "keywords from 'a', 'b'"
    alone = FlagsCodec(("a", "b"), ("c",), ordered=True)
    assert alone.parse("c") == "c" and alone.write("c", Format()) == "c"
    assert alone.write(alone.parse("a b"), Format()) == "a b"
    with pytest.raises(Rejected, match="in the order a, b"):
        alone.parse("b a")


# --------------------------------------------------------------------- generated code


def test_to_python_writes_a_keyword_alone_as_a_string(tmp_path: Path) -> None:
    source = (f'<mujoco><default><dcmotor input="none"/></default>{WORLD}<actuator>'
              '<general joint="j" input="quat"/><pid joint="j" input="pos ff"/>'
              '<dcmotor joint="j" motorconst="1" resistance="1" input="voltage"/>'
              '</actuator></mujoco>')
    (tmp_path / "m.xml").write_text(source, encoding="utf-8")
    model = mjcf.from_path(tmp_path / "m.xml")
    code = to_python(model, str(tmp_path))
    assert 'input="none"' in code and 'input="quat"' in code
    assert 'input=("pos", "ff")' in code and 'input="voltage"' in code
    module = tmp_path / "m.py"
    module.write_text(code, encoding="utf-8")
    built = runpy.run_path(str(module))["build"]()
    assert isinstance(built, mjcf.RootElement)
    assert built.to_xml_string() == model.to_xml_string()
