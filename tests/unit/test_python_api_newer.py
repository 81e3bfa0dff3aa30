"""The names launch gained after 3.7 (read from its newest sources; no release holds them, so
the differential corpus cannot record them against a real tool): each does what its source
says."""

from __future__ import annotations

from launcher.api import LaunchDescription, SetLaunchConfiguration
from launcher.api.actions import ReplaceEnvironmentVariables
from launcher.api.substitutions import (
    LaunchConfiguration,
    PathSubstitution,
    StringJoinSubstitution,
    StringStripSubstitution,
)
from launcher.runtime.context import LaunchContext


def context(**configurations: str) -> LaunchContext:
    return LaunchContext({"PATH": "/usr/bin"}, configurations)


def test_a_path_substitution_joins_with_the_slash_operator():
    path = PathSubstitution(LaunchConfiguration("share")) / "urdf" / LaunchConfiguration("robot")
    assert path.perform(context(share="/opt/p", robot="r.urdf")) == "/opt/p/urdf/r.urdf"


def test_string_join_puts_its_delimiter_between_the_performed_texts():
    joined = StringJoinSubstitution(["a", LaunchConfiguration("x"), "c"], delimiter=",")
    assert joined.perform(context(x="b")) == "a,b,c"


def test_string_strip_takes_the_white_space_around_the_text_away():
    assert StringStripSubstitution(LaunchConfiguration("x")).perform(context(x="  v \n")) == "v"


def test_replace_environment_variables_leaves_the_processes_only_the_given_ones():
    from tests.support.fake_service import run

    done, _ = run(LaunchDescription([
        SetLaunchConfiguration("home", "/h"),
        ReplaceEnvironmentVariables({"HOME": LaunchConfiguration("home"), "ONLY": "1"})]),
        environment={"PATH": "/usr/bin", "OTHER": "x"})
    assert done.environment == {"HOME": "/h", "ONLY": "1"}
