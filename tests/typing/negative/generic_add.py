"""The generic add()/insert() with a literal tag: checked like add_<tag>() (issue 25).

Each mistake that add_<tag>() turns into an error is one here too, through add() and insert().
A literal tag whose call fails its own overload matches a deprecated overload instead of the
``str`` fallback, so the code is pyright's reportDeprecated and mypy's ``deprecated`` (which
the repository's mypy configuration enables: it is not part of ``--strict``).
"""

import typed_mjcf as mjcf

model = mjcf.RootElement()
body = model.worldbody.add_body(name="arm")
geom = body.add_geom(name="upper")
site = body.add_site(name="tip")

# a misspelt keyword
body.add("geom", tpye="capsule")  # E: mypy[deprecated] pyright[reportDeprecated]
body.insert("geom", 0, tpye="capsule")  # E: mypy[deprecated] pyright[reportDeprecated]
model.worldbody.add("body", nmae="leg")  # E: mypy[deprecated] pyright[reportDeprecated]

# a value outside the keyword set
body.add("geom", type="capsul")  # E: mypy[deprecated] pyright[reportDeprecated]
body.insert("joint", 0, type="hinged")  # E: mypy[deprecated] pyright[reportDeprecated]

# an array of the wrong length
body.add("geom", pos=(1, 2))  # E: mypy[deprecated] pyright[reportDeprecated]
body.insert("geom", 0, rgba=(1, 0, 0))  # E: mypy[deprecated] pyright[reportDeprecated]

# a tag that is no child of the element (a <motor> belongs in <actuator>)
body.add("motor")  # E: mypy[deprecated] pyright[reportDeprecated]
model.worldbody.insert("motor", 0, joint="shoulder")  # E: mypy[deprecated] pyright[reportDeprecated]
model.actuator.add("body", name="b")  # E: mypy[deprecated] pyright[reportDeprecated]

# a reference to an element of the wrong kind (a geom where a joint belongs)
model.actuator.add("motor", joint=geom)  # E: mypy[deprecated] pyright[reportDeprecated]
model.sensor.insert("jointpos", 0, joint=geom)  # E: mypy[deprecated] pyright[reportDeprecated]
model.sensor.add("touch", site=geom)  # E: mypy[deprecated] pyright[reportDeprecated]

# an attribute of another tag (mass is a geom's, not a joint's)
body.add("joint", mass=1.0)  # E: mypy[deprecated] pyright[reportDeprecated]
body.insert("site", 0, condim=3)  # E: mypy[deprecated] pyright[reportDeprecated]

# the same calls through add_<tag>(), for comparison
body.add_geom(tpye="capsule")  # E: mypy[call-arg] pyright[reportCallIssue]
body.add_joint(mass=1.0)  # E: mypy[call-arg] pyright[reportCallIssue]
model.actuator.add_motor(joint=geom)  # E: mypy[arg-type] pyright[reportArgumentType]

# correct calls stay clean, a typed child is returned
ok: mjcf.Geom = body.add("geom", type="capsule", pos=(1, 2, 3), rgba=(1, 0, 0, 1))
motor: mjcf.Motor = model.actuator.insert("motor", 0, joint=body.add_joint(name="j"))
touch: mjcf.Touch = model.sensor.add("touch", site=site)
