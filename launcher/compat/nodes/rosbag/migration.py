"""rosbag.migration without migration rules: launcher runs no rule files, so a bag migrates
only where nothing needs migrating. `checkbag` lists the types a bag stores whose definition
differs from launcher's (each needs a rule that is not there); `fixbag2` copies a bag whose
types all match, or writes it unchanged when forced. The rule classes (MessageUpdateRule,
RuleChain, ScaffoldNode) are left out (tests/fidelity/left_out.py)."""

from __future__ import annotations

import itertools
import re
from typing import Any

from rosbags.typesys import get_types_from_msg

from rosbag._ros1 import ros1_types
from rosbag.bag import Bag

_BUILTIN = ("bool", "byte", "int8", "int16", "int32", "int64", "char", "uint8", "uint16",
            "uint32", "uint64", "float32", "float64", "string", "time", "duration")


class BagMigrationException(Exception):
    """A bag that cannot be migrated."""


class MessageMigrator:
    """Finds where a stored type goes: to launcher's type when their definitions match (no
    migration), nowhere otherwise (launcher has no rules to migrate it)."""

    def __init__(self, input_rule_files: list[str] = [], plugins: bool = True) -> None:  # noqa: B006
        if input_rule_files:
            raise BagMigrationException(
                f"cannot load {', '.join(input_rule_files)}: launcher's rosbag runs no "
                "message migration rules")

    def find_target(self, old_class: Any) -> Any:
        """launcher's class of the stored type when its definition is the same, else None."""
        key = get_message_key(old_class)
        try:
            same = key is not None and ros1_types().definition(key[0])[1] == key[1]
        except Exception:  # noqa: BLE001 (a type launcher does not know has no target)
            return None
        return old_class if same else None

    def find_path(self, old_class: Any, new_class: Any) -> list[Any]:
        """The rules from one class to the other: none (the same type, or no rules)."""
        return []

    def all_rules_valid(self) -> bool:
        """Whether every rule loaded is valid: there are none."""
        return True

    def get_invalid_rules(self) -> list[Any]:
        """The rules that are not valid: none."""
        return []

    def migrate(self, msg_from: Any, msg_to: Any) -> None:
        """Copy the fields of one message into another of the same type."""
        for field in getattr(msg_from, "_FIELDS", ()):
            setattr(msg_to, field, getattr(msg_from, field))

    def migrate_raw(self, msg_from: Any, msg_to: Any) -> Any:
        """A raw message moved to its target: unchanged (no rules)."""
        return msg_from


class _Stored:
    """A stored type as migration keys it (its ROS 1 name and md5sum)."""

    def __init__(self, raw: tuple[Any, ...]) -> None:
        self._type, self._md5sum = raw[0], raw[2]


def get_message_key(c: Any) -> tuple[str, str] | None:
    """(type, md5sum) of a class (ROS 1's `_type` and `_md5sum`, or launcher's)."""
    kind = getattr(c, "_type", None) or getattr(c, "_TYPE", None)
    if kind is None:
        return None
    md5sum = getattr(c, "_md5sum", None) or ros1_types().definition(kind)[1]
    return kind, md5sum


def get_path_key(c1: Any, c2: Any) -> tuple[Any, Any]:
    """The key of a migration path between two classes."""
    return get_message_key(c1), get_message_key(c2)


def checkmessages(migrator: MessageMigrator, messages: list[Any]) -> list[Any]:
    """(message, rules) of each message whose type needs migrating."""
    return [(m, []) for m in messages if migrator.find_target(type(m)) is None]


def checkbag(migrator: MessageMigrator, inbag: str) -> list[Any]:
    """(raw message, rules) of each stored type that differs from launcher's: each needs a
    rule, and launcher has none."""
    found, seen = [], set()
    with Bag(inbag) as bag:
        for _topic, raw, _t in bag.read_messages(raw=True):
            stored = _Stored(raw)
            key = (stored._type, stored._md5sum)
            if key not in seen:
                seen.add(key)
                if migrator.find_target(stored) is None:
                    found.append((raw, []))
    return found


def fixbag(migrator: MessageMigrator, inbag: str, outbag: str) -> bool:
    """Copy `inbag` to `outbag` when it needs no migration; whether it was written."""
    return not fixbag2(migrator, inbag, outbag)


def fixbag2(migrator: MessageMigrator, inbag: str, outbag: str, force: bool = False) -> list[Any]:
    """Copy `inbag` to `outbag` when no type needs migrating (or `force`: unchanged); the
    migrations that could not be made (none when forced)."""
    missing = checkbag(migrator, inbag)
    if not missing or force:
        with Bag(inbag) as bag, Bag(outbag, "w", options=bag.options) as out:
            for topic, raw, t, header in bag.read_messages(raw=True,
                                                           return_connection_header=True):
                out.write(topic, raw, t, raw=True, connection_header=header)
    return [] if force else missing


def clean_name(name: str, top_name: str) -> str:
    """A type name without 'std_msgs' and the top-level type's package."""
    parts = name.split("/")
    for package in ("std_msgs", top_name.split("/")[0]):
        if package in parts:
            parts.remove(package)
    return "/".join(parts)


def qualified_name(name: str, top_name: str) -> str:
    """A type name as `pkg/Name`, its package the top-level type's if it has none."""
    cleaned = clean_name(name, top_name)
    if len(cleaned.split("/")) == 2 or re.sub(r"\[\d*\]$", "", cleaned) in _BUILTIN:
        return cleaned
    if cleaned == "Header":
        return "std_msgs/Header"
    return top_name.split("/")[0] + "/" + cleaned


def migration_default_value(field_type: str) -> str:
    """The Python text of a field type's default value, as a migration rule writes it."""
    if field_type in _BUILTIN[:11]:
        return "0"
    if field_type in ("float32", "float64"):
        return "0."
    if field_type == "string":
        return "''"
    array = re.fullmatch(r"(.+)\[(\d*)\]", field_type)
    if array:
        base, length = array.group(1), array.group(2)
        if base in ("byte", "uint8"):
            return f"chr(0)*{length}" if length else "''"
        if not length:
            return "[]"
        return "[" + ",".join(itertools.repeat(migration_default_value(base), int(length))) + "]"
    return f"self.get_new_class('{field_type}')()"


def constants_from_def(core_type: str, msg_def: str) -> set[tuple[str, Any, str]]:
    """{(name, value, type)} of the constants of a type's definition text."""
    core = msg_def.split("\n" + "=" * 80 + "\n")[0]
    name = core_type if "/msg/" in core_type else core_type.replace("/", "/msg/", 1)
    constants = get_types_from_msg(core, name)[name][0]
    return {(constant, value, kind) for constant, kind, value in constants}
