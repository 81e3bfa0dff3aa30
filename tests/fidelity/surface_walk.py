"""Walk installed packages and print their public surface as JSON (run by surface.py inside
the interpreter that has the real packages; imports nothing of launcher's or of the tests).

`python surface_walk.py ROOT...`: for each root package, every public module (no part of its
dotted name starts with `_`), and in each module its public names: `__all__` where the module
has one, else the names not starting with `_` whose object is defined in the root package or
is a plain constant. A class is recorded with its signature, its bases, its public members
(methods, properties, attributes of its own and of the package's classes it derives from)
and, for an enum, its members.
"""

from __future__ import annotations

import enum
import importlib
import inspect
import json
import pkgutil
import sys
import warnings

CONSTANT_TYPES = (int, float, str, bytes, bool, tuple, frozenset, type(None))
NOT_THEIRS = {"TYPE_CHECKING"}  # typing's, imported


def public(dotted: str) -> bool:
    return not any(part.startswith("_") for part in dotted.split("."))


def modules(root: str) -> dict[str, object]:
    found: dict[str, object] = {}
    try:
        package = importlib.import_module(root)
    except Exception as exc:  # noqa: BLE001 (recorded, not raised)
        return {root: exc}
    found[root] = package
    for info in pkgutil.walk_packages(getattr(package, "__path__", []), root + ".",
                                      onerror=lambda name: None):
        if not public(info.name) or info.name.rpartition(".")[2] in ("conftest", "test"):
            continue
        try:
            found[info.name] = importlib.import_module(info.name)
        except BaseException as exc:  # noqa: BLE001 (a module that needs what is not here)
            found[info.name] = exc
    return found


def parameters(thing: object) -> list[list[object]] | None:
    try:
        signature = inspect.signature(thing)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return None
    out = []
    for parameter in signature.parameters.values():
        default = None if parameter.default is inspect.Parameter.empty else \
            repr(parameter.default)[:80]
        out.append([parameter.name, parameter.kind.name, default])
    return out


def member_kind(raw: object) -> str:
    if isinstance(raw, property):
        return "property"
    if isinstance(raw, classmethod):
        return "classmethod"
    if isinstance(raw, staticmethod):
        return "staticmethod"
    if inspect.isfunction(raw) or inspect.ismethoddescriptor(raw):
        return "method"
    if inspect.isclass(raw):
        return "class"
    return "attribute"


def members(cls: type, root: str) -> dict[str, dict[str, object]]:
    out: dict[str, dict[str, object]] = {}
    for klass in reversed(cls.__mro__):
        if not (getattr(klass, "__module__", "") or "").startswith(root):
            continue
        for name, raw in vars(klass).items():
            if name.startswith("_") and name != "__init__":
                continue
            if name == "__init__" or isinstance(raw, enum.Enum):
                continue
            kind = member_kind(raw)
            entry: dict[str, object] = {"kind": kind}
            if kind in ("method", "classmethod", "staticmethod"):
                function = getattr(raw, "__func__", raw)
                entry["signature"] = parameters(function)
            out[name] = entry
    return out


def describe(name: str, thing: object, root: str) -> dict[str, object]:
    if inspect.isclass(thing):
        entry: dict[str, object] = {
            "kind": "enum" if issubclass(thing, enum.Enum) else "class",
            "module": thing.__module__,
            "bases": [f"{b.__module__}.{b.__qualname__}" for b in thing.__bases__],
            "signature": parameters(thing),
            "members": members(thing, root),
        }
        if issubclass(thing, enum.Enum):
            entry["enum"] = [member.name for member in thing]
        return entry
    if callable(thing):
        return {"kind": "function", "module": getattr(thing, "__module__", None),
                "signature": parameters(thing)}
    return {"kind": "constant", "type": type(thing).__name__}


def own(thing: object, root: str) -> bool:
    if inspect.ismodule(thing):
        return False
    if inspect.isclass(thing) or callable(thing):
        return (getattr(thing, "__module__", "") or "").split(".")[0] == root
    return isinstance(thing, CONSTANT_TYPES)


def surface(root: str) -> dict[str, object]:
    out: dict[str, object] = {}
    for dotted, module in sorted(modules(root).items()):
        if isinstance(module, BaseException):
            out[dotted] = {"error": f"{type(module).__name__}: {module}"[:300]}
            continue
        listed = getattr(module, "__all__", None)
        names = list(listed) if listed is not None else [
            name for name, thing in vars(module).items()
            if not name.startswith("_") and name not in NOT_THEIRS and own(thing, root)]
        entries = {}
        for name in sorted(set(names)):
            if not hasattr(module, name):
                continue  # __all__ naming what the module lacks (a bug of theirs)
            thing = getattr(module, name)
            if inspect.ismodule(thing):
                continue
            entries[name] = describe(name, thing, root)
        out[dotted] = {"names": entries, "all": listed is not None}
    return out


def main() -> None:
    warnings.simplefilter("ignore")
    json.dump({root: surface(root) for root in sys.argv[1:]}, sys.stdout, indent=1,
              sort_keys=True)


if __name__ == "__main__":
    main()
