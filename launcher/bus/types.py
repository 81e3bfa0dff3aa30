"""ROS 2 message and service types: definitions, CDR, and RIHS01 type hashes.

Definitions come from rosbags' Jazzy typestore (one pinned distro, so hashes do not move) and
from `msg/*.msg` and `srv/*.srv` files of packages. Building the whole Jazzy typestore takes
~0.2 s, so its field definitions and type hashes are cached once as a pickle (per rosbags
version), with plain numbers for the kinds of fields, so that a node reads them without
importing rosbags. The message classes of launcher's own node API are made here too
(message_class.py, shaped as rosbags makes them); rosbags' Typestore itself (for bags, and the
hashes of package types) is made on first use, with the types used so far.
"""

from __future__ import annotations

import contextlib
import importlib.util
import os
import pickle
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from launcher.bus import interfaces, kinds, message_class
from launcher.bus.cdr import MSG, MSGS, PRIMS, CdrError, Codec, Unsupported
from launcher.errors import LaunchError, did_you_mean

DISTRO = "ros2_jazzy"


class UnknownType(LaunchError):
    pass


def _cache_file() -> Path:
    """Named after the store file's size and time: a new rosbags makes a new cache."""
    spec = importlib.util.find_spec("rosbags")  # (found, not imported)
    assert spec is not None and spec.submodule_search_locations
    store = os.path.join(spec.submodule_search_locations[0], "typesys", "stores",
                         f"{DISTRO}.py")
    stat = os.stat(store)
    base = os.environ.get("LAUNCHER_CACHE_DIR") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "launcher")
    return Path(base) / f"types2-{DISTRO}-{stat.st_size}-{int(stat.st_mtime)}.pickle"


def _distro() -> tuple[dict[str, Any], dict[str, str]]:
    """(field definitions, RIHS01 hashes) of every type of the distro."""
    path = _cache_file()
    try:
        with open(path, "rb") as handle:
            fielddefs, hashes = pickle.load(handle)
        return fielddefs, hashes
    except (OSError, pickle.UnpicklingError, EOFError, ValueError, TypeError):
        pass
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(getattr(Stores, DISTRO.upper()))
    fielddefs = {name: plain(definition) for name, definition in store.fielddefs.items()}
    hashes = {name: store.hash_rihs01(name) for name in fielddefs}
    try:  # a cache only: a home that cannot be written costs start-up time, nothing else
        path.parent.mkdir(parents=True, exist_ok=True)
        temporary = path.with_suffix(f".{os.getpid()}.tmp")
        with open(temporary, "wb") as handle:
            pickle.dump((fielddefs, hashes), handle, protocol=pickle.HIGHEST_PROTOCOL)
        os.replace(temporary, path)
    except OSError:
        pass
    return fielddefs, hashes


def plain(value: Any) -> Any:
    """A field definition with rosbags' Nodetype members as the numbers they are."""
    if isinstance(value, tuple):
        return tuple(plain(item) for item in value)
    if isinstance(value, list):
        return [plain(item) for item in value]
    if isinstance(value, int) and not isinstance(value, bool):
        return int(value)
    return value


def normalize(name: str) -> str:
    """`geometry_msgs/Twist` and `geometry_msgs/msg/Twist` both mean the latter."""
    parts = name.strip().split("/")
    if len(parts) == 2:
        return f"{parts[0]}/msg/{parts[1]}"
    return name.strip()


class TypeRegistry:
    def __init__(self) -> None:
        self.fielddefs: dict[str, Any] = {}  # the types in use, with what they name
        self._store: Any = None
        self._unregistered: dict[str, Any] = {}  # ensured since the store last looked
        self._available: dict[str, Any] = {}
        self._loaded_distro = False
        self._hashes: dict[str, str] = {}
        self._distro_hashes: dict[str, str] = {}
        self.services: dict[str, dict[str, Any]] = {}  # service -> its hashing definitions
        self._index: Any = None
        self._codec: Any = None
        self._numeric_fields: dict[str, list[tuple[int, str]]] = {}
        self._classes: dict[str, type] = {}

    # --- definitions ------------------------------------------------------------------------
    def _definitions(self) -> dict[str, Any]:
        if not self._loaded_distro:
            fielddefs, self._distro_hashes = _distro()
            self._available = {**fielddefs, **self._available}
            self._loaded_distro = True
        return self._available

    @property
    def store(self) -> Any:
        """rosbags' Typestore with every type in use registered (made on first use)."""
        if self._store is None:
            from rosbags.typesys.store import Typestore

            self._store = Typestore()
            self._unregistered = dict(self.fielddefs)
        if self._unregistered:
            self._store.register({k: v for k, v in self._unregistered.items()
                                  if k not in self._store.fielddefs})
            self._unregistered = {}
        return self._store

    def known(self) -> Iterable[str]:
        return self._definitions().keys()

    def ensure(self, name: str) -> str:
        name = normalize(name)
        if name in self.fielddefs:
            return name
        available = self._definitions()
        if name not in available and name.endswith("_Event") and "/srv/" in name:
            return self.service_event(name.removesuffix("_Event"))  # introspection's events
        if name not in available and not self._from_package(name):
            known = [*available, *self._package_types(name)]
            raise UnknownType(f"unknown message type '{name}'{did_you_mean(name, known)}")
        needed: dict[str, Any] = {}
        self._collect(name, available, needed)
        self.fielddefs.update(needed)
        if self._store is not None:
            self._unregistered.update(needed)
        return name

    def _from_package(self, name: str) -> bool:
        """Look for `pkg/msg/Name.msg`, `pkg/srv/Name.srv` or `pkg/action/Name.action` in the
        package index."""
        parts = name.split("/")
        if len(parts) != 3 or parts[1] not in ("msg", "srv", "action"):
            return False
        for half in ("_Request", "_Response"):  # a service's halves come with the service
            if parts[1] in ("srv", "action") and name.endswith(half):
                return self._from_package(name.removesuffix(half))
        if parts[1] == "action":  # an action's parts come with the action
            for part in interfaces.ACTION_SUFFIXES:
                if name.endswith(part):
                    return self._from_package(name.removesuffix(part))
        index = self.package_index()
        if parts[0] not in index:  # a package made since the index was built?
            self._index = None
            index = self.package_index()
        if parts[0] not in index:
            return False
        found = interfaces.find_definition(name, index.share(parts[0]))
        if found is None:
            return self._ros1_action(name, index)
        kind, path = found
        text = path.read_text(encoding="utf-8")
        parse = {"msg": interfaces.parse_msg, "srv": interfaces.parse_srv,
                 "action": interfaces.parse_action}[kind]
        self._available.update(parse(text, name, path))
        if kind == "srv":
            self.services[name] = interfaces.service_hash_definitions(name)
        if kind == "action":
            for service in (f"{name}_SendGoal", f"{name}_GetResult"):
                self.services[service] = interfaces.service_hash_definitions(service)
        return True

    def _package_types(self, name: str) -> list[str]:
        """The types `pkg/kind/…` a package of the index has (read or not yet): what an
        unknown name of it may have meant."""
        parts = name.split("/")
        index = self.package_index()
        if len(parts) != 3 or parts[0] not in index:
            return []
        folder = index.share(parts[0]) / parts[1]
        try:
            return [f"{parts[0]}/{parts[1]}/{path.stem}" for path in folder.iterdir()
                    if path.suffix == f".{parts[1]}"]
        except OSError:
            return []

    def _ros1_action(self, name: str, index: Any) -> bool:
        """A ROS 1 action's messages (`pkg/msg/FibonacciActionGoal`, …) made from the
        package's `action/Fibonacci.action`, as genaction makes them."""
        found = interfaces.ros1_action_base(name)
        if found is None:
            return False
        package, action = found
        path = index.share(package) / "action" / f"{action}.action"
        if not path.is_file():
            return False
        self._available.update(interfaces.parse_ros1_action(
            path.read_text(encoding="utf-8"), package, action, path))
        return name in self._available

    def action(self, name: str) -> str:
        """An action type (its goal, result, feedback, services and feedback message
        registered for CDR); an unknown one is an error with "did you mean"."""
        name = normalize(name)
        if f"{name}_Goal" not in self.fielddefs and f"{name}_Goal" not in self._available \
                and not self._from_package(name):
            raise UnknownType(f"unknown action type '{name}'"
                              f"{did_you_mean(name, _package_actions())}")
        for part in ("_Goal", "_Result", "_Feedback", "_FeedbackMessage"):
            self.ensure(f"{name}{part}")
        for service in ("_SendGoal", "_GetResult"):
            self.service(f"{name}{service}")
        return name

    def package_index(self) -> Any:
        """The package index, built once and rebuilt when a package is not found in it."""
        if self._index is None:
            from launcher.packages.index import PackageIndex  # only for non-distro types

            self._index = PackageIndex.from_environment()
        return self._index

    def service(self, name: str) -> tuple[str, str]:
        """(request type, response type) of a service type, registered for CDR."""
        name = normalize(name)
        if name not in self.services and not self._from_package(name):
            known = _package_services()
            raise UnknownType(f"unknown service type '{name}'{did_you_mean(name, known)}")
        return self.ensure(f"{name}_Request"), self.ensure(f"{name}_Response")

    def service_event(self, name: str) -> str:
        """`pkg/srv/Name_Event`, the message service introspection publishes (its info, the
        request and the response), registered for CDR."""
        name = normalize(name)
        self.service(name)
        event = f"{name}_Event"
        if event not in self.fielddefs:
            definitions = self.services.get(name) or interfaces.service_hash_definitions(name)
            for key, value in definitions.items():
                if key != name:  # (the service itself is no message)
                    self._available.setdefault(key, value)
        return self.ensure(event)

    def service_hash(self, name: str) -> str:
        """ROS 2's RIHS01 hash of a service type (see interfaces.py)."""
        request, response = self.service(name)
        if name not in self._hashes:
            from rosbags.typesys.store import Typestore

            hashing = Typestore()
            hashing.fielddefs.update(self.fielddefs)
            hashing.fielddefs.update(self.services[normalize(name)])
            hashing.fielddefs.setdefault(interfaces.TIME, self._definitions()[interfaces.TIME])
            self._hashes[name] = hashing.hash_rihs01(normalize(name))
        return self._hashes[name]

    def _collect(self, name: str, available: dict[str, Any], out: dict[str, Any]) -> None:
        if name in out or name in self.fielddefs:
            return
        constants, fields = available[name]
        # an empty structure is one uint8, as rosbags and ROS 2 write it
        out[name] = (constants, fields or [("structure_needs_at_least_one_member",
                                            (kinds.BASE, ("uint8", 0)))])
        for _, (kind, detail) in available[name][1]:
            for candidate in _referenced(kind, detail):
                if candidate not in available and "/" in candidate:
                    self._from_package(candidate)  # a package type naming another
                if candidate in available:
                    self._collect(candidate, available, out)

    # --- messages ---------------------------------------------------------------------------
    def message_class(self, name: str) -> type:
        """The class of a type's messages for launcher's node API (message_class.py)."""
        found = self._classes.get(name)
        if found is None:
            name = self.ensure(name)
            found = self._classes.get(name)
            if found is None:
                found = message_class.make(name, [f for f, _ in self.fields(name)])
                self._classes[name] = found
        return found

    @property
    def codec(self) -> Any:
        if self._codec is None:
            self._codec = Codec(self.fields)
        return self._codec

    def serialize(self, message: Any, name: str) -> bytes:
        """CDR of a message (any object with the type's fields as attributes)."""
        name = self.ensure(name)
        try:
            return self.codec.serialize(message, name)
        except Unsupported as exc:
            raise LaunchError(f"{name}: {exc}") from None

    def writer(self, name: str) -> Callable[[Any], bytes]:
        """serialize() for one type, its name resolved once (a publisher's)."""
        name = self.ensure(name)
        serialize = self.codec.serialize

        def write(message: Any) -> bytes:
            try:
                return serialize(message, name)
            except Unsupported as exc:
                raise LaunchError(f"{name}: {exc}") from None
        return write

    def reader(self, name: str, make: Any = None) -> Callable[[bytes | memoryview], Any]:
        """deserialize() for one type, its name resolved once (a subscription's)."""
        name = self.ensure(name)
        if make is None:  # the class (and numpy for its arrays) now, not at the first message
            self.message_class(name)
            with contextlib.suppress(Unsupported):  # (said at the first message)
                if self._numeric_arrays(name, set()):
                    import numpy  # noqa: F401
        deserialize, make = self.codec.deserialize, make or self._new_message

        def read(data: bytes | memoryview) -> Any:
            try:
                return deserialize(data, name, make)
            except Unsupported as exc:
                raise LaunchError(f"{name}: {exc}") from None
            except CdrError as exc:
                raise ValueError(f"malformed {name}: {exc}") from None
        return read

    def _numeric_arrays(self, name: str, seen: set[str]) -> bool:
        """Whether a type holds numeric arrays, itself or in the types it names."""
        seen.add(name)
        for _field, kind, detail in self.codec.plan(name):
            inner = detail if kind == MSG else detail[0] if kind == MSGS else None
            if kind == PRIMS or (inner is not None and inner not in seen
                                 and self._numeric_arrays(inner, seen)):
                return True
        return False

    def deserialize(self, data: bytes | memoryview, name: str,
                    make: Any = None) -> Any:
        """The message in a CDR payload: the type's class (numeric arrays as numpy arrays),
        or what `make(type, values)` builds from each type's field values."""
        name = self.ensure(name)
        try:
            return self.codec.deserialize(data, name, make or self._new_message)
        except Unsupported as exc:
            raise LaunchError(f"{name}: {exc}") from None
        except CdrError as exc:
            raise ValueError(f"malformed {name}: {exc}") from None

    def _new_message(self, name: str, values: list[Any]) -> Any:
        arrays = self._numeric_fields.get(name)
        if arrays is None:
            arrays = [(i, detail[4]) for i, (_f, kind, detail) in
                      enumerate(self.codec.plan(name)) if kind == PRIMS]
            self._numeric_fields[name] = arrays
        if arrays:
            import numpy  # the classes hold numeric arrays as numpy arrays, as rosbags' do

            for index, base in arrays:
                dtype = {"byte": "uint8", "char": "uint8"}.get(base, base)
                values[index] = numpy.array(values[index], dtype=dtype)
        return self.message_class(name)(*values)

    def definition(self, name: str) -> str:
        """The type's ros2msg text, each type it names after it (`MSG: pkg/Type` under a
        line of '='), as rosbag2's MCAP files and Foxglove take it."""
        name = self.ensure(name)  # (first: the store registers what is ensured)
        return str(self.store.generate_msgdef(name, ros_version=2)[0])

    def type_hash(self, name: str) -> str:
        name = self.ensure(name)
        if name not in self._hashes:
            if name in self._distro_hashes:  # (a package cannot redefine a distro type)
                self._hashes[name] = self._distro_hashes[name]
            else:
                self._hashes[name] = self.store.hash_rihs01(name)
        return self._hashes[name]

    def fields(self, name: str) -> list[tuple[str, Any]]:
        return list(self.fielddefs[self.ensure(name)][1])

    def defaults(self, name: str) -> dict[str, Any]:
        """The fields of `name` its definition gives a default value (interfaces.py)."""
        return interfaces.DEFAULTS.get(self.ensure(name), {})


def _referenced(kind: Any, detail: Any) -> list[str]:
    """Type names a field refers to (names, sequences and arrays of names)."""
    if isinstance(detail, str):
        return [detail]
    if isinstance(detail, tuple):
        found = []
        for item in detail:
            if isinstance(item, tuple) and len(item) == 2:
                found += _referenced(item[0], item[1])
            elif isinstance(item, str):
                found.append(item)
        return found
    return []


def _package_services() -> list[str]:
    """Every `pkg/srv/Name` the packages define (for "did you mean")."""
    return _package_interfaces("srv")


def _package_actions() -> list[str]:
    """Every `pkg/action/Name` the packages define (for "did you mean")."""
    return _package_interfaces("action")


def _package_interfaces(kind: str) -> list[str]:
    from launcher.packages.index import PackageIndex  # only when reporting an error

    found = []
    for package in PackageIndex.from_environment():
        folder = package.path / kind
        if folder.is_dir():
            found += [f"{package.name}/{kind}/{p.stem}" for p in folder.glob(f"*.{kind}")]
    return sorted(found)


_registry: TypeRegistry | None = None


def registry() -> TypeRegistry:
    global _registry
    if _registry is None:
        _registry = TypeRegistry()
    return _registry
