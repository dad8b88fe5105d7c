"""A model giving ``<frame>`` an attribute MuJoCo's reader ignores (``bogus``), beside a
``<replicate>``: it loads, with a warning, as in MuJoCo."""

MODEL = """\
<mujoco>
  <worldbody>
    <replicate count="2" offset="1 0 0"
               prefix="p_">
      <geom name="g" size="0.1"/>
    </replicate>
    <frame pos="0 0 1" bogus="x">
      <geom name="h" size="0.1"/>
    </frame>
  </worldbody>
</mujoco>
"""
