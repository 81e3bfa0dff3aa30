"""The MuJoCo world server.

loading.py reads a world file (SDF through sdf/, MJCF through mjcf.py); world.py is the World
(its entities, spawning, stepping, resets) behind World.from_path; templates.py parses what is
spawned (URDF, SDF, MJCF); plugins/ are the systems; server.py serves the world on the bus
through transport.py: runner.py's loop steps it and says the time (clocks.py),
world_services.py answers its requests; viewer.py shows it in a browser through MuJoCo Studio
(studio.py, the one place that knows Studio's internals); pacing.py, snapshot.py,
resources.py and transform.py do one thing each.
"""

import os

# Pictures are rendered offscreen (snapshot.py): EGL unless the user chose a backend. MuJoCo
# reads this once, when it is first imported, and every MuJoCo import is in this package.
os.environ.setdefault("MUJOCO_GL", "egl")
