"""`catkin_make [-C DIR] [--source DIR] …`, as the course runs it (packages/catkin.py): says
catkin_make's spaces, reads every package.xml, makes Python scripts runnable, says each C++
target it leaves out, and writes devel/setup.bash."""

from __future__ import annotations

import argparse
from pathlib import Path

from launcher.arguments import Parser
from launcher.packages.manifest import Package


def main(argv: list[str], prog: str = "catkin_make") -> int:
    p = Parser(prog=prog, description="catkin_make for launcher: the packages of src/ are "
                                      "used in place; devel/setup.bash puts them on the path")
    p.add_argument("-C", "--directory", default=".", help="the workspace (default: here)")
    p.add_argument("--source", default=None, help="the source space (default: DIR/src)")
    p.add_argument("-j", dest="jobs", help=argparse.SUPPRESS)
    p.add_argument("--pkg", nargs="+", default=None, help="only these packages")
    p.add_argument("targets", nargs="*", help="make targets (all, install: the same here)")
    args, _cmake_args = p.parse_known_args(argv)  # -DCMAKE_… and the like: CMake's, unused

    from launcher import compat
    from launcher.packages import catkin

    workspace = Path(args.directory).resolve()
    source = Path(args.source).resolve() if args.source else catkin.check_source(workspace)
    print(f"Base path: {workspace}\nSource space: {source}\nBuild space: "
          f"{workspace / 'build'}\nDevel space: {workspace / 'devel'}\nInstall space: "
          f"{workspace / 'install'}")
    found = catkin.packages(source)
    if args.pkg:
        found = [pkg for pkg in found if pkg.name in args.pkg]
    print(f"####\n#### launcher: {len(found)} package(s) in {source}, used in place\n####")
    for package in found:
        print(f"-- ~~  - {package.name}")
    for package in found:
        for script in catkin.python_scripts(package):
            if catkin.make_runnable(script):
                print(f"-- {package.name}: {script.relative_to(package.path)} made runnable")
        for where, command, target in catkin.cxx_targets(package):
            print(f"{where}: warning: {command}({target}) of package '{package.name}' is C++, "
                  "left out: C++ Gazebo plugins and nodes are not supported by launcher; "
                  "use a Python plugin (GZ_SIM_SYSTEM_PLUGIN_PATH) or the /gazebo/* "
                  "services, and rospy nodes", flush=True)
    devel = catkin.write_devel(workspace, compat.COMMANDS)
    print(f"-- wrote {devel / 'setup.bash'}: source it to use the workspace's packages")
    if "run_tests" in args.targets:
        run_tests(found, workspace / "build" / "test_results")
    return 0


def run_tests(packages: list[Package], results: Path) -> None:
    """`catkin_make run_tests`: each package's add_rostest files through rostest, their
    results under build/test_results/PKG (catkin_test_results reads them). As catkin's
    target, it succeeds whatever the tests say. The workspace's packages are found as its
    devel space would give them."""
    import os

    from launcher.cli.ros1 import rostest
    from launcher.packages import catkin

    folders = [str(package.path.parent) for package in packages]
    os.environ["LAUNCHER_PACKAGE_PATH"] = os.pathsep.join(
        [*folders, *filter(None, [os.environ.get("LAUNCHER_PACKAGE_PATH")])])
    for package in packages:
        for test_file, arguments in catkin.rostests(package):
            print(f"-- run_tests: {package.name}: rostest {test_file.name}", flush=True)
            rostest.main([package.name, test_file.name, *arguments,
                          "--results-base-dir", str(results)])
