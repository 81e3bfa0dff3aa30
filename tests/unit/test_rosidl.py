"""Message and service classes with rclpy's semantics (launcher/compat/rosidl.py), and the
import hook that serves them (finder.py). Expected texts are rosidl_generator_py's."""

from __future__ import annotations

import array
import os
import subprocess
import sys
import textwrap

import pytest

from launcher.bus.types import registry
from launcher.compat import SITE, finder, rosidl


@pytest.fixture(scope="module", autouse=True)
def hook():
    finder.install()
    yield


def test_keyword_constructor_defaults_repr_and_equality():
    from geometry_msgs.msg import Twist, Vector3

    twist = Twist(linear=Vector3(x=0.5))
    assert twist.linear.x == 0.5 and twist.angular.z == 0.0
    assert repr(twist) == ("geometry_msgs.msg.Twist(linear=geometry_msgs.msg.Vector3(x=0.5, "
                           "y=0.0, z=0.0), angular=geometry_msgs.msg.Vector3(x=0.0, y=0.0, "
                           "z=0.0))")
    assert twist == Twist(linear=Vector3(x=0.5)) and twist != Twist()
    assert Twist(Vector3(x=1.0)).linear.x == 1.0  # positional, in field order (ROS 1)
    assert Twist.get_fields_and_field_types() == {"linear": "geometry_msgs/Vector3",
                                                  "angular": "geometry_msgs/Vector3"}
    assert [repr(s) for s in Twist.SLOT_TYPES] == ["geometry_msgs/Vector3"] * 2
    with pytest.raises(AssertionError, match="Invalid arguments passed to constructor: lineer"):
        Twist(lineer=Vector3())


def test_field_types_are_checked_on_assignment_with_rosidls_texts():
    from example_interfaces.srv import AddTwoInts
    from geometry_msgs.msg import Twist
    from sensor_msgs.msg import JointState
    from std_msgs.msg import String

    twist = Twist()
    with pytest.raises(AssertionError, match="^The 'x' field must be of type 'float'$"):
        twist.linear.x = 1
    with pytest.raises(AssertionError, match="The 'linear' field must be a sub message of "
                                             "type 'Vector3'"):
        twist.linear = 3
    with pytest.raises(AssertionError, match="The 'data' field must be of type 'str'"):
        String(data=5)
    request = AddTwoInts.Request()
    with pytest.raises(AssertionError, match=r"The 'a' field must be an integer in "
                                             r"\[-9223372036854775808, 9223372036854775807\]"):
        request.a = 2**63
    with pytest.raises(AssertionError, match="The 'position' field must be a set or sequence "
                                             "and each value of type 'float'"):
        JointState(position=["x"])
    with pytest.raises(AssertionError, match="The 'name' field must be a set or sequence and "
                                             "each value of type 'str'"):
        JointState(name=[1])
    assert repr(request) == "example_interfaces.srv.AddTwoInts_Request(a=0, b=0)"


def test_numeric_sequences_are_arrays_and_fixed_arrays_numpy_and_cdr_round_trips():
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import JointState

    state = JointState(name=["a", "b"], position=[1.0, 2.0])
    assert isinstance(state.position, array.array) and state.position.typecode == "d"
    data = registry().serialize(state, "sensor_msgs/msg/JointState")
    back = registry().deserialize(data, "sensor_msgs/msg/JointState", rosidl.make)
    assert back == state and type(back) is JointState
    odometry = Odometry()
    odometry.pose.pose.position.x = 3.0
    assert type(odometry.pose.covariance).__name__ == "ndarray"  # float64[36], as rclpy
    odometry.pose.covariance[0] = 0.5
    data = registry().serialize(odometry, "nav_msgs/msg/Odometry")
    back = registry().deserialize(data, "nav_msgs/msg/Odometry", rosidl.make)
    assert back == odometry and back.pose.covariance[0] == 0.5


def test_constants_services_and_ros1_spellings():
    from std_msgs.msg import Header
    from std_srvs.srv import Trigger
    from visualization_msgs.msg import Marker

    assert Marker.ARROW == 0 and Marker.SPHERE == 2
    assert Trigger.Request.__qualname__ == "Trigger_Request"
    assert Trigger.Response().success is False
    header = Header()
    header.stamp.secs = 3
    header.stamp.nsecs = 500
    header.seq = 7  # ROS 1's, not sent
    assert (header.stamp.sec, header.stamp.nanosec, header.seq) == (3, 500, 7)
    assert header.stamp.to_sec() == pytest.approx(3.0000005)


def test_an_unknown_type_import_names_close_types():
    with pytest.raises(ImportError, match="cannot import name 'Twst' from 'geometry_msgs.msg'"
                                          ".*did you mean 'Twist'"):
        from geometry_msgs.msg import Twst  # noqa: F401


def run_python(code: str, env: dict[str, str]) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", textwrap.dedent(code)], env=env,
                          capture_output=True, text=True, timeout=60)


def test_a_real_install_wins_and_the_choice_variable_flips_it(tmp_path):
    """Fake "real" rclpy and std_msgs on PYTHONPATH: they are what is imported; with
    LAUNCHER_ROS_MODULES=launcher, launcher's are."""
    for name in ("rclpy", "std_msgs", "std_msgs/msg"):
        (tmp_path / "real" / name).mkdir(parents=True)
        (tmp_path / "real" / name / "__init__.py").write_text("REAL = True\n")
    env = dict(os.environ, PYTHONPATH=f"{tmp_path / 'real'}{os.pathsep}{SITE}")
    code = """
        import rclpy, std_msgs.msg
        print(getattr(rclpy, 'REAL', False), getattr(std_msgs.msg, 'REAL', False))
    """
    assert run_python(code, env).stdout.split() == ["True", "True"]
    env["LAUNCHER_ROS_MODULES"] = "launcher"
    done = run_python(code, env)
    assert done.stdout.split() == ["False", "False"], done.stderr


def test_standard_modules_with_optional_imports_load_under_the_hook():
    """copy.py tries `org.python.core` while it loads; answering that must not import
    ElementTree (which needs copy whole): xml.dom.minidom, as xacro imports it."""
    env = dict(os.environ, PYTHONPATH=SITE)
    done = run_python("import xml.dom.minidom, copy; print(callable(copy.deepcopy))", env)
    assert done.returncode == 0 and done.stdout.strip() == "True", done.stderr


def test_the_launch_and_xacro_shims_come_from_the_hook_after_any_real_one(tmp_path):
    """What a shell with `launcher env` gets: launch, launch_ros and ament_index_python from
    launcher where none is installed, a real one where it is."""
    env = dict(os.environ, PYTHONPATH=SITE)
    code = """
        import ament_index_python, launch, launch_ros
        print(*(getattr(m, 'REAL', m.__file__.split('/compat/')[-1].split('/')[0])
                for m in (ament_index_python, launch, launch_ros)))
    """
    done = run_python(code, env)
    assert done.stdout.split() == ["shims"] * 3, done.stderr
    (tmp_path / "real" / "launch").mkdir(parents=True)
    (tmp_path / "real" / "launch" / "__init__.py").write_text("REAL = True\n")
    env["PYTHONPATH"] = f"{tmp_path / 'real'}{os.pathsep}{SITE}"
    done = run_python(code, env)
    assert done.stdout.split() == ["shims", "True", "shims"], done.stderr


def test_workspace_messages_are_importable_where_the_site_hook_is_on_the_path(tmp_path):
    package = tmp_path / "ws" / "my_msgs"
    (package / "msg").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>my_msgs</name><version>1.0.0</version><description>d'
        '</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>'
        '</package>')
    (package / "msg" / "Ping.msg").write_text("int32 COUNT=3\nstring text\n"
                                              "geometry_msgs/Point where\n")
    env = dict(os.environ, PYTHONPATH=SITE, LAUNCHER_PACKAGE_PATH=str(tmp_path / "ws"))
    done = run_python("""
        from my_msgs.msg import Ping
        print(Ping(text='hi'), Ping.COUNT)
    """, env)
    assert done.stdout.strip() == ("my_msgs.msg.Ping(text='hi', where=geometry_msgs.msg.Point("
                                   "x=0.0, y=0.0, z=0.0)) 3"), done.stderr


def test_service_halves_by_their_ros1_and_ros2_names():
    from std_srvs.srv import SetBool, SetBool_Response, SetBoolRequest

    assert SetBoolRequest is SetBool.Request and SetBool_Response is SetBool.Response


def workspace_with(tmp_path, kind: str, name: str, text: str) -> dict[str, str]:
    package = tmp_path / "ws" / "my_msgs"
    (package / kind).mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>my_msgs</name><version>1.0.0</version><description>d'
        '</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>'
        '</package>')
    (package / kind / name).write_text(text)
    return dict(os.environ, PYTHONPATH=SITE, LAUNCHER_PACKAGE_PATH=str(tmp_path / "ws"))


def test_a_definitions_default_values_are_what_a_new_message_starts_with(tmp_path):
    env = workspace_with(tmp_path, "msg", "Gains.msg",
                         'int32 count 7\nfloat64[] gains [1.5, 2]  # per joint\n'
                         'string name "bot # one"\nbool on true\nstring[] tags ["a", "b,c"]\n'
                         'int32 plain\n')
    done = run_python("""
        from my_msgs.msg import Gains
        print(Gains())
        print(Gains(count=1).count)
    """, env)
    assert done.stdout.splitlines() == [
        "my_msgs.msg.Gains(count=7, gains=array('d', [1.5, 2.0]), name='bot # one', on=True, "
        "tags=['a', 'b,c'], plain=0)", "1"], done.stderr


def test_service_and_action_parts_keep_their_default_values(tmp_path):
    env = workspace_with(tmp_path, "srv", "Step.srv", "uint64 steps 1\n---\nbool done true\n")
    (tmp_path / "ws" / "my_msgs" / "action").mkdir()
    (tmp_path / "ws" / "my_msgs" / "action" / "Go.action").write_text(
        "float64 speed 0.5\n---\nint8 code -1\n---\nstring state 'moving'\n")
    done = run_python("""
        from my_msgs.srv import Step
        from my_msgs.action import Go
        print(Step.Request().steps, Step.Response().done)
        print(Go.Goal().speed, Go.Result().code, Go.Feedback().state)
    """, env)
    assert done.stdout.splitlines() == ["1 True", "0.5 -1 moving"], done.stderr


def test_messages_built_from_data_take_the_default_values_of_missing_fields(tmp_path):
    env = workspace_with(tmp_path, "msg", "Gains.msg", "int32 count 7\nint32 plain\n")
    done = run_python("""
        from launcher.bus.messages import build
        message = build("my_msgs/msg/Gains", {"plain": 2})
        print(message.count, message.plain)
    """, env)
    assert done.stdout.strip() == "7 2", done.stderr


def test_a_default_value_that_does_not_fit_its_type_is_said_at_its_line(tmp_path):
    from pathlib import Path

    from launcher.bus.interfaces import parse_msg
    from launcher.errors import LaunchError

    with pytest.raises(LaunchError) as raised:
        parse_msg("int32 plain\nint32 count seven\n", "my_msgs/msg/Bad", Path("Bad.msg"))
    assert str(raised.value) == ("Bad.msg:2: invalid default value 'seven' for int32 count "
                                 "(expected a whole number)")


def test_another_threads_standard_import_hides_no_interface_package():
    """A standard library module that another thread is importing (a container loading two
    components at once) does not make this thread's `rcl_interfaces` unknown: only this
    thread's own standard imports are passed over."""
    import importlib
    import types

    busy = types.ModuleType("xml.being_imported")
    busy.__spec__ = importlib.machinery.ModuleSpec("xml.being_imported", None)
    busy.__spec__._initializing = True  # as importlib marks a module it is executing
    sys.modules[busy.__name__] = busy
    gone = {name: sys.modules.pop(name) for name in list(sys.modules)
            if name.partition(".")[0] == "diagnostic_msgs"}
    try:
        assert importlib.import_module("diagnostic_msgs.msg").KeyValue().key == ""
    finally:
        del sys.modules[busy.__name__]
        sys.modules.update(gone)


def test_this_threads_standard_import_is_passed_over():
    """copy's `from org.python.core import …` and the like: an optional import made while a
    standard library module runs is never looked up in the type store."""
    found = {}
    exec(compile("found['inside'] = inside()", "<standard>", "exec"),
         {"__name__": "copy", "found": found, "inside": finder._inside_standard_import})
    assert found["inside"] is True
    assert finder._inside_standard_import() is False
