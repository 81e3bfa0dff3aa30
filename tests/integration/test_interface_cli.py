"""`launcher interface …` as `ros2 interface` has it: the distro's types and the packages' own
files, through the real command."""

from __future__ import annotations


def test_show_a_distro_message_with_its_nested_types(ws):
    shown = ws.run("interface", "show", "geometry_msgs/msg/Twist")
    assert shown.returncode == 0, shown.stderr
    assert shown.stdout.startswith("geometry_msgs/Vector3 linear\n\tfloat64 x\n\tfloat64 y\n")
    constants = ws.run("interface", "show", "sensor_msgs/msg/NavSatStatus").stdout
    assert "int8 STATUS_FIX=0\n" in constants and constants.endswith("uint16 service\n")


def test_show_a_packages_service_as_its_file_says(ws):
    shown = ws.run("interface", "show", "std_srvs/srv/SetBool").stdout
    assert shown.startswith("bool data") and "\n---\n" in shown and "string message" in shown


def test_proto_list_package_packages(ws):
    proto = ws.run("interface", "proto", "geometry_msgs/msg/Vector3").stdout
    assert proto == '"x: 0.0\ny: 0.0\nz: 0.0\n"\n'
    listed = ws.run("interface", "list").stdout
    assert listed.startswith("Messages:\n") and "\nServices:\n" in listed
    assert "    std_msgs/msg/String\n" in listed and "    std_srvs/srv/Trigger\n" in listed
    services = ws.run("interface", "list", "-s").stdout
    assert "Messages:" not in services and "    std_srvs/srv/SetBool\n" in services
    assert ws.run("interface", "package", "std_srvs").stdout.split() == \
        ["std_srvs/srv/Empty", "std_srvs/srv/SetBool", "std_srvs/srv/Trigger"]
    packages = ws.run("interface", "packages").stdout.split()
    assert "geometry_msgs" in packages and "std_srvs" in packages


def test_unknown_types_and_packages_say_did_you_mean(ws):
    unknown = ws.run("interface", "show", "geometry_msgs/msg/Twits")
    assert unknown.returncode == 1
    assert "unknown type 'geometry_msgs/msg/Twits' (did you mean 'geometry_msgs/msg/Twist'" \
        in unknown.stderr and "Traceback" not in unknown.stderr
    package = ws.run("interface", "package", "std_srv")
    assert package.returncode == 1 and "did you mean 'std_srvs'" in package.stderr
