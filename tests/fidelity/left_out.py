"""What launcher leaves out of the real packages' surface on purpose, each with its reason.

Keys are as surface_check.py names a difference: "module" for a whole module, "module:Name"
for a name. The docs page of what is left out (docs/_gen/reference_fidelity.py) is made from
this table, and test_surface.py holds it to the truth: each entry must still be missing (a
name that launcher gains leaves this list), and the whole stays within 2% of the surface.
"""

from __future__ import annotations

TYPESUPPORT = ("The compiled type support of rclpy's wheels (rosidl's C extension modules); "
               "launcher's message classes are Python, serialised by its own CDR codec.")

LEFT_OUT: dict[str, str] = {
    **{f"{package}.{package}_s__rosidl_typesupport_{kind}": TYPESUPPORT
       for package in ("lifecycle_msgs", "rcl_interfaces")
       for kind in ("c", "fastrtps_c", "introspection_c")},
}
