"""What a job asks of a node: sizes in words, Ray's options, and whether any node can meet
it (Ray itself waits for ever on a task no node can take)."""

from __future__ import annotations

from typing import Any

from launcher import records
from launcher.batch.spec import Resources
from launcher.schema import parse_bytes

RAY_OWN = ("CPU", "GPU", "memory", "object_store_memory")


def ray_options(r: Resources) -> dict[str, Any]:
    options: dict[str, Any] = {"num_cpus": r.cpus, "num_gpus": r.gpus}
    if r.memory is not None:
        options["memory"] = parse_bytes(r.memory, "memory")
    if r.custom:
        options["resources"] = dict(r.custom)
    return options


@records.dataclass(frozen=True)
class NodeOffer:
    """What one live node of the cluster has in all."""

    address: str
    cpus: float
    gpus: float
    memory: float
    custom: dict[str, float]

    def describe(self) -> str:
        gpus = f"{self.gpus:g} GPU" if self.gpus else "no GPU"
        own = "".join(f", {amount:g} {name}" for name, amount in sorted(self.custom.items()))
        return f"{self.address}: {self.cpus:g} CPU, {self.memory / 2**30:.1f} GiB, {gpus}{own}"


def unmet(r: Resources, nodes: list[NodeOffer], where: str = "the cluster") -> str | None:
    """Why no node of `where` can run a job asking `r`, or None when one can."""
    need = ray_options(r)
    for node in nodes:
        if node.cpus >= r.cpus and node.gpus >= r.gpus and \
                node.memory >= need.get("memory", 0) and \
                all(node.custom.get(k, 0) >= v for k, v in r.custom.items()):
            return None
    asks = [f"{r.cpus:g} CPU"] + ([f"{r.gpus:g} GPU"] if r.gpus else []) + \
        ([f"{r.memory} of memory"] if r.memory else []) + \
        [f"{v:g} {k}" for k, v in r.custom.items()]
    offers = "; ".join(n.describe() for n in nodes) or "no live node"
    return f"each job asks for {', '.join(asks)}; no node of {where} can give that ({offers})"
