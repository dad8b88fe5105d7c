"""What MuJoCo Warp refuses, element by element, learnt from Warp's own put_model: the
Python call and ``typed-mjcf check --backend warp``."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from typed_mjcf.cli import main
from typed_mjcf.warp import put_worlds, warp_refusals


def _model() -> tuple[mjcf.RootElement, mjcf.Joint]:
    model = mjcf.RootElement(model="refused")
    model.worldbody.add_geom(type="plane", size=(1, 1, 0.1))
    body = model.worldbody.add_body(name="b", pos=(0, 0, 0.2))
    hinge = body.add_joint(name="hinge", type="hinge")
    body.add_geom(type="sphere", size=(0.1,))
    return model, hinge


def _pgs(model: mjcf.RootElement, _: mjcf.Joint) -> None:
    model.option.solver = "PGS"


def _midphase(model: mjcf.RootElement, _: mjcf.Joint) -> None:
    model.option.flag.midphase = "disable"


def _fwdinv(model: mjcf.RootElement, _: mjcf.Joint) -> None:
    model.option.flag.fwdinv = "enable"


def _pid(model: mjcf.RootElement, hinge: mjcf.Joint) -> None:
    model.actuator.add_pid(name="servo", joint=hinge, kp=1)


def _sleep_with_cg(model: mjcf.RootElement, _: mjcf.Joint) -> None:
    model.option.solver = "CG"
    model.option.flag.sleep = "enable"


def _all_of_them(model: mjcf.RootElement, hinge: mjcf.Joint) -> None:
    _pgs(model, hinge)
    _midphase(model, hinge)
    _pid(model, hinge)


# each model: what it sets, and the (path, attribute, Warp's words) put_model refuses
CASES: dict[str, tuple[Callable[[mjcf.RootElement, mjcf.Joint], None],
                       list[tuple[str, str | None, str]]]] = {
    "solver": (_pgs, [("option", "solver", "mjSOL_PGS is unsupported")]),
    "disable flag": (_midphase, [("option/flag", "midphase",
                                  "mjDSBL_MIDPHASE is unsupported")]),
    "enable flag": (_fwdinv, [("option/flag", "fwdinv", "mjENBL_FWDINV is unsupported")]),
    "actuator": (_pid, [("actuator/pid[servo]", None, "['mjGAIN_PID'] not supported")]),
    # two settings together: either alone is fine
    "sleep without Newton": (_sleep_with_cg, [
        ("option", "solver", "sleeping requires the Newton solver"),
        ("option/flag", "sleep", "sleeping requires the Newton solver")]),
    # several refusals: put_model stops at the first; each is found
    "several": (_all_of_them, [
        ("actuator/pid[servo]", None, "['mjGAIN_PID'] not supported"),
        ("option", "solver", "mjSOL_PGS is unsupported"),
        ("option/flag", "midphase", "mjDSBL_MIDPHASE is unsupported")]),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_every_refusal_of_put_model_is_found_at_its_element(case: str) -> None:
    change, expected = CASES[case]
    model, hinge = _model()
    change(model, hinge)
    before = model.to_xml_string()
    found = warp_refusals(model)
    assert sorted((r.path, r.attribute) for r in found) == sorted(
        (path, attribute) for path, attribute, _ in expected)
    for refusal in found:
        words = next(w for p, a, w in expected if (p, a) == (refusal.path, refusal.attribute))
        assert words in refusal.message, refusal
    assert model.to_xml_string() == before  # asked on copies


def test_a_model_warp_runs_has_no_refusal() -> None:
    model, _ = _model()
    assert warp_refusals(model) == []
    worlds = put_worlds(model, nworld=2, device="cpu")  # and Warp takes it indeed
    assert worlds.nworld == 2


def test_check_backend_warp_reports_each_refusal_at_its_line(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    model, hinge = _model()
    _all_of_them(model, hinge)
    path = tmp_path / "refused.xml"
    path.write_text(model.to_xml_string(), encoding="utf-8")
    assert main(["check", "--backend", "warp", str(path)]) == 1
    lines = capsys.readouterr().out.splitlines()
    text = model.to_xml_string().splitlines()
    pid_line = next(i for i, line in enumerate(text, 1) if "<pid" in line)
    option_line = next(i for i, line in enumerate(text, 1) if "<option" in line)
    refuses = "MuJoCo Warp refuses it (NotImplementedError:"
    assert lines == [
        (f"{path}:{pid_line}: warp: actuator/pid[servo]: {refuses} ['mjGAIN_PID'] not "
         f"supported.)"),
        f"{path}:{option_line}: warp: option: solver: {refuses} mjSOL_PGS is unsupported.)",
        (f"{path}:{option_line + 1}: warp: option/flag: midphase: {refuses} mjDSBL_MIDPHASE "
         f"is unsupported.)"),
        "checked 1 file: 3 errors, 0 warnings"]


def test_check_backend_warp_passes_a_model_warp_runs(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    model, _ = _model()
    path = tmp_path / "runs.xml"
    path.write_text(model.to_xml_string(), encoding="utf-8")
    assert main(["check", "--backend", "warp", str(path)]) == 0
    assert capsys.readouterr().out == "checked 1 file: 0 errors, 0 warnings\n"
