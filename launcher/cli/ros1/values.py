"""The message a ROS 1 tool builds from its words (`rostopic pub`, `rosservice call`)."""

from __future__ import annotations

from typing import Any

from launcher.errors import UsageError


def message_values(type_name: str, words: list[str]) -> Any:
    """The message rostopic pub builds from its words: one YAML mapping, or values for the
    fields in their order (`rostopic pub /c std_msgs/String hello`)."""
    import yaml

    from launcher.bus.messages import build, to_data

    loaded = []
    for word in words:
        try:
            loaded.append(yaml.safe_load(word))
        except yaml.YAMLError as exc:
            raise UsageError(f"Argument error: the value '{word}' is not valid YAML: "
                             f"{' '.join(str(exc).split())}") from None
    if not loaded:
        return {}
    if len(loaded) == 1 and (loaded[0] is None or isinstance(loaded[0], dict)):
        return loaded[0] or {}
    fields = list(to_data(build(type_name, {})))
    if len(loaded) > len(fields):
        raise UsageError(f"Argument error: too many arguments: {type_name} has "
                         f"{len(fields)} field(s) ({', '.join(fields)}), {len(loaded)} given")
    return dict(zip(fields, loaded, strict=False))
