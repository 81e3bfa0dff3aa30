"""Console scripts read from setup.py without running it (launcher/packages/setup_py.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from launcher.errors import LaunchError
from launcher.packages.setup_py import console_scripts
from tests.support.environment import shared


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "setup.py"
    path.write_text(text)
    return path


def test_literals_names_concatenation_and_formatting(tmp_path):
    path = write(tmp_path, """from setuptools import setup
package_name = 'talk'
setup(
    name=package_name,
    entry_points={
        'console_scripts': [
            'talker = ' + package_name + '.talker:main',
            f'listener = {package_name}.listener:main',
            'echo = %s.echo:main' % package_name,
            'shout ='
            ' talk.shout:main',
        ],
    },
)
""")
    assert [(n, t) for n, t, _ in console_scripts(path)] == [
        ("talker", "talk.talker:main"), ("listener", "talk.listener:main"),
        ("echo", "talk.echo:main"), ("shout", "talk.shout:main")]


def test_no_entry_points_is_none(tmp_path):
    assert console_scripts(write(tmp_path, "from setuptools import setup\nsetup(name='x')\n")) \
        == []


def test_an_entry_point_computed_at_run_time_is_an_error_at_its_place(tmp_path):
    path = write(tmp_path, "import os\nfrom setuptools import setup\n"
                           "setup(name='x',\n      entry_points={'console_scripts': "
                           "[os.environ['X']]})\n")
    with pytest.raises(LaunchError) as caught:
        console_scripts(path)
    text = str(caught.value)
    assert "cannot read setup.py's entry_points without running it: a subscript expression" \
        in text and "setup.cfg" in text
    assert caught.value.location.line == 4 and caught.value.location.column == 41


def test_a_syntax_error_names_the_line(tmp_path):
    with pytest.raises(LaunchError, match="cannot read setup.py") as caught:
        console_scripts(write(tmp_path, "setup(\n"))
    assert caught.value.location.file.endswith("setup.py")


@pytest.mark.parametrize("package, expected", [
    ("topics/minimal_publisher", {"publisher_old_school", "publisher_local_function",
                                  "publisher_member_function"}),
    ("topics/minimal_subscriber", {"subscriber_old_school", "subscriber_lambda",
                                   "subscriber_member_function"}),
    ("services/minimal_service", {"service", "service_member_function"}),
    ("services/minimal_client", {"client", "client_async", "client_async_member_function",
                                 "client_async_callback"}),
])
def test_the_ros2_examples_setup_files(package, expected):
    found = console_scripts(shared("external", "ros2_examples", "rclpy", package, "setup.py"))
    assert {name for name, _, _ in found} == expected
    assert all(":main" in target for _, target, _ in found)
