"""Pictures asked for with arguments of the wrong kind."""

import typed_mjcf as mjcf

model = mjcf.RootElement()
geom = model.worldbody.add_geom(size=(0.1,))

model.render(camera=geom)  # E: mypy[arg-type] pyright[reportArgumentType]
model.render(keyframe=1.5)  # E: mypy[arg-type] pyright[reportArgumentType]
model.render(width=640.0, height=480)  # E: mypy[arg-type] pyright[reportArgumentType]
model.render(640, 480)  # E: mypy[arg-type,call-arg] pyright[reportCallIssue]
model.render(640)  # E: mypy[arg-type] pyright[reportArgumentType]
model.render(views="front")  # E: mypy[arg-type] pyright[reportArgumentType]
model.render(camera=mjcf.FreeView(azimuth="left"))  # E: mypy[arg-type] pyright[reportArgumentType]
model.render(wdith=640)  # E: mypy[call-arg] pyright[reportCallIssue]
mjcf.set_notebook_display("png")  # E: mypy[arg-type] pyright[reportArgumentType]
