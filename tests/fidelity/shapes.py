"""Models with the shapes real MJCF files have where names are not plain: written for these
tests after the robots and examples people load (bimanual arms whose parts are named
``left/...``, MuJoCo's replicate and flexcomp examples), none copied from anywhere.

Each is a whole model MuJoCo 4.0.0 compiles; ``test_shapes.py`` checks that typed-mjcf
loads it, validates it without an error, compiles it to the same model and writes it back
unchanged.
"""

from __future__ import annotations

# Two arms of one robot in one file, parts named '<side>/<part>' and default classes
# '<robot>/<role>', as bimanual and multi-part robot descriptions name them; references
# (class=, target=, joint=, body1=, tendon=, objname=) use those names as written.
BIMANUAL = """\
<mujoco model="bimanual">
  <compiler angle="radian" autolimits="true"/>
  <option integrator="implicitfast"/>
  <default>
    <default class="robot">
      <joint damping="1" armature="0.1" frictionloss="0.1"/>
      <position kp="100" forcerange="-20 20"/>
      <default class="robot/visual">
        <geom type="capsule" contype="0" conaffinity="0" group="2" density="0"/>
      </default>
      <default class="robot/collision">
        <geom type="capsule" group="3"/>
        <default class="robot/finger">
          <geom type="box" friction="1.5 0.01 0.001"/>
        </default>
      </default>
    </default>
  </default>
  <asset>
    <material name="robot/black" rgba="0.1 0.1 0.1 1"/>
    <material name="robot/gray" rgba="0.5 0.5 0.5 1"/>
  </asset>
  <worldbody>
    <light name="top" pos="0 0 2"/>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <body name="left/base_link" childclass="robot" pos="-0.4 0 0">
      <geom class="robot/visual" material="robot/black" size="0.05" fromto="0 0 0 0 0 0.1"/>
      <body name="left/upper_arm_link" pos="0 0 0.1">
        <joint name="left/shoulder" axis="0 0 1" range="-3 3"/>
        <geom class="robot/visual" material="robot/gray" size="0.04" fromto="0 0 0 0.3 0 0"/>
        <geom class="robot/collision" size="0.04" fromto="0 0 0 0.3 0 0"/>
        <body name="left/gripper_link" pos="0.3 0 0">
          <joint name="left/wrist" axis="1 0 0" range="-1.5 1.5"/>
          <geom class="robot/finger" size="0.02 0.01 0.03"/>
          <site name="left/tcp" pos="0.05 0 0"/>
        </body>
      </body>
    </body>
    <body name="right/base_link" childclass="robot" pos="0.4 0 0">
      <geom class="robot/visual" material="robot/black" size="0.05" fromto="0 0 0 0 0 0.1"/>
      <body name="right/upper_arm_link" pos="0 0 0.1">
        <joint name="right/shoulder" axis="0 0 1" range="-3 3"/>
        <geom class="robot/visual" material="robot/gray" size="0.04" fromto="0 0 0 -0.3 0 0"/>
        <geom class="robot/collision" size="0.04" fromto="0 0 0 -0.3 0 0"/>
        <body name="right/gripper_link" pos="-0.3 0 0">
          <joint name="right/wrist" axis="1 0 0" range="-1.5 1.5"/>
          <geom class="robot/finger" size="0.02 0.01 0.03"/>
          <site name="right/tcp" pos="-0.05 0 0"/>
        </body>
      </body>
    </body>
    <camera name="left/wrist_cam" mode="targetbody" target="left/gripper_link" pos="0 -1 1"/>
  </worldbody>
  <contact>
    <exclude body1="left/base_link" body2="left/upper_arm_link"/>
    <exclude body1="right/base_link" body2="right/upper_arm_link"/>
  </contact>
  <tendon>
    <fixed name="left/coupling">
      <joint joint="left/shoulder" coef="1"/>
      <joint joint="left/wrist" coef="-1"/>
    </fixed>
  </tendon>
  <equality>
    <joint name="mirror" joint1="left/shoulder" joint2="right/shoulder" polycoef="0 -1 0 0 0"/>
  </equality>
  <actuator>
    <position name="left/shoulder" class="robot" joint="left/shoulder" ctrlrange="-3 3"/>
    <position name="left/wrist" class="robot" joint="left/wrist" ctrlrange="-1.5 1.5"/>
    <position name="right/shoulder" class="robot" joint="right/shoulder" ctrlrange="-3 3"/>
    <position name="right/wrist" class="robot" joint="right/wrist" ctrlrange="-1.5 1.5"/>
  </actuator>
  <sensor>
    <framepos name="left/tcp_pos" objtype="site" objname="left/tcp"/>
    <tendonpos name="left/coupling" tendon="left/coupling"/>
  </sensor>
  <keyframe>
    <key name="home" qpos="0 0 0 0" ctrl="0 0 0 0"/>
  </keyframe>
</mujoco>
"""

# A cloth flag on a pole: the bodies <flexcomp name="flag"> makes are named flag_<vertex>,
# and the connect and weld constraints and a sensor name them.
FLAG = """\
<mujoco model="flag">
  <option timestep="0.001" density="1.2" viscosity="1.8e-5" integrator="implicitfast"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <body name="pole" pos="0 0 1">
      <geom type="cylinder" size="0.02 1"/>
    </body>
    <flexcomp name="flag" type="grid" count="9 5 1" spacing="0.05 0.05 0.05" pos="0.22 0 1.8"
              radius="0.001" dim="2" mass="0.1">
      <edge equality="true" damping="0.001"/>
      <contact condim="3" solref="0.01 1" selfcollide="none"/>
      <pin id="2 3"/>
    </flexcomp>
  </worldbody>
  <equality>
    <connect body1="flag_0" body2="pole" anchor="0 0 0"/>
    <connect body1="flag_1" body2="pole" anchor="0 0 0"/>
    <weld body1="flag_44" body2="pole"/>
  </equality>
  <sensor>
    <framepos name="corner" objtype="body" objname="flag_40"/>
  </sensor>
</mujoco>
"""

# A soft cube with trilinear dofs: its bodies are the corners of the interpolation grid,
# named cube_<i>_<j>_<k>.
SOFT_CUBE = """\
<mujoco model="soft cube">
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <flexcomp name="cube" type="grid" count="4 4 4" spacing="0.05 0.05 0.05" pos="0 0 0.5"
              radius="0.001" dim="3" dof="trilinear" mass="0.5">
      <elasticity young="5e4" poisson="0.2"/>
      <contact selfcollide="none"/>
    </flexcomp>
  </worldbody>
  <contact>
    <exclude body1="cube_0_0_0" body2="world"/>
  </contact>
  <sensor>
    <framepos name="top corner" objtype="body" objname="cube_1_1_1"/>
  </sensor>
</mujoco>
"""

# Balls hanging on tendons, the row made by <replicate>: the tendons name the sites inside
# the replicate as written (MuJoCo copies each tendon with them), and an actuator and a
# sensor name the copies MuJoCo makes ("swing1", "string0").
CRADLE = """\
<mujoco model="cradle">
  <default>
    <tendon limited="true" range="0 0.15" width="0.001"/>
    <default class="ball">
      <geom size="0.02" density="8000"/>
    </default>
  </default>
  <worldbody>
    <geom type="plane" size="1 1 0.1"/>
    <replicate count="4" offset="-0.04 0 0">
      <site name="hook" pos="0 -0.04 0.2"/>
      <body name="ball" pos="0 0 0.05">
        <freejoint name="swing"/>
        <geom class="ball"/>
        <site name="eye" pos="0 -0.008 0.018"/>
      </body>
    </replicate>
  </worldbody>
  <tendon>
    <spatial name="string">
      <site site="hook"/>
      <site site="eye"/>
    </spatial>
  </tendon>
  <actuator>
    <motor name="push" joint="swing1" gear="1 0 0 0 0 0"/>
  </actuator>
  <sensor>
    <tendonpos name="first string" tendon="string0"/>
    <framepos name="last ball" objtype="body" objname="ball3"/>
  </sensor>
</mujoco>
"""

# A box of particles from three nested replicates (a separator on the middle one), and
# elements of every kind that MuJoCo copies with what they name: copies are named
# '<name><inner index><sep><middle index><outer index>'.
PARTICLES = """\
<mujoco model="particles">
  <option timestep="0.01"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <replicate count="3" offset="0.07 0 0">
      <replicate count="12" offset="0 0.07 0" sep="_">
        <replicate count="2" offset="0 0 0.07">
          <body name="p" pos="-0.1 -0.4 0.2">
            <joint name="x" type="slide" axis="1 0 0"/>
            <joint name="z" type="slide" axis="0 0 1"/>
            <geom name="g" size="0.02"/>
            <site name="s"/>
          </body>
        </replicate>
      </replicate>
    </replicate>
  </worldbody>
  <contact>
    <exclude name="no self" body1="p" body2="world"/>
    <pair name="floor contact" geom1="g" geom2="floor"/>
  </contact>
  <equality>
    <joint name="lock" joint1="x" active="false"/>
  </equality>
  <actuator>
    <motor name="lift" joint="z"/>
  </actuator>
  <sensor>
    <actuatorfrc name="lift force" actuator="lift"/>
    <framepos name="one particle" objtype="site" objname="s1_112"/>
    <jointpos name="last x" joint="x1_112"/>
    <actuatorfrc name="a lift" actuator="lift0_050"/>
  </sensor>
  <custom>
    <tuple name="particle">
      <element objtype="body" objname="p"/>
    </tuple>
  </custom>
</mujoco>
"""

# A separator with '/' gives copies names with '/' ("arm/0"), which a reference names as
# written, like the literal names with '/' beside them.
SLASHED_COPIES = """\
<mujoco model="slashed copies">
  <worldbody>
    <geom type="plane" size="1 1 0.1"/>
    <body name="rack/base" pos="0 0 0.5">
      <geom size="0.05"/>
    </body>
    <replicate count="2" offset="0.2 0 0" sep="/">
      <body name="arm" pos="0 0 0.3">
        <joint name="hinge" axis="0 1 0"/>
        <geom size="0.03" fromto="0 0 0 0.1 0 0" type="capsule"/>
      </body>
    </replicate>
  </worldbody>
  <contact>
    <exclude body1="arm/0" body2="rack/base"/>
  </contact>
  <actuator>
    <motor name="second" joint="hinge/1"/>
  </actuator>
</mujoco>
"""

SHAPES: dict[str, str] = {
    "bimanual": BIMANUAL,
    "flag": FLAG,
    "soft-cube": SOFT_CUBE,
    "cradle": CRADLE,
    "particles": PARTICLES,
    "slashed-copies": SLASHED_COPIES,
}
