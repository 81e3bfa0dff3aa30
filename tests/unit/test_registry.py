import types

import pytest

from launcher.description.action import Action
from launcher.description.registry import BUILTINS, Registry, action


def test_index_matches_the_decorators():
    """Every indexed name is defined by its module, and every marked class is indexed."""
    registry = Registry()
    registry.load_all()
    assert set(registry.actions) == set(BUILTINS["action"])
    assert set(registry.substitutions) == set(BUILTINS["substitution"])
    for name, cls in registry.actions.items():
        assert cls.__module__ == BUILTINS["action"][name]
    for name, cls in registry.substitutions.items():
        assert cls.__module__ == BUILTINS["substitution"][name]


def test_lookup_imports_only_what_is_used():
    registry = Registry()
    assert registry.find_action("log").__name__ == "Log"
    assert "executable" not in registry.actions
    assert registry.find_action("nonsense") is None
    assert "executable" in registry.known("action")


def test_a_name_defined_twice_is_rejected():
    module = types.ModuleType("plugin_twice")

    @action("log")
    class Other(Action):
        pass

    Other.__module__ = "plugin_twice"
    module.Other = Other
    registry = Registry()
    registry.find_action("log")
    with pytest.raises(RuntimeError, match="action 'log' is defined twice"):
        registry.load([module])
