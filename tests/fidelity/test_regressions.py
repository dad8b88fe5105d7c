"""Regressions from the property tests and the parser sweeps: concrete models.

Each case is MJCF that MuJoCo 4.0.0's parser refuses (checked every run). The library must
refuse it too: at assignment (so parsing raises) or in ``validate()``. Cases the library
does not refuse yet are listed in ``KNOWN_GAPS`` with the cause; they are reported as xfail,
and fail once fixed so that the entry gets removed.
"""

from __future__ import annotations

import mujoco
import pytest

import typed_mjcf as mjcf
from typed_mjcf._model.validate import validate

WORLD = ('<worldbody><body name="b"><joint name="j"/><geom size="0.1"/>'
         '<site name="s"/><site name="s2"/></body></worldbody>')


def doc(*parts: str) -> str:
    return "<mujoco>" + "".join(parts) + "</mujoco>"


CASES: dict[str, str] = {
    # --- refused by validate() -------------------------------------------------------------
    "orientation-exclusive": doc('<worldbody><body quat="1 0 0 0" euler="0 0 0"/></worldbody>'),
    "default-camera-exclusive": doc('<default><camera fovy="45" sensorsize="1 1"/></default>'),
    "connect-oneof": doc('<equality><connect anchor="0 0 0"/></equality>'),
    "framepos-together": doc(WORLD, '<sensor><framepos objtype="body" objname="b" '
                                    'reftype="body"/></sensor>'),
    "replicate-count": doc('<worldbody><replicate><geom size="1"/></replicate></worldbody>'),
    "undefined-class": doc('<worldbody><geom class="nope" size="1"/></worldbody>'),
    "flexcomp-unknown-material": doc('<asset><material name="red"/></asset><worldbody><flexcomp '
                                     'type="grid" count="2 2 1" spacing="1 1 1" dim="2" '
                                     'name="f" material="red nope"/></worldbody>'),
    "flex-unknown-material": doc('<worldbody><body name="b1"/><body name="b2"/><body '
                                 'name="b3"/></worldbody><deformable><flex name="f" dim="2" '
                                 'body="b1 b2 b3" vertex="0 0 0 1 0 0 0 1 0" element="0 1 2" '
                                 'material="nope"/></deformable>'),
    "undefined-childclass": doc('<worldbody><frame childclass="nope"/></worldbody>'),
    "nested-default-without-class": doc('<default><default/></default>'),
    "renamed-main-class": doc('<default class="base"/>'),
    "joint-in-world-frame": doc('<worldbody><frame><joint/></frame></worldbody>'),
    "inertial-in-world-frame": doc('<worldbody><frame><inertial pos="0 0 0" mass="1"/>'
                                   '</frame></worldbody>'),
    "joint-in-replicate": doc('<worldbody><body><replicate count="2"><frame><joint/></frame>'
                              '</replicate></body></worldbody>'),
    "self-attach-without-body": doc('<worldbody><body><attach prefix="p"/></body></worldbody>'),
    # found by test_properties: a named clock is copied per replicate under one name
    "named-clock-with-two-replicates": doc(
        '<worldbody><replicate count="1"/><replicate count="1"/></worldbody>',
        '<sensor><clock name="c"/></sensor>'),
    # --- value ranges (found by test_properties and the sweeps) ----------------------------
    "statistic-extent-zero": doc('<statistic extent="0"/>'),
    "global-realtime-zero": doc('<visual><global realtime="0"/></visual>'),
    "map-znear-zero": doc('<visual><map znear="0"/></visual>'),
    "size-nuser-below-minus-one": doc('<size nuser_body="-2"/>'),
    "skin-group-above-5": doc('<asset><skin group="6" vertex="0 0 0" face="0 0 0"/></asset>'),
    "zero-quaternion": doc('<worldbody><geom size="1" quat="0 0 0 0"/></worldbody>'),
    "negative-kv": doc(WORLD, '<actuator><position joint="j" kv="-1"/></actuator>'),
    "negative-dampratio": doc('<default><position dampratio="-1"/></default>'),
    "negative-tausmooth": doc(WORLD, '<actuator><muscle joint="j" tausmooth="-1"/></actuator>'),
    "negative-adhesion-gain": doc(WORLD, '<actuator><adhesion body="b" gain="-1"/></actuator>'),
    "negative-damper-ctrlrange": doc(WORLD, '<actuator><damper joint="j" ctrlrange="-1 1"/>'
                                            '</actuator>'),
    "maxhullvert-below-4": doc('<default><mesh maxhullvert="2"/></default>'),
    "negative-nuser-sensor": doc('<size nuser_sensor="-3"/>'),
    "dcmotor-zero-motorconst": doc(WORLD, '<actuator><dcmotor joint="j" motorconst="0" '
                                          'resistance="1"/></actuator>'),
    "default-negative-damper-kv": doc('<default><damper kv="-1"/></default>'),
    "default-negative-adhesion-gain": doc('<default><adhesion gain="-0.5"/></default>'),
    # --- numbers C's strtod does not read, though Python's float() and int() do -----------
    "number-with-underscore": doc('<worldbody><site pos="1_0 0 0"/></worldbody>'),
    "number-with-non-ascii-digit": doc('<worldbody><site pos="\u0661 0 0"/></worldbody>'),
    "int-in-hexadecimal": doc('<worldbody><geom size="1" condim="0x3"/></worldbody>'),
    "double-too-large": doc('<worldbody><site pos="1e400 0 0"/></worldbody>'),
    "float-too-large": doc('<worldbody><geom size="1" rgba="1e39 0 0 1"/></worldbody>'),
    # --- keywords in another case (Python assignment takes any case, as dm_control does) ---
    "keyword-in-upper-case": doc('<worldbody><geom type="CAPSULE" size="1 1"/></worldbody>'),
    "bool-in-title-case": doc('<worldbody><body mocap="True"/></worldbody>'),
    "flag-in-upper-case": doc('<option><flag contact="DISABLE"/></option>'),
    "headlight-active-5": doc('<visual><headlight active="5"/></visual>'),
    "contact-sensor-num-zero": doc(WORLD, '<sensor><contact body1="b" num="0"/></sensor>'),
    "actuatorgroupdisable-above-30": doc('<option actuatorgroupdisable="31"/>'),
    "actuatorgroupdisable-negative": doc('<option actuatorgroupdisable="-1"/>'),
    "dcmotor-zero-resistance": doc(WORLD, '<actuator><dcmotor joint="j" motorconst="1" '
                                          'resistance="0"/></actuator>'),
    # --- arity and keywords ----------------------------------------------------------------
    "frame-scale-two-values": doc('<worldbody><frame scale="1 2"/></worldbody>'),
    "compiler-coordinate-global": doc('<compiler coordinate="global"/>'),
    # --- attributes the parser requires ----------------------------------------------------
    "fixed-joint-coef": doc(WORLD, '<tendon><fixed><joint joint="j"/></fixed></tendon>'),
    "pulley-divisor": doc(WORLD, '<tendon><spatial><site site="s"/><pulley/><site site="s2"/>'
                                 '</spatial></tendon>'),
    "user-sensor-dim": doc('<sensor><user/></sensor>'),
    "extension-plugin-plugin": doc('<extension><plugin/></extension>'),
    "plugin-config-value": doc('<extension><plugin plugin="mujoco.pid"><instance name="i">'
                               '<config key="k"/></instance></plugin></extension>'),
    "material-layer-texture": doc('<asset><material name="m"><layer role="rgb"/></material>'
                                  '</asset>'),
    "builtin-mesh-params": doc('<asset><mesh name="m" builtin="sphere"/></asset>'),
    "numeric-size-or-data": doc('<custom><numeric name="n"/></custom>'),
    "text-data": doc('<custom><text name="t"/></custom>'),
    "dcmotor-constants": doc('<default><dcmotor/></default>'),
    # --- attributes the parser refuses together --------------------------------------------
    "kv-and-dampratio": doc(WORLD, '<actuator><position joint="j" kv="1" dampratio="1"/>'
                                   '</actuator>'),
    "default-kv-and-dampratio": doc('<default><pid kv="1" dampratio="1"/></default>'),
    "ctrlrange-and-inheritrange": doc(WORLD, '<actuator><position joint="j" ctrlrange="0 1" '
                                             'inheritrange="1"/></actuator>'),
    "actrange-and-inheritrange": doc(WORLD, '<actuator><intvelocity joint="j" actrange="0 1" '
                                            'inheritrange="1"/></actuator>'),
    "posrange-and-inheritrange": doc(WORLD, '<actuator><pid joint="j" posrange="0 1" '
                                            'inheritrange="1"/></actuator>'),
    "cranklength-without-cranksite": doc(WORLD, '<actuator><motor joint="j" cranklength="1"/>'
                                                '</actuator>'),
    "slidersite-without-cranksite": doc(WORLD, '<actuator><motor joint="j" slidersite="s"/>'
                                               '</actuator>'),
    "refsite-without-site": doc(WORLD, '<actuator><motor joint="j" refsite="s"/></actuator>'),
    # found by test_properties: the actuator rows of a default class share one actuator
    "default-general-sets-adhesion-gain": doc(
        '<default><general gainprm="-1"/></default>', WORLD,
        '<actuator><adhesion body="b"/></actuator>'),
    "default-texture-gridlayout": doc('<default><texture gridlayout="aa"/></default>'),
    # --- input= of <general>, <pid>, <dcmotor>: one reader, measured with MuJoCo 4.0.0 -----
    "input-out-of-order": doc(WORLD, '<actuator><pid joint="j" input="ff pos"/></actuator>'),
    "default-input-out-of-order": doc('<default><general input="vel pos"/></default>'),
    "input-chart-with-tokens": doc(WORLD, '<actuator><general joint="j" input="pos expmap"/>'
                                          '</actuator>'),
    "input-none-with-tokens": doc(WORLD, '<actuator><dcmotor joint="j" motorconst="1" '
                                         'resistance="1" input="none voltage"/></actuator>'),
    "input-two-charts": doc(WORLD, '<actuator><pid joint="j" input="expmap quat"/></actuator>'),
    "input-repeated-token": doc(WORLD, '<actuator><pid joint="j" input="pos pos"/></actuator>'),
    "input-none-in-upper-case": doc(WORLD, '<actuator><general joint="j" input="NONE"/>'
                                           '</actuator>'),
    # --- data= of <contact> and <rangefinder>: flags read in enum order only ----------------
    "contact-data-out-of-order": doc(WORLD, '<sensor><contact body1="b" data="force found"/>'
                                            '</sensor>'),
    "contact-data-velocities-swapped": doc(WORLD, '<sensor><contact body1="b" '
                                                  'data="angvel linvel"/></sensor>'),
    "rangefinder-data-out-of-order": doc('<worldbody><site name="s"/></worldbody><sensor>'
                                         '<rangefinder site="s" data="depth dist"/></sensor>'),
    "rangefinder-data-repeated": doc('<worldbody><site name="s"/></worldbody><sensor>'
                                     '<rangefinder site="s" data="dist dist"/></sensor>'),
    # --- keyword lists the grammar shares between tags, narrower on one (MuJoCo's compiler
    # refuses these; tests/fidelity/test_shared_keywords.py probes every shared list) -------
    "site-type-plane": doc('<worldbody><site type="plane" size="1 1 1"/></worldbody>'),
    "site-type-hfield": doc('<worldbody><site type="hfield" size="1 1 1"/></worldbody>'),
    "pid-input-none": doc(WORLD, '<actuator><pid joint="j" input="none"/></actuator>'),
    "pid-input-voltage": doc(WORLD, '<actuator><pid joint="j" input="voltage"/></actuator>'),
    "dcmotor-input-pressure": doc(WORLD, '<actuator><dcmotor joint="j" motorconst="1" '
                                         'resistance="1" input="pressure"/></actuator>'),
}

# What MuJoCo says for each case (the first line of its error, after "XML Error: ").
MESSAGES: dict[str, str] = {
    'actrange-and-inheritrange': 'actrange and inheritrange cannot both be defined',
    'actuatorgroupdisable-above-30': 'disabled actuator group value cannot exceed 30',
    'actuatorgroupdisable-negative': 'disabled actuator group value must be non-negative',
    'builtin-mesh-params': "required attribute missing: 'params'",
    'compiler-coordinate-global': 'global coordinates no longer supported',
    'connect-oneof': "one of ('site1', 'site2'), ('body1', 'anchor') must be specified",
    'contact-sensor-num-zero': "'num' must be positive in sensor",
    'cranklength-without-cranksite': 'cranklength and slidersite can only be used in slidercrank transmission',
    'ctrlrange-and-inheritrange': 'ctrlrange and inheritrange cannot both be defined',
    'dcmotor-constants': 'DC motor: motor constant K must be positive',
    'dcmotor-zero-resistance': 'DC motor: resistance R must be positive',
    'default-camera-exclusive': "at most one of 'fovy', 'sensorsize' can be specified",
    'default-general-sets-adhesion-gain': 'adhesion gain cannot be negative',
    'default-texture-gridlayout': 'gridlayout length must match gridsize',
    'extension-plugin-plugin': "required attribute missing: 'plugin'",
    'fixed-joint-coef': "required attribute missing: 'coef'",
    'frame-scale-two-values': "attribute 'scale' must have 1 or 3 values",
    'framepos-together': "attributes 'reftype', 'refname' must be specified together",
    'global-realtime-zero': 'realtime must be greater than 0',
    'headlight-active-5': "invalid keyword: '5'",
    'inertial-in-world-frame': 'World body cannot have inertia',
    'joint-in-replicate': 'joint cannot be a direct child of replicate',
    'joint-in-world-frame': 'World body cannot have joints',
    'kv-and-dampratio': 'kv and dampratio cannot both be defined',
    'map-znear-zero': 'znear must be strictly positive',
    'material-layer-texture': "required attribute missing: 'texture'",
    'maxhullvert-below-4': 'maxhullvert must be larger than 3',
    'negative-nuser-sensor': 'nuser_sensor must be >= -1',
    'dcmotor-zero-motorconst': 'DC motor: motor constant K must be positive',
    'default-negative-damper-kv': 'damping coefficient cannot be negative',
    'default-negative-adhesion-gain': 'adhesion gain cannot be negative',
    'default-kv-and-dampratio': 'kv and dampratio cannot both be defined',
    'named-clock-with-two-replicates': "repeated name 'c0' in sensor",
    'negative-adhesion-gain': 'adhesion gain cannot be negative',
    'negative-damper-ctrlrange': 'damper control range cannot be negative',
    'negative-dampratio': 'dampratio cannot be negative',
    'negative-kv': 'kv cannot be negative',
    'negative-tausmooth': 'muscle tausmooth cannot be negative',
    'nested-default-without-class': 'empty class name',
    'numeric-size-or-data': 'custom field size must be positive',
    'orientation-exclusive': 'multiple orientation specifiers are not allowed',
    'plugin-config-value': "required attribute missing: 'value'",
    'posrange-and-inheritrange': 'posrange and inheritrange cannot both be defined',
    'pulley-divisor': "required attribute missing: 'divisor'",
    'refsite-without-site': 'refsite can only be used with site transmission',
    'renamed-main-class': "top-level default class 'main' cannot be renamed",
    'replicate-count': "required attribute missing: 'count'",
    'self-attach-without-body': "either 'body' or 'frame' attribute must be specified for self-attach",
    'size-nuser-below-minus-one': 'nuser_body must be >= -1',
    'skin-group-above-5': 'skin group must be between 0 and 5',
    'slidersite-without-cranksite': 'cranklength and slidersite can only be used in slidercrank transmission',
    'statistic-extent-zero': 'extent must be strictly positive',
    'text-data': 'text field cannot be empty',
    'undefined-childclass': 'unknown default childclass',
    'undefined-class': "unknown default class name 'nope'",
    'flexcomp-unknown-material': "unknown material 'nope' in flex",
    'flex-unknown-material': "unknown material 'nope' in flex",
    'user-sensor-dim': "required attribute missing: 'dim'",
    'zero-quaternion': 'zero quaternion is not allowed',
    'number-with-underscore': "bad format in attribute 'pos'",
    'number-with-non-ascii-digit': "bad format in attribute 'pos'",
    'int-in-hexadecimal': "bad format in attribute 'condim'",
    'double-too-large': "number is too large in attribute 'pos'",
    'float-too-large': "number is too large in attribute 'rgba'",
    'keyword-in-upper-case': "invalid keyword: 'CAPSULE'",
    'bool-in-title-case': "invalid keyword: 'True'",
    'flag-in-upper-case': "invalid keyword: 'DISABLE'",
    'input-out-of-order': 'inputs must be listed in canonical order',
    'default-input-out-of-order': 'inputs must be listed in canonical order',
    'input-chart-with-tokens': 'invalid keyword',
    'input-none-with-tokens': 'invalid keyword',
    'input-two-charts': 'invalid keyword',
    'input-repeated-token': 'duplicate keyword',
    'input-none-in-upper-case': 'invalid keyword',
    'contact-data-out-of-order': 'data attributes must be in order',
    'contact-data-velocities-swapped': 'data attributes must be in order',
    'rangefinder-data-out-of-order': 'data attributes must be in order',
    'rangefinder-data-repeated': 'duplicate keyword',
    'site-type-plane': 'hfields and planes not allowed in site',
    'site-type-hfield': 'hfields and planes not allowed in site',
    'pid-input-none': 'pid inputs are a subset of [pos, vel, ff]',
    'pid-input-voltage': 'pid inputs are a subset of [pos, vel, ff]',
    'dcmotor-input-pressure': "dcmotor inputs are 'none' or a subset of [pos, vel, ff, voltage]",
}

_SEMANTIC = "a MuJoCo rule on values that the schema cannot state"
KNOWN_GAPS: dict[str, str] = {
    "zero-quaternion": "a rule on the whole value (not all four zero), not a bound on each number",
    "maxhullvert-below-4": "-1 (no limit) or at least 4: bounds cannot say 'or'",
    "dcmotor-constants": "MuJoCo's default motorconst (0) is refused; the element or its class "
                         "must set it, which no table says (bounds check values set)",
    "frame-scale-two-values": "arity 1..3 in the schema; the parser takes 1 or 3 values",
    "compiler-coordinate-global": "a grammar keyword the parser no longer accepts",
    "default-general-sets-adhesion-gain": _SEMANTIC, "default-texture-gridlayout": _SEMANTIC,
}


# What validate() says for the cases the schema's tables close (schema/facts.toml's bounds,
# required attributes and [[constraint]] entries): the element's path, the rule, the
# attribute, the value and what was expected.
FINDINGS: dict[str, str] = {
    'actrange-and-inheritrange':
        'actuator/intvelocity[0]: exclusive: <intvelocity> may set at most one of actrange | inheritrange; it sets actrange, inheritrange',
    'actuatorgroupdisable-above-30':
        'option: range: <option> actuatorgroupdisable="31": expected each value >= 0 and <= 30 (MuJoCo refuses others)',
    'actuatorgroupdisable-negative':
        'option: range: <option> actuatorgroupdisable="-1": expected each value >= 0 and <= 30 (MuJoCo refuses others)',
    'builtin-mesh-params':
        'asset/mesh[m]: requires: <mesh> sets builtin, which requires params',
    'contact-sensor-num-zero':
        'sensor/contact[0]: range: <contact> num="0": expected > 0 (MuJoCo refuses others)',
    'cranklength-without-cranksite':
        'actuator/motor[0]: requires: <motor> sets cranklength, which requires cranksite',
    'ctrlrange-and-inheritrange':
        'actuator/position[0]: exclusive: <position> may set at most one of ctrlrange | inheritrange; it sets ctrlrange, inheritrange',
    'dcmotor-zero-motorconst':
        'actuator/dcmotor[0]: range: <dcmotor> motorconst="0": expected each value > 0 (MuJoCo refuses others)',
    'dcmotor-zero-resistance':
        'actuator/dcmotor[0]: range: <dcmotor> resistance="0": expected > 0 (MuJoCo refuses others)',
    'default-kv-and-dampratio':
        'default/pid: exclusive: <pid> may set at most one of kv | dampratio; it sets kv, dampratio',
    'default-negative-adhesion-gain':
        'default/adhesion: range: <adhesion> gain="-0.5": expected >= 0 (MuJoCo refuses others)',
    'default-negative-damper-kv':
        'default/damper: range: <damper> kv="-1": expected >= 0 (MuJoCo refuses others)',
    'fixed-joint-coef':
        "tendon/fixed[0]/joint[0]: required-attribute: <joint> requires the attribute 'coef', which is not set",
    'global-realtime-zero':
        'visual/global: range: <global> realtime="0": expected > 0 (MuJoCo refuses others)',
    'kv-and-dampratio':
        'actuator/position[0]: exclusive: <position> may set at most one of kv | dampratio; it sets kv, dampratio',
    'map-znear-zero':
        'visual/map: range: <map> znear="0": expected > 0 (MuJoCo refuses others)',
    'material-layer-texture':
        "asset/material[m]/layer[0]: required-attribute: <layer> requires the attribute 'texture', which is not set",
    'negative-adhesion-gain':
        'actuator/adhesion[0]: range: <adhesion> gain="-1": expected >= 0 (MuJoCo refuses others)',
    'negative-damper-ctrlrange':
        'actuator/damper[0]: range: <damper> ctrlrange="-1 1": expected each value >= 0 (MuJoCo refuses others)',
    'negative-dampratio':
        'default/position: range: <position> dampratio="-1": expected >= 0 (MuJoCo refuses others)',
    'negative-kv':
        'actuator/position[0]: range: <position> kv="-1": expected >= 0 (MuJoCo refuses others)',
    'negative-nuser-sensor':
        'size: range: <size> nuser_sensor="-3": expected >= -1 (MuJoCo refuses others)',
    'negative-tausmooth':
        'actuator/muscle[0]: range: <muscle> tausmooth="-1": expected >= 0 (MuJoCo refuses others)',
    'numeric-size-or-data':
        'custom/numeric[n]: oneof: <numeric> must set all of at least one of size | data',
    'plugin-config-value':
        "extension/plugin[0]/instance[i]/config[0]: required-attribute: <config> requires the attribute 'value', which is not set",
    'posrange-and-inheritrange':
        'actuator/pid[0]: exclusive: <pid> may set at most one of posrange | inheritrange; it sets posrange, inheritrange',
    'pulley-divisor':
        "tendon/spatial[0]/pulley[0]: required-attribute: <pulley> requires the attribute 'divisor', which is not set",
    'refsite-without-site':
        'actuator/motor[0]: requires: <motor> sets refsite, which requires site',
    'size-nuser-below-minus-one':
        'size: range: <size> nuser_body="-2": expected >= -1 (MuJoCo refuses others)',
    'skin-group-above-5':
        'asset/skin[0]: range: <skin> group="6": expected >= 0 and <= 5 (MuJoCo refuses others)',
    'slidersite-without-cranksite':
        'actuator/motor[0]: requires: <motor> sets slidersite, which requires cranksite',
    'statistic-extent-zero':
        'statistic: range: <statistic> extent="0": expected > 0 (MuJoCo refuses others)',
    'text-data':
        "custom/text[t]: required-attribute: <text> requires the attribute 'data', which is not set",
    'user-sensor-dim':
        "sensor/user[0]: required-attribute: <user> requires the attribute 'dim', which is not set",
    'flexcomp-unknown-material':
        "worldbody/flexcomp[f]: unresolved-reference: material='nope' names no material in the model",
    'flex-unknown-material':
        "deformable/flex[f]: unresolved-reference: material='nope' names no material in the model",
}


def mujoco_error(xml: str) -> str | None:
    try:
        mujoco.MjSpec.from_string(xml)
    except ValueError as error:
        return str(error)
    return None


def mujoco_compile_error(xml: str) -> str | None:
    """What MuJoCo says reading ``xml`` or, when it reads it, compiling it."""
    try:
        mujoco.MjModel.from_xml_string(xml)
    except ValueError as error:
        return str(error)
    return None


def library_refuses(xml: str) -> bool:
    try:
        model = mjcf.from_xml_string(xml)
    except mjcf.MjcfError:
        return True  # refused at assignment
    return any(f.severity == "error" for f in validate(model))


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_library_refuses_what_mujoco_refuses(case: str) -> None:
    xml = CASES[case]
    error = mujoco_compile_error(xml)
    assert error is not None, f"MuJoCo now accepts {case}: {xml}"
    assert MESSAGES[case] in error, error
    expect(library_refuses(xml), KNOWN_GAPS.get(case),
           broken=f"{case} is accepted by the library: {xml}",
           closed=f"{case} is refused now: remove it from KNOWN_GAPS")


@pytest.mark.parametrize("case", sorted(FINDINGS))
def test_a_closed_gap_is_one_error_naming_path_attribute_value_and_bounds(case: str) -> None:
    assert case in CASES and case not in KNOWN_GAPS
    findings = [str(f) for f in validate(mjcf.from_xml_string(CASES[case]))
                if f.severity == "error"]
    assert findings == [FINDINGS[case]]


def expect(holds: bool, gap: str | None, *, broken: str, closed: str) -> None:
    """``holds`` must be true, unless ``gap`` says why not yet: then an expected failure,
    which becomes a failure once the gap is closed (so the list of gaps stays true)."""
    if gap is None:
        assert holds, broken
    elif holds:
        pytest.fail(closed)
    else:
        pytest.xfail(gap)


def test_known_gaps_are_cases() -> None:
    assert set(KNOWN_GAPS) <= set(CASES) == set(MESSAGES)


# ----------------------------------------------------------------------------- accepted

# MJCF that MuJoCo accepts (some of it is what MuJoCo itself writes): the library must read
# it and find no error in it.
ACCEPTED: dict[str, str] = {
    "implicit-mesh-name": doc('<asset><mesh file="meshes/part.v2.stl"/></asset>',
                              '<worldbody><geom type="mesh" mesh="part.v2"/></worldbody>'),
    "world-and-main": doc('<worldbody><body name="b"><geom class="main" size="1"/></body>'
                          '</worldbody><contact><exclude body1="world" body2="b"/></contact>'),
    "unnamed-clock-with-two-replicates": doc(
        '<worldbody><replicate count="1"/><replicate count="1"/></worldbody>',
        '<sensor><clock/></sensor>'),
    "joint-in-frame-in-body": doc('<worldbody><body><frame><joint/></frame></body></worldbody>'),
    "inertial-in-replicate-in-world": doc(
        '<worldbody><replicate count="2"><inertial pos="0 0 0" mass="1"/></replicate>'
        '</worldbody>'),
    # numbers C's strtod reads that Python's float() does not, or reads differently
    "hexadecimal-double": doc('<worldbody><site pos="0x1p3 0 -0x.8p0"/></worldbody>'),
    "infinite-and-tiny": doc('<worldbody><site pos="inf -INF 1e-400"/></worldbody>'),
    "double-beyond-float32": doc('<worldbody><site pos="1e39 0 0"/></worldbody>'),
    # found by test_round_trip: what MuJoCo writes for a <pid> and a <dcmotor>
    "general-input-servo-tokens": doc(WORLD, '<actuator><general joint="j" input="pos ff"/>'
                                             '</actuator>'),
    "dcmotor-input-none": doc(WORLD, '<actuator><dcmotor joint="j" motorconst="1" '
                                     'resistance="1" input="none"/></actuator>'),
    # <orientation> has <general>'s input reader (the grammar file says chart keywords only)
    "orientation-input-vel": doc('<worldbody><body><joint type="ball"/><geom size="0.1"/>'
                                 '<site name="s"/><site name="r"/></body></worldbody><actuator>'
                                 '<orientation site="s" refsite="r" input="vel"/></actuator>'),
    # MuJoCo 4.0.0's contact sensor reports velocities (the grammar file lacks them)
    "contact-data-velocities": doc(WORLD, '<sensor><contact body1="b" '
                                          'data="found force linvel angvel"/></sensor>'),
    "rangefinder-data-all": doc('<worldbody><site name="s"/></worldbody><sensor><rangefinder '
                                'site="s" data="dist dir origin point normal depth"/></sensor>'),
    # input= takes a chart keyword, none or servo tokens on each of general, pid, dcmotor
    # (the compiler decides which a kind of actuator can use)
    "general-input-none": doc(WORLD, '<actuator><general joint="j" input="none"/></actuator>'),
    "general-input-expmap": doc(WORLD, '<actuator><general joint="j" input="expmap"/>'
                                       '</actuator>'),
    "pid-input-quat": doc(WORLD, '<actuator><pid joint="j" input="quat"/></actuator>'),
    "dcmotor-input-expmap": doc(WORLD, '<actuator><dcmotor joint="j" motorconst="1" '
                                       'resistance="1" input="expmap"/></actuator>'),
    "dcmotor-input-every-token": doc(WORLD, '<actuator><dcmotor joint="j" motorconst="1" '
                                            'resistance="1" input="pos vel ff voltage"/>'
                                            '</actuator>'),
    # what MuJoCo writes for a <cylinder> (MuJoCo 4.0.0 added the pressure input)
    "general-input-pressure": doc(WORLD, '<actuator><general joint="j" dyntype="filter" '
                                         'input="pressure" biastype="affine"/></actuator>'),
    "default-input-forms": doc('<default><general input="quat"/><default class="a">'
                               '<pid input="expmap"/></default><default class="b">'
                               '<dcmotor motorconst="1" resistance="1" input="vel ff"/>'
                               '</default></default>'),
    # reported from a robot file: inheritrange="0" is off (MuJoCo refuses only a positive
    # one beside a non-zero ctrlrange), also in a class below one that sets it
    "default-inheritrange-off": doc(
        '<default><position inheritrange="1"/><default class="g"><position '
        'ctrlrange="0 0.041" kp="100" kv="10" inheritrange="0"/></default></default>', WORLD,
        '<actuator><position class="g" joint="j"/></actuator>'),
}
ACCEPTED_GAPS: dict[str, str] = {}


def library_accepts(xml: str) -> bool:
    try:
        model = mjcf.from_xml_string(xml)
    except mjcf.MjcfError:
        return False
    return not any(f.severity == "error" for f in validate(model))


@pytest.mark.parametrize("case", sorted(ACCEPTED))
def test_the_library_accepts_what_mujoco_accepts(case: str) -> None:
    xml = ACCEPTED[case]
    assert mujoco_error(xml) is None
    expect(library_accepts(xml), ACCEPTED_GAPS.get(case),
           broken=f"{case} is refused by the library: {xml}",
           closed=f"{case} is accepted now: remove it from ACCEPTED_GAPS")


def test_what_mujoco_writes_for_a_pid_parses() -> None:
    spec = mujoco.MjSpec.from_string(doc(WORLD, '<actuator><pid joint="j" kp="1" '
                                                'input="pos ff"/></actuator>'))
    spec.compile()
    xml = spec.to_xml()
    assert 'input="pos ff"' in xml
    general = mjcf.from_xml_string(xml).find_all("actuator")[0]
    assert isinstance(general, mjcf.General) and general.input == ("pos", "ff")


# ----------------------------------------------------------------------------- round trip


def test_empty_section_inside_a_section_round_trips() -> None:
    # found by test_properties: touching model.option.flag writes <option/>, which parses
    # to an option with no children, which is not written: parse -> export is not a fixed
    # point (and an empty tag is written for nothing)
    model = mjcf.RootElement()
    _ = model.option.flag, model.default.mesh
    xml = model.to_xml_string()
    again = mjcf.from_xml_string(xml).to_xml_string()
    if again != xml:
        pytest.xfail("_export._is_empty_single is not recursive: an empty once-only section "
                     "holding only empty once-only sections is written as an empty tag")
    assert xml == "<mujoco/>\n"
