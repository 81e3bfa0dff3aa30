"""The assets a Foxglove client fetches (the robot's meshes, named in /robot_description):
`package://PKG/PATH` through the package index and `model://NAME/PATH` through the resource
path, as foxglove_bridge serves them; each URI must match `asset_uri_allowlist` (its
default: mesh, texture and description files), and the file must lie inside its package or
model folder (no `..` out of it, no link out of it)."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

# foxglove_bridge's default asset_uri_allowlist
DEFAULT_ALLOWLIST = [r"^package://(?:[-\w%]+/)*[-\w%.]+\.(?:dae|fbx|glb|gltf|jpeg|jpg|mtl|obj|"
                     r"png|stl|tif|tiff|urdf|webp|xacro)$"]
MODEL_PATTERN = r"^model://(?:[-\w%]+/)*[-\w%.]+\.(?:dae|fbx|glb|gltf|jpeg|jpg|mtl|obj|png|" \
                r"stl|tif|tiff|urdf|sdf|webp)$"


class Assets:
    def __init__(self, allowlist: list[str], packages: Any) -> None:
        self._allowed = [re.compile(pattern) for pattern in allowlist]
        if allowlist == DEFAULT_ALLOWLIST:
            self._allowed.append(re.compile(MODEL_PATTERN))
        self._packages = packages

    def fetch(self, uri: str) -> bytes | None:
        """The file's bytes; None (the SDK answers "not found") for a URI that is not allowed,
        not found, or outside its folder."""
        path = self.path(uri)
        if path is None:
            return None
        try:
            return path.read_bytes()
        except OSError:
            return None

    def path(self, uri: str) -> Path | None:
        if not any(pattern.match(uri) for pattern in self._allowed):
            return None
        scheme, _, rest = uri.partition("://")
        name, _, inside = rest.partition("/")
        if not name or not inside or ".." in inside.split("/"):
            return None
        try:
            if scheme == "package":
                root = Path(self._packages.share(name)).resolve()
            elif scheme == "model":
                from launcher.sim.resources import find_model

                root = find_model(name).resolve()
            else:
                return None
        except Exception:  # noqa: BLE001 - an unknown package or model: not found
            return None
        path = (root / inside).resolve()
        return path if path.is_relative_to(root) and path.is_file() else None
