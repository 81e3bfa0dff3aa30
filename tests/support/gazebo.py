"""ros_gz_sim_demos as a package of the workspace, its launch folder the external one."""

from __future__ import annotations

from pathlib import Path

from tests.support.environment import shared


def demos_workspace(ws) -> Path:
    """ros_gz_sim_demos as a package whose launch folder is the external one, in place."""
    package = ws.root / "pkgs" / "ros_gz_sim_demos"
    package.mkdir(parents=True)
    (package / "package.xml").write_text(
        '<?xml version="1.0"?><package format="3"><name>ros_gz_sim_demos</name>'
        "<version>0.0.0</version><description>demos</description>"
        '<maintainer email="m@example.com">m</maintainer><license>Apache-2.0</license>'
        "</package>")
    (package / "launch").symlink_to(shared("external", "ros_gz_sim_demos", "launch"))
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "pkgs")
    return package
