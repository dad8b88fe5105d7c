"""Bad input every command meets alike (a missing file, XML that is not MJCF, malformed XML,
a schema error), by file name, and the one line each command prints for it."""

BAD = {
    "missing.xml": None,  # not written: the file does not exist
    "not_mjcf.xml": "<robot name='r'>\n  <link name='base'/>\n</robot>\n",
    "malformed.xml": "<mujoco>\n  <worldbody>\n    <geom size='1'>\n  </worldbody>\n</mujoco>\n",
    "schema.xml": "<mujoco>\n  <worldbody>\n    <geom sise='1'/>\n  </worldbody>\n</mujoco>\n",
}
EXPECTED = {
    "missing.xml": "missing.xml: cannot read the file: No such file or directory",
    "not_mjcf.xml": "not_mjcf.xml:1: the root element is <robot>, expected <mujoco>",
    "malformed.xml": "malformed.xml:4: malformed XML: Opening and ending tag mismatch: geom line 3 "
                     "and worldbody, line 4, column 15",
    "schema.xml": ("schema.xml:3: worldbody/geom[0]: <geom> has no attribute 'sise' "
                   "(did you mean 'size'?)"),
}
