"""Run at interpreter start in the processes launcher starts (this folder is on their
PYTHONPATH): installs launcher's fallback finder for rclpy, rospy and message packages (see
launcher/compat/finder.py), then runs the `sitecustomize` this one stands in front of, if the
interpreter has one. Without launcher importable (another interpreter), it does nothing."""

import importlib.machinery
import os
import sys

try:
    from launcher.compat.finder import install
except ImportError:
    pass
else:
    install()


def _chain() -> None:
    here = os.path.dirname(os.path.abspath(__file__))
    rest = [p for p in sys.path if os.path.abspath(p or ".") != here]
    spec = importlib.machinery.PathFinder.find_spec("sitecustomize", rest)
    if spec is None or spec.loader is None:
        return
    from importlib.util import module_from_spec  # (only here: ~7 ms of every start)

    module = module_from_spec(spec)
    sys.modules["sitecustomize"] = module
    spec.loader.exec_module(module)


_chain()
del _chain
