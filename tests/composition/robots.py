"""Real-robot-shaped models, written as files at test time: an arm, a gripper and a mobile
base, each an MJCF file with its meshes and textures in folders of its own (``meshdir``,
``texturedir``), default classes, keyframes, tendons, sensors and constraints of every kind.

The shapes follow public robots (MuJoCo Menagerie's arms carry a ``home`` key and an
``attachment_site``; its Robotiq 2F-85 couples its fingers with ``<equality><joint>`` and
``<connect>``), made small. Meshes are written by :func:`box_stl` (binary STL) and as OBJ
text, the texture as a 4x4 PNG. Two files are shared across folders on purpose:

- ``screw.stl`` is in the arm's and the gripper's folders with the same bytes, and
- ``base_link.stl`` is in both with different bytes (a different mesh).
"""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import typed_mjcf as mjcf
from tests.support.meshes import box_stl, tetra_obj


def png(width: int, height: int, rgb: tuple[int, int, int]) -> bytes:
    """A one-colour RGB PNG."""
    rows = b"".join(b"\0" + bytes(rgb) * width for _ in range(height))

    def chunk(kind: bytes, data: bytes) -> bytes:
        crc = zlib.crc32(kind + data) & 0xFFFFFFFF
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows))
            + chunk(b"IEND", b""))


SCREW = box_stl(0.01)  # the same bytes in the arm's and the gripper's folders

ARM_XML = """\
<mujoco model="arm">
  <compiler angle="radian" meshdir="assets" texturedir="textures" autolimits="true"/>
  <option integrator="implicitfast"/>
  <default>
    <joint damping="0.5" armature="0.01"/>
    <default class="visual">
      <geom type="mesh" contype="0" conaffinity="0" group="2"/>
    </default>
    <default class="collision">
      <geom group="3"/>
      <default class="tip">
        <geom condim="4" friction="1 0.01 0.001"/>
      </default>
    </default>
  </default>
  <asset>
    <texture name="steel" type="2d" file="steel.png"/>
    <material name="steel" texture="steel" rgba="0.7 0.7 0.75 1"/>
    <mesh file="base_link.stl"/>
    <mesh name="upper" file="links/upper.obj"/>
    <mesh name="screw" file="screw.stl"/>
  </asset>
  <worldbody>
    <body name="aux1" pos="0.5 0 0.2">
      <joint name="a1" axis="1 0 0"/>
      <geom size="0.02"/>
    </body>
    <body name="aux2" pos="0.6 0 0.2">
      <joint name="a2" axis="1 0 0"/>
      <geom size="0.02"/>
    </body>
    <body name="base">
      <geom class="visual" mesh="base_link" material="steel"/>
      <geom class="collision" type="cylinder" size="0.06 0.02"/>
      <body name="link1" pos="0 0 0.05">
        <joint name="j1" axis="0 0 1" range="-3 3"/>
        <geom class="visual" mesh="upper"/>
        <geom class="collision" type="capsule" fromto="0 0 0 0 0 0.3" size="0.03"/>
        <site name="s1" pos="0 0.05 0.1"/>
        <body name="link2" pos="0 0 0.3">
          <joint name="j2" axis="0 1 0" range="-2 2"/>
          <geom class="collision" type="capsule" fromto="0 0 0 0.3 0 0" size="0.025"/>
          <site name="s2" pos="0.1 0.05 0"/>
          <body name="link3" pos="0.3 0 0">
            <joint name="j3" type="slide" axis="1 0 0" range="0 0.1"/>
            <geom class="tip" type="box" size="0.03 0.03 0.03"/>
            <body name="wrist" pos="0.05 0 0">
              <joint name="j4" type="ball"/>
              <geom class="visual" mesh="screw"/>
              <geom class="collision" type="sphere" size="0.03"/>
              <site name="attachment_site" pos="0.04 0 0" quat="0.7071068 0 0.7071068 0"/>
            </body>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
  <contact>
    <exclude body1="base" body2="link1"/>
  </contact>
  <tendon>
    <fixed name="couple">
      <joint joint="j1" coef="1"/>
      <joint joint="j2" coef="-0.5"/>
    </fixed>
    <spatial name="cable" range="0 1">
      <site site="s1"/>
      <site site="s2"/>
    </spatial>
    <fixed name="aux_t">
      <joint joint="a1" coef="1"/>
    </fixed>
  </tendon>
  <deformable>
    <flex name="strand" dim="1" body="aux1 aux2" vertex="0 0 0 0 0 0" element="0 1"/>
  </deformable>
  <equality>
    <connect body1="aux1" body2="aux2" anchor="0 0 0" active="false"/>
    <weld body1="aux1" body2="aux2" active="false"/>
    <joint joint1="a1" joint2="a2" polycoef="0 1 0 0 0"/>
    <tendon tendon1="aux_t" active="false"/>
    <flex flex="strand" active="false"/>
  </equality>
  <actuator>
    <motor name="m1" joint="j1" ctrlrange="-1 1"/>
    <position name="p2" joint="j2" kp="50"/>
    <velocity name="v3" joint="j3" kv="10"/>
    <intvelocity name="iv1" joint="a1" actrange="-1 1" kp="5"/>
    <general name="g2" joint="a2" dyntype="filter" dynprm="0.1"/>
    <cylinder name="cyl" joint="j3" area="0.01"/>
    <muscle name="mus" tendon="couple" lengthrange="-1 1"/>
    <damper name="d1" joint="j1" kv="1" ctrlrange="0 1"/>
    <adhesion name="stick" body="wrist" ctrlrange="0 1"/>
    <pid name="pid2" joint="j2" kp="20" ki="1"/>
    <orientation name="o4" joint="j4" kp="5"/>
    <dcmotor name="dc1" joint="a1" motorconst="0.1" resistance="1"/>
  </actuator>
  <sensor>
    <jointpos name="q1" joint="j1"/>
    <actuatorfrc name="f1" actuator="m1"/>
    <tendonpos name="cable_length" tendon="cable"/>
    <framepos name="tip" objtype="site" objname="attachment_site"/>
    <ballquat name="wrist_quat" joint="j4"/>
  </sensor>
  <keyframe>
    <key name="home" qpos="0.4 0.5 0.1 0.2 0.03 1 0 0 0" qvel="1 2 3 4 5 6 7 8"
         ctrl="0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9 1 1.1 1.2 1.3 1.4 1.5"
         act="0.01 0.02 0.03 0.04 0.05"/>
    <key name="stowed" qpos="0 0 -1 -1 0 0 1 0 0" time="2"/>
  </keyframe>
</mujoco>
"""

HAND_XML = """\
<mujoco model="gripper">
  <compiler angle="radian" meshdir="meshes" autolimits="true"/>
  <option cone="elliptic" impratio="10"/>
  <default>
    <default class="gripper">
      <joint damping="0.1" range="0 0.8"/>
      <default class="visual">
        <geom type="mesh" contype="0" conaffinity="0" group="2" rgba="0.1 0.1 0.1 1"/>
      </default>
      <default class="collision">
        <geom type="mesh" group="3"/>
      </default>
    </default>
  </default>
  <asset>
    <mesh file="base_link.stl"/>
    <mesh name="screw" file="hardware/screw.stl"/>
    <mesh name="finger" file="finger.obj" scale="0.5 0.5 0.5"/>
  </asset>
  <worldbody>
    <body name="palm" childclass="gripper">
      <geom class="visual" mesh="base_link"/>
      <geom class="collision" mesh="base_link"/>
      <geom class="visual" mesh="screw" pos="0 0 0.02"/>
      <site name="pinch" pos="0 0 0.12"/>
      <body name="left_driver" pos="0 0.03 0.05">
        <joint name="left_driver_joint" axis="1 0 0"/>
        <geom class="collision" mesh="finger"/>
        <body name="left_follower" pos="0 0.01 0.05">
          <joint name="left_follower_joint" axis="1 0 0" range="-0.8 0.8"/>
          <geom type="box" size="0.005 0.01 0.02"/>
        </body>
      </body>
      <body name="right_driver" pos="0 -0.03 0.05" quat="0 0 0 1">
        <joint name="right_driver_joint" axis="1 0 0"/>
        <geom class="collision" mesh="finger"/>
        <body name="right_follower" pos="0 0.01 0.05">
          <joint name="right_follower_joint" axis="1 0 0" range="-0.8 0.8"/>
          <geom type="box" size="0.005 0.01 0.02"/>
        </body>
      </body>
    </body>
  </worldbody>
  <contact>
    <exclude body1="palm" body2="left_driver"/>
    <exclude body1="palm" body2="right_driver"/>
  </contact>
  <tendon>
    <fixed name="split">
      <joint joint="right_driver_joint" coef="0.5"/>
      <joint joint="left_driver_joint" coef="0.5"/>
    </fixed>
  </tendon>
  <equality>
    <connect anchor="0 0 0.01" body1="right_follower" body2="right_driver" solref="0.005 1"/>
    <connect anchor="0 0 0.01" body1="left_follower" body2="left_driver" solref="0.005 1"/>
    <joint joint1="right_driver_joint" joint2="left_driver_joint" polycoef="0 1 0 0 0"/>
    <weld body1="left_follower" body2="right_follower" active="false"/>
    <tendon tendon1="split" active="false"/>
  </equality>
  <actuator>
    <general name="fingers" tendon="split" ctrlrange="0 255" gainprm="0.3137255"
             biastype="affine" biasprm="0 -100 -10" forcerange="-5 5"/>
    <position name="follow" joint="right_follower_joint" kp="2"/>
  </actuator>
  <sensor>
    <jointpos name="opening" joint="right_driver_joint"/>
    <framepos name="pinch" objtype="site" objname="pinch"/>
  </sensor>
  <keyframe>
    <key name="home" qpos="0.3 0.1 0.3 0.1" ctrl="128 0.1"/>
  </keyframe>
</mujoco>
"""

BASE_XML = """\
<mujoco model="rover">
  <compiler angle="radian" meshdir="meshes"/>
  <default>
    <default class="wheel">
      <geom type="cylinder" size="0.08 0.02" rgba="0.2 0.2 0.2 1"/>
    </default>
  </default>
  <asset>
    <mesh name="chassis" file="chassis.obj"/>
  </asset>
  <worldbody>
    <body name="chassis" pos="0 0 0.1">
      <joint name="x" type="slide" axis="1 0 0"/>
      <joint name="y" type="slide" axis="0 1 0"/>
      <joint name="yaw" axis="0 0 1"/>
      <geom type="mesh" mesh="chassis"/>
      <geom class="wheel" pos="0.2 0.2 0" euler="1.5708 0 0"/>
      <geom class="wheel" pos="0.2 -0.2 0" euler="1.5708 0 0"/>
      <body name="mount" pos="0 0 0.15"/>
    </body>
    <body name="target" mocap="true" pos="1 0 0.5">
      <geom type="sphere" size="0.02" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
  <actuator>
    <velocity name="drive" joint="x" kv="20"/>
  </actuator>
  <keyframe>
    <key name="home" qpos="0.5 -0.5 0.25" ctrl="0.2" mpos="1 1 0.6" mquat="0 1 0 0"/>
  </keyframe>
</mujoco>
"""


def _write(folder: Path, name: str, xml: str, files: dict[str, bytes]) -> Path:
    for relative, contents in files.items():
        path = folder / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(contents)
    path = folder / name
    path.write_text(xml, encoding="utf-8")
    return path


def write_arm(folder: Path) -> Path:
    return _write(folder, "arm.xml", ARM_XML, {
        "assets/base_link.stl": box_stl(0.05),
        "assets/links/upper.obj": tetra_obj(0.05, 0.05, 0.3),
        "assets/screw.stl": SCREW,
        "textures/steel.png": png(4, 4, (128, 128, 140)),
    })


def write_hand(folder: Path, *, own_base_link: bool = True) -> Path:
    """The gripper; ``own_base_link=False`` names its base mesh ``palm.stl`` instead (no
    file shares a name with another of different contents then)."""
    xml, base = HAND_XML, "base_link.stl"
    if not own_base_link:
        xml, base = xml.replace('<mesh file="base_link.stl"/>',
                                '<mesh name="base_link" file="palm.stl"/>'), "palm.stl"
    return _write(folder, "gripper.xml", xml, {
        f"meshes/{base}": box_stl(0.04),
        "meshes/hardware/screw.stl": SCREW,
        "meshes/finger.obj": tetra_obj(0.01, 0.02, 0.05),
    })


def write_base(folder: Path) -> Path:
    return _write(folder, "rover.xml", BASE_XML, {
        "meshes/chassis.obj": tetra_obj(0.3, 0.3, 0.05),
    })


class Parts:
    """The three models, loaded from their files in ``root`` (each in its own folder)."""

    def __init__(self, root: Path, *, own_base_link: bool = True) -> None:
        self.arm_path = write_arm(root / "arm")
        self.hand_path = write_hand(root / "gripper", own_base_link=own_base_link)
        self.base_path = write_base(root / "rover")

    def arm(self) -> mjcf.RootElement:
        return mjcf.from_path(self.arm_path)

    def hand(self) -> mjcf.RootElement:
        return mjcf.from_path(self.hand_path)

    def base(self) -> mjcf.RootElement:
        return mjcf.from_path(self.base_path)


def site(model: mjcf.RootElement, name: str) -> mjcf.Site:
    found = model.find("site", name)
    assert isinstance(found, mjcf.Site), name
    return found


def body(model: mjcf.RootElement, name: str) -> mjcf.Body:
    found = model.find("body", name)
    assert isinstance(found, mjcf.Body), name
    return found


def make_arm(name: str, links: int = 3) -> mjcf.RootElement:
    """A chain of capsule links with hinge joints, a defaults class, a motor, a sensor and a
    keyframe."""
    arm = mjcf.RootElement(model=name)
    arm.default.add_joint(damping=0.5, axis=(0, 1, 0))
    link_class = arm.default.add_default(class_="link")
    link_class.add_geom(type="capsule", size=(0.03,), rgba=(0.8, 0.2, 0.2, 1))
    # a base at the worldbody level lands in the attachment frame, giving a free frame mass
    arm.worldbody.add_geom(name="base", type="box", size=(0.05, 0.05, 0.02))
    parent: mjcf.Worldbody | mjcf.Body = arm.worldbody
    body: mjcf.Body | None = None
    for i in range(links):
        body = parent.add_body(name=f"link{i}", pos=(0, 0, 0.2 if i else 0))
        body.add_joint(name=f"joint{i}")
        body.add_geom(class_="link", fromto=(0, 0, 0, 0, 0, 0.2))
        parent = body
    assert body is not None
    body.add_site(name="tip", pos=(0, 0, 0.2))
    arm.actuator.add_motor(name="shoulder", joint="joint0")
    arm.sensor.add_jointpos(name="elbow_angle", joint="joint1")
    arm.keyframe.add_key(name="home", qpos=home(links))
    return arm


def home(links: int) -> list[float]:
    return [0.1 * (i + 1) for i in range(links)]
