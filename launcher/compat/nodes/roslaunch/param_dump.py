"""roslaunch.param_dump: the parameters the launch files set, as `roslaunch --dump-params`
prints them."""

from __future__ import annotations

import sys

from roslaunch.config import load_config_default
from roslaunch.core import RLException


def dump_params(files: list[str]) -> bool:
    """Print the parameters the files set, as YAML ({full name: value}); False (with the
    error on stderr) when they cannot be loaded."""
    import yaml

    try:
        config = load_config_default(files, None, verbose=False)
    except RLException as exc:
        print(str(exc), file=sys.stderr)
        return False
    values = {key: param.value for key, param in sorted(config.params.items())}
    print(yaml.safe_dump(values, default_flow_style=False), end="")
    return True
