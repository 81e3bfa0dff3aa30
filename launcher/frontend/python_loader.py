"""Python launch files: a module with `generate_launch_description()`.

The file is the user's own code and runs as such (as `ros2 launch` runs it); substitution
text in it is still never evaluated as Python. An exception inside the file is reported with
its traceback trimmed to the frames of the user's file.
"""

from __future__ import annotations

import importlib.util
import itertools
import sys
import traceback
from pathlib import Path

from launcher import compat
from launcher.description.action import LaunchDescription
from launcher.errors import Location, ParseError

_counter = itertools.count()


def load_python(path: Path) -> LaunchDescription:
    compat.enable_in_process()  # ROS 2 files import launch, launch_ros, ament_index_python
    name = f"_launcher_launch_file_{next(_counter)}"
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise ParseError("cannot load this Python file", Location(str(path)))
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
        generate = getattr(module, "generate_launch_description", None)
        if generate is None:
            raise ParseError("a Python launch file must define generate_launch_description()",
                             Location(str(path)))
        result = generate()
    except ParseError:
        raise
    except SyntaxError as exc:
        where = Location(str(path), exc.lineno or 0, exc.offset or 0)
        raise ParseError(f"invalid Python: {exc.msg}", where) from None
    except Exception as exc:  # the user's code failed: show where, in their file
        raise _user_error(exc, path) from None
    finally:
        sys.modules.pop(name, None)
    if not isinstance(result, LaunchDescription):
        raise ParseError(f"generate_launch_description() returned {type(result).__name__}, "
                         "expected a LaunchDescription", Location(str(path)))
    result.file = path
    return result


def _user_error(exc: Exception, path: Path) -> ParseError:
    frames = traceback.extract_tb(exc.__traceback__)
    mine = [f for f in frames if Path(f.filename) == path]
    last = mine[-1] if mine else None
    where = Location(str(path), last.lineno or 0) if last else Location(str(path))
    trace = "".join(traceback.format_list(mine)).rstrip()
    text = f"{type(exc).__name__}: {exc}"
    return ParseError(f"the launch file raised {text}" + (f"\n{trace}" if trace else ""), where)


