"""A package's components: the nodes a component container can load by plugin name.

rclcpp packages register C++ classes (`rclcpp_components_register_nodes`); a Python package
declares a component as a callable that makes its node, either in package.xml
    <export><component plugin="pkg::Driver" module="pkg.driver:Driver"/></export>
or as the entry-point group `rclpy_components` of setup.cfg / setup.py
    'rclpy_components': ['pkg::Driver = pkg.driver:Driver']
The callable is called with no arguments; the nodes it makes (launcher's or rclpy's) take the
name, namespace, remaps and parameters that the container was asked for. A compiled package
found only as source offers its stand-in's (launcher's own implementation, see index.py).
"""

from __future__ import annotations

from launcher.packages.executables import declared, lookup
from launcher.packages.manifest import Package
from launcher.records import dataclass

GROUP = "rclpy_components"


@dataclass(frozen=True)
class Component:
    plugin: str  # pkg::Name
    target: str  # module:callable
    folder: str  # what its module needs on sys.path


def components(package: Package) -> dict[str, Component]:
    found: dict[str, Component] = {}
    for plugin, target in declared(package, "component", GROUP, key="plugin"):
        found.setdefault(plugin, Component(plugin, target, str(package.path)))
    if package.stand_in is not None:
        found = {**found, **components(package.stand_in)}
    return found


def find_component(package: Package, plugin: str) -> Component:
    return lookup(package, "component", plugin, components(package), "it offers")
