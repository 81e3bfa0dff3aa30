"""gz-sim-label-system: a semantic label (0–255) for a model's visuals, or for one visual's
(the plugin inside a `<visual>`), which segmentation cameras draw: as in gz-rendering, a pixel
of a labelled visual carries its label, and any other pixel the background's, 0. A visual's
own label wins over its model's."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from launcher.records import dataclass as record
from launcher.schema import Kind, attr
from launcher.sim.mjcf import PluginConfig
from launcher.sim.plugins import Plugin
from launcher.sim.sdf.geometry import VISUAL_GROUP


@record
class Parameters:
    label: int = attr(Kind.INT, required=True, minimum=0, maximum=255)


@dataclass
class VisualLabel(PluginConfig):
    """A Label plugin inside a `<visual>`: that visual's geom, below the entity's prefix."""
    visual: str = ""


def labels_of(sim: Any) -> dict[str, int]:
    """The world's labelled visual geoms (by name) and their labels."""
    found = getattr(sim, "segmentation_labels", None)
    if found is None:
        found = sim.segmentation_labels = {}
    return found


class Label(Plugin):
    declared = Parameters

    def prepare(self, spec: Any) -> None:
        self.value = self.parameters(self.declared).label
        self.geoms: list[str] = []

    def bind(self, model: Any, data: Any) -> None:
        labels = labels_of(self.sim)
        for name in self.geoms:
            labels.pop(name, None)
        prefix = f"{self.entity.name}/"
        visual = getattr(self.config, "visual", "")
        self.geoms = [model.geom(g).name for g in range(model.ngeom)
                      if (model.geom(g).name == prefix + visual if visual else
                          model.geom(g).name.startswith(prefix) and
                          int(model.geom_group[g]) == VISUAL_GROUP)]
        for name in self.geoms:
            if visual or name not in labels:  # (a visual's own label stays)
                labels[name] = self.value

    def close(self) -> None:
        labels = labels_of(self.sim)
        for name in self.geoms:
            if labels.get(name) == self.value:
                labels.pop(name)
