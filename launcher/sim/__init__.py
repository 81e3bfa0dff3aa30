"""The MuJoCo world server (see server.py)."""

import os

# Pictures are rendered offscreen (snapshot.py): EGL unless the user chose a backend. MuJoCo
# reads this once, when it is first imported, and every MuJoCo import is in this package.
os.environ.setdefault("MUJOCO_GL", "egl")
