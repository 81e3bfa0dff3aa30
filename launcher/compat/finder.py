"""The import hook that makes ROS node code importable without ROS: `rclpy`, `rospy` and the
message packages (`geometry_msgs.msg`, `std_srvs.srv`, a workspace's own `my_msgs.msg`), and
the shims of `launch`, `launch_ros` and `ament_index_python`.

It sits at the end of `sys.meta_path`, so it is asked only after every other finder has come
up empty: a real rclpy, rospy or message package that the user installed (pip, /opt/ros on
PYTHONPATH) always wins. `LAUNCHER_ROS_MODULES=launcher` puts it first instead, to use
launcher's graph from a shell where a real ROS is installed too.

It is installed at interpreter start by the `sitecustomize` in `compat/site/` (on the
PYTHONPATH of every process a launch or `launcher run` starts, and of the shell that sourced
hooks/setup.sh), because message imports often come before `import rclpy`.
"""

from __future__ import annotations

import importlib.machinery
import os
import sys
import threading

TYPE_CHECKING = False  # (typing.TYPE_CHECKING without importing typing)

if TYPE_CHECKING:  # (typing's names are not imported at run time: this runs at every start)
    import types
    from collections.abc import Sequence
    from typing import Any

NODE_APIS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "nodes")
_API_NAMES = ("rclpy", "rospy", "tf2_ros", "tf2_geometry_msgs", "sensor_msgs_py", "cv_bridge",
              "message_filters", "actionlib", "tf", "rosbag", "roslaunch")
# launch files' and xacro's modules (compat/shims): found here too, so that a shell with
# `launcher env` runs `xacro` with `$(find pkg)` and Python launch files, a real one first
SHIMS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "shims")
SHIMMED = ("ament_index_python", "launch", "launch_ros", "launch_testing",
           "launch_testing_ros", "launch_pytest", "launch_xml", "launch_yaml",
           "controller_manager", "rostest")
# The real packages' module tree (recorded by tests/fidelity/surface.py): a module of it that
# has no file among the shims is made from it, its names found in the packages above it
LAYOUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "layout.json")
# where launch's and launch_ros's names are, whatever module of theirs a file imports one from
CANONICAL = {"launch": ("launcher.api", "launcher.api.utilities", "launch"),
             "launch_ros": ("launcher.api", "launcher.api.ros", "launcher.api.ros_adapter",
                            "launch")}
LAYOUT_ROOTS = ("launch", "launch_xml", "launch_yaml", "launch_ros", "launch_testing",
                "launch_testing_ros", "launch_pytest", "ament_index_python", "rclpy", "rospy",
                "actionlib", "rostest", "rosbag", "roslaunch")
_KINDS = ("msg", "srv", "action")
CHOICE_VARIABLE = "LAUNCHER_ROS_MODULES"


class InterfaceFinder:
    """A meta path finder and the loader of what it finds (the importlib.abc protocols,
    without importing importlib.abc: this runs at every interpreter start)."""

    def __init__(self) -> None:
        self._packages: set[str] | None = None
        self._busy = threading.local()  # finding imports modules too: those are not ours

    # --- finding ------------------------------------------------------------------------------
    def find_spec(self, fullname: str, path: Sequence[str] | None = None,
                  target: types.ModuleType | None = None) -> importlib.machinery.ModuleSpec | None:
        top, _, rest = fullname.partition(".")
        if top in _API_NAMES or top in SHIMMED:
            if rest:  # submodules come from the package's own __path__, else the layout
                if not _ours(fullname.rpartition(".")[0]):
                    return None
                found = importlib.machinery.PathFinder.find_spec(fullname, path)
                return found or _layout_spec(fullname)
            found = importlib.machinery.PathFinder.find_spec(
                fullname, [NODE_APIS if top in _API_NAMES else SHIMS])
            return found or _layout_spec(fullname)
        if rest and rest not in _KINDS or getattr(self._busy, "on", False) \
                or _inside_standard_import():
            return None
        self._busy.on = True
        try:
            if not self._is_interface_package(top):
                return None
        finally:
            self._busy.on = False
        spec = importlib.machinery.ModuleSpec(fullname, self, is_package=not rest)
        if not rest:
            spec.submodule_search_locations = []
        return spec

    def _is_interface_package(self, name: str) -> bool:
        if not name.isidentifier() or name.startswith("_") or name in sys.stdlib_module_names:
            return False  # (Windows-only modules that Linux code tries, like msvcrt)
        if self._packages is None:
            self._packages = _interface_packages()
        if name in self._packages:
            return True
        return _workspace_interface_package(name)

    # --- loading ------------------------------------------------------------------------------
    def create_module(self, spec: importlib.machinery.ModuleSpec) -> None:
        return None

    def exec_module(self, module: types.ModuleType) -> None:
        package, _, kind = module.__name__.partition(".")
        module.__file__ = None
        if not kind:
            module.__doc__ = f"{package}: interfaces from launcher's type store"
            return
        module.__doc__ = f"{package}.{kind}: {kind} classes from launcher's type store"
        module.__getattr__ = _lazy_types(package, kind)  # type: ignore[attr-defined]


_layout: dict[str, dict[str, str]] | None = None


def layout() -> dict[str, dict[str, str]]:
    """{module: {its public names: the module of the real package that defines the name
    ("" for the module itself)}} of the real packages that launcher shims."""
    global _layout
    if _layout is None:
        import json

        with open(LAYOUT, encoding="utf-8") as file:
            _layout = json.load(file)
    return _layout


def _ours(package: str) -> bool:
    """Whether `package` is launcher's (a shim's file or a layout module), not a real install
    whose missing submodules are not ours to make."""
    module = sys.modules.get(package)
    if module is None:
        return False
    origin = getattr(getattr(module, "__spec__", None), "origin", None)
    return origin is None and isinstance(getattr(module, "__loader__", None), LayoutLoader) \
        or isinstance(origin, str) and origin.startswith((SHIMS, NODE_APIS))


def _layout_spec(fullname: str) -> importlib.machinery.ModuleSpec | None:
    modules = layout()
    if fullname not in modules:
        return None
    spec = importlib.machinery.ModuleSpec(fullname, LayoutLoader())
    if any(name.startswith(fullname + ".") for name in modules):
        spec.submodule_search_locations = []
    return spec


class LayoutLoader:
    """A module of the real packages' tree with no file of its own among the shims: its names
    are the ones its nearest packages above it give (the real packages re-export what their
    modules define, and the shims define each thing once)."""

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> None:
        return None

    def exec_module(self, module: types.ModuleType) -> None:
        names = layout()[module.__name__]
        module.__all__ = list(names)  # type: ignore[attr-defined]
        module.__getattr__ = _from_above(module.__name__, names)  # type: ignore


def rest_from_layout(dotted: str) -> Any:
    """A shim file's module `__getattr__`: the names the real module has that the file does
    not define, found as a layout module finds them (the layout is read at the first)."""
    found: list[Any] = []

    def get(name: str) -> Any:
        if name.startswith("__"):  # (probes such as __path__ or __file__ by tools)
            raise AttributeError(f"module '{dotted}' has no attribute '{name}'")
        if not found:
            found.append(_from_above(dotted, layout().get(dotted, {})))
        return found[0](name)
    return get


def _from_above(dotted: str, names: dict[str, str]) -> Any:
    def get(name: str) -> Any:
        if name in names:
            home = names[name]
            if home and home != dotted and _ours(home.partition(".")[0]):
                try:  # where the real package defines it (a shim file, or found above it)
                    value = getattr(importlib.import_module(home), name)
                except (ImportError, AttributeError):
                    pass
                else:
                    setattr(sys.modules[dotted], name, value)
                    return value
            package = dotted.rpartition(".")[0]
            while package:
                above = sys.modules.get(package) or importlib.import_module(package)
                value = vars(above).get(name, _NOTHING)
                if value is _NOTHING and isinstance(getattr(above, "__loader__", None),
                                                    LayoutLoader):
                    try:
                        value = getattr(above, name)
                    except AttributeError:
                        value = _NOTHING
                if value is not _NOTHING:
                    setattr(sys.modules[dotted], name, value)
                    return value
                package = package.rpartition(".")[0]
            for canonical in CANONICAL.get(dotted.partition(".")[0], ()):
                value = getattr(importlib.import_module(canonical), name, _NOTHING)
                if value is not _NOTHING:
                    setattr(sys.modules[dotted], name, value)
                    return value
            raise AttributeError(f"module '{dotted}' has no attribute '{name}': launcher does "
                                 f"not provide {dotted}.{name} (the real package has it)")
        from launcher.errors import did_you_mean

        raise AttributeError(f"module '{dotted}' has no attribute '{name}'"
                             f"{did_you_mean(name, sorted(names))}")
    return get


_NOTHING = object()


def _inside_standard_import() -> bool:
    """Whether this thread is importing a standard library module: its optional imports
    (copy's `org.python.core`) are never interface packages, and looking them up would import
    modules that need it whole (ElementTree needs copy.deepcopy). This thread's own: a module
    another thread imports meanwhile (a container loading two components at once) must not
    hide `rcl_interfaces` from this one."""
    frame = sys._getframe(1)
    while frame is not None:
        if frame.f_code.co_name == "<module>" and \
                str(frame.f_globals.get("__name__", "")).partition(".")[0] in \
                sys.stdlib_module_names:
            return True
        frame = frame.f_back
    return False


def _lazy_types(package: str, kind: str) -> Any:
    def get(name: str) -> Any:
        # Only what looks like a type name (capitalised) is looked up; the rest (dunders,
        # getattr(module, "X", default) probes) is a plain AttributeError.
        if not (name[:1].isupper() and name.isidentifier()):  # (UUID is a type too)
            raise AttributeError(f"module '{package}.{kind}' has no attribute '{name}'")
        from launcher.bus.types import UnknownType
        from launcher.compat import rosidl

        type_name = f"{package}/{kind}/{name}"
        half = next((h for h in ("Request", "Response") if kind == "srv" and name.endswith(h)
                     and len(name) > len(h)), "")
        try:
            if kind == "srv" and name.endswith("_Event") and len(name) > 6:  # introspection's
                from launcher.bus.types import registry

                event = registry().service_event(type_name[:-len("_Event")])
                cls = rosidl.message_class(event, f"{package}.{kind}", name)
            elif half:  # ROS 1's TriggerRequest, and Trigger_Request
                service = rosidl.service_class(type_name[:-len(half)].rstrip("_"))
                cls = getattr(service, half)
            elif kind == "action":
                cls = rosidl.action_class(type_name)
            else:
                cls = rosidl.service_class(type_name) if kind == "srv" else \
                    rosidl.message_class(type_name)
        except UnknownType:
            if not any(c.islower() for c in name):  # an all-capitals probe (`REAL`), not a
                raise AttributeError(  # type (UUID): getattr(module, "REAL", default) works
                    f"module '{package}.{kind}' has no attribute '{name}'") from None
            # ImportError, not AttributeError: `from pkg.msg import Twst` shows this text
            # (Python replaces an AttributeError's with its own "cannot import name")
            raise ImportError(_unknown(package, kind, name),
                              name=f"{package}.{kind}") from None
        setattr(sys.modules[f"{package}.{kind}"], name, cls)
        return cls
    return get


def _unknown(package: str, kind: str, name: str) -> str:
    from launcher.bus.types import registry
    from launcher.errors import did_you_mean

    known = [t.rsplit("/", 1)[-1] for t in registry().known() if t.startswith(f"{package}/{kind}/")
             and not t.endswith(("_Request", "_Response", "_Event"))] if kind != "action" else []
    if kind in ("srv", "action") or not known:
        known += _package_definitions(package, kind)
    listing = ", ".join(sorted(set(known))[:20]) or "none"
    return (f"cannot import name '{name}' from '{package}.{kind}': no {kind} type "
            f"'{package}/{kind}/{name}'{did_you_mean(name, known)}; {package}.{kind} has: "
            f"{listing}")


def _interface_packages() -> set[str]:
    """The packages of the type store's distro (no package index needed for those)."""
    from launcher.bus.types import registry

    return {name.split("/", 1)[0] for name in registry().known()}


def _workspace_interface_package(name: str) -> bool:
    """A package of the index with `msg/`, `srv/` or `action/` definitions."""
    folder = _package_folder(name)
    return folder is not None and any(os.path.isdir(os.path.join(folder, k)) for k in _KINDS)


def _package_folder(name: str) -> str | None:
    from launcher.bus.types import registry

    index = registry().package_index()
    if name not in index:
        return None
    return str(index.share(name))


def _package_definitions(package: str, kind: str) -> list[str]:
    folder = _package_folder(package)
    if folder is None:
        return []
    try:
        return [f[:-len(kind) - 1] for f in os.listdir(os.path.join(folder, kind))
                if f.endswith(f".{kind}")]
    except OSError:
        return []


def install() -> None:
    """Add the finder to this interpreter (once): last, or first if the user chose launcher's."""
    if any(isinstance(f, InterfaceFinder) for f in sys.meta_path):
        return
    finder = InterfaceFinder()
    if os.environ.get(CHOICE_VARIABLE) == "launcher":
        sys.meta_path.insert(0, finder)
    else:
        sys.meta_path.append(finder)
