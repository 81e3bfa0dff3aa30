"""ROS 1's serialization of launcher's rospy messages, as a bag stores them.

A type is written with ROS 1's definition (rosbags' Noetic store, so its md5sum and bytes are
what ROS 1's own tools expect: a Header's `seq`, a CameraInfo's `D`…), its fields read off
launcher's message by the matching name (ROS 2 spells some in lower case); a type that Noetic
does not have is written with launcher's definition. Messages become rosbags' message objects
and rosbags writes and reads their bytes (its CDR↔ROS 1 conversion assumes ROS 2's Header,
without `seq`, so it is not used). A message whose type launcher does not know, or whose
definition in the bag differs from the one here, is read with the bag's own definition into
one of rosbags' message objects (dataclasses with the same fields), as ROS 1's rosbag builds a
class from the bag's definition.
"""

from __future__ import annotations

import array
import functools
from collections.abc import Callable
from typing import Any

import numpy
from rosbags.typesys import Stores, get_types_from_msg, get_typestore
from rosbags.typesys.store import Typestore

from launcher.bus import kinds
from launcher.bus.cdr import TYPECODES
from launcher.bus.types import UnknownType, normalize, plain, registry
from launcher.compat import rosidl

Reader = Callable[[bytes | memoryview], Any]
_DTYPES = {"byte": "uint8", "char": "uint8"}
_TIMES = ("builtin_interfaces/msg/Time", "builtin_interfaces/msg/Duration")


class Ros1Types:
    """ROS 1 definitions, md5sums and (de)serialization of the types a process uses."""

    def __init__(self) -> None:
        self.store: Typestore = get_typestore(Stores.ROS1_NOETIC)
        self._wire: dict[str, list[tuple[str, Any]]] = {}  # fields, named as launcher's
        self._foreign: dict[tuple[str, str], Typestore] = {}
        self._definitions: dict[str, tuple[str, str]] = {}

    # --- launcher's types ---------------------------------------------------------------
    def ensure(self, type_name: str) -> str:
        """`pkg/msg/Name`, registered here with what it names (UnknownType if launcher does
        not know it either)."""
        name = normalize(type_name)
        if name not in self.store.fielddefs:
            types = registry()
            types.ensure(name)
            self.store.register({key: value for key, value in types.fielddefs.items()
                                 if key not in self.store.fielddefs})
        return name

    def definition(self, type_name: str) -> tuple[str, str]:
        """(ROS 1 message definition text, md5sum) of a type: launcher's, or one a bag
        defined."""
        name = normalize(type_name)
        found = self._definitions.get(name)
        if found is None:
            try:
                found = self.store.generate_msgdef(self.ensure(name))
            except UnknownType:
                store = next((s for (t, _), s in self._foreign.items() if t == name), None)
                if store is None:
                    raise
                found = store.generate_msgdef(name)
            self._definitions[name] = found
        return found

    def _fields(self, name: str) -> list[tuple[str, Any]]:
        found = self._wire.get(name)
        if found is None:
            theirs = [field for field, _ in registry().fields(name)]
            lower = {field.lower(): field for field in theirs}
            found = [(field if field in theirs else lower.get(field.lower(), field), plain(kind))
                     for field, kind in self.store.fielddefs[self.ensure(name)][1]]
            self._wire[name] = found
        return found

    def serialize(self, message: Any) -> tuple[str, bytes]:
        """(type, ROS 1 bytes) of a launcher message, or of one of rosbags' that a bag gave."""
        foreign = getattr(message, "__msgtype__", None)
        if foreign is not None:
            store = next((s for (t, _), s in self._foreign.items() if t == foreign), None)
            return foreign, bytes((store or self.store).serialize_ros1(message, foreign))
        name = self.ensure(rosidl.type_name_of(type(message)))
        try:
            theirs = self._to_rosbags(message, name)
        except AttributeError as exc:
            raise ValueError(f"cannot write {name} in ROS 1's form: {exc}") from None
        return name, bytes(self.store.serialize_ros1(theirs, name))

    def _to_rosbags(self, message: Any, name: str) -> Any:
        def numbers(value: Any, _kind: int, code: str) -> Any:
            if code in TYPECODES:
                return numpy.asarray(value, dtype=_DTYPES.get(code, code))
            return list(value)

        values = _field_values(message, self._fields(name), self._to_rosbags, numbers)
        return self.store.types[name](*values)

    def _from_rosbags(self, theirs: Any, name: str) -> Any:
        def numbers(value: Any, kind: int, code: str) -> Any:
            if code in TYPECODES and kind == kinds.SEQUENCE:
                return array.array(TYPECODES[code], value.tobytes())
            return value

        fields = self.store.fielddefs[name][1]
        return self._make(name, _field_values(theirs, fields, self._from_rosbags, numbers))

    # --- reading ----------------------------------------------------------------------------
    def reader(self, type_name: str, md5sum: str, msgdef: str) -> tuple[Reader, Any]:
        """(bytes → message, the message class) for a bag's connection."""
        name = normalize(type_name)
        try:
            registry().ensure(name)
            ours = self.definition(name)[1] == md5sum
        except (UnknownType, KeyError, ValueError):
            ours = False
        if ours:
            return (lambda data: self._from_rosbags(self.store.deserialize_ros1(data, name),
                                                    name),
                    rosidl.message_class(name))
        store = self._foreign_store(name, md5sum, msgdef)
        return (lambda data: store.deserialize_ros1(data, name)), store.types[name]

    def _make(self, name: str, values: list[Any]) -> Any:
        cls: Any = rosidl.message_class(name)
        given = dict(zip((field for field, _ in self._fields(name)), values, strict=True))
        if len(given) == len(cls._FIELDS) and all(f in given for f in cls._FIELDS):
            message = rosidl.make(name, [given.pop(field) for field in cls._FIELDS])
        else:  # ROS 2 has more fields than ROS 1 had: those keep their defaults
            message = cls(**{field: given.pop(field) for field in cls._FIELDS
                             if field in given})
        for field, value in given.items():  # ROS 1's own (a Header's seq)
            setattr(message, field, value)
        return message

    def _foreign_store(self, name: str, md5sum: str, msgdef: str) -> Typestore:
        store = self._foreign.get((name, md5sum))
        if store is None:
            store = Typestore()
            store.register({key: self.store.fielddefs[key] for key in _TIMES})  # time, duration
            try:
                store.register(get_types_from_msg(msgdef, name))
            except Exception as exc:  # noqa: BLE001 (rosbags' parser says why in its text)
                raise ValueError(f"cannot read {name}: its definition in the bag does not "
                                 f"parse ({exc})") from None
            self._foreign[(name, md5sum)] = store
        return store


def _field_values(message: Any, fields: list[tuple[str, Any]],
                  nested: Callable[[Any, Any], Any],
                  numbers: Callable[[Any, int, str], Any]) -> list[Any]:
    """Each of the `fields` of `message`, converted: a message within by `nested` (each one of
    an array too), any other array by `numbers(value, its kind, the items' type)`."""
    values = []
    for field, (kind, detail) in fields:
        value = getattr(message, field)
        if kind == kinds.NAME:
            value = nested(value, detail)
        elif kind in (kinds.ARRAY, kinds.SEQUENCE):
            (inner, inner_detail), _ = detail
            value = ([nested(item, inner_detail) for item in value] if inner == kinds.NAME
                     else numbers(value, kind, inner_detail[0]))
        values.append(value)
    return values


@functools.cache
def ros1_types() -> Ros1Types:
    """The process's ROS 1 types (made on first use)."""
    return Ros1Types()
