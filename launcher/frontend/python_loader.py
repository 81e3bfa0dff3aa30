"""Python launch files: a module with `generate_launch_description()`.

The file is the user's own code and runs as such (as `ros2 launch` runs it); substitution
text in it is still never evaluated as Python. An exception inside the file is reported with
its traceback trimmed to the frames of the user's file; so are sys.exit() and a
KeyboardInterrupt the file raises itself, which would otherwise end the launcher as if it were
done or Ctrl-C had been pressed.
"""

from __future__ import annotations

import importlib.util
import itertools
import re
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

from launcher import compat
from launcher.description import made_by_code
from launcher.description.action import LaunchDescription, LaunchDescriptionEntity
from launcher.errors import Location, ParseError

_counter = itertools.count()
_INSTEAD = {"launch file": "; a launch file returns a LaunchDescription instead"}
T = TypeVar("T")


def load_python(path: Path) -> LaunchDescription:
    compat.enable_in_process()  # ROS 2 files import launch, launch_ros, ament_index_python
    with made_by_code.writing():
        module = load_module(path, f"_launcher_launch_file_{next(_counter)}")
        generate = getattr(module, "generate_launch_description", None)
        if generate is None:
            raise ParseError("a Python launch file must define generate_launch_description()",
                             Location(str(path)))
        result = run_user_code(path, generate)
    where = _definition(generate, path)
    if not isinstance(result, LaunchDescription):
        raise ParseError(f"generate_launch_description() returned {type(result).__name__}, "
                         "expected a LaunchDescription", where)
    _check_entities(result, where)
    result.file = path
    return result


def load_module(path: Path, name: str, noun: str = "launch file") -> Any:
    """The user's Python file run as a module named `name` (kept out of sys.modules after,
    and no __pycache__ left in their folder); its failures said at its line."""
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise ParseError("cannot load this Python file", Location(str(path)))
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    writes_bytecode = sys.dont_write_bytecode
    sys.dont_write_bytecode = True
    try:
        run_user_code(path, lambda: spec.loader.exec_module(module),  # type: ignore[union-attr]
                      noun)
    finally:
        sys.modules.pop(name, None)
        sys.dont_write_bytecode = writes_bytecode
    return module


def run_user_code(path: Path, work: Callable[[], T], noun: str = "launch file") -> T:
    """`work()`, code of the user's file at `path`: an exception in it is said at its line,
    with the traceback trimmed to the file's frames; so are sys.exit() and a
    KeyboardInterrupt the code raises itself (no Ctrl-C was pressed)."""
    try:
        return work()
    except ParseError:
        raise
    except SyntaxError as exc:
        where = Location(str(path), exc.lineno or 0, exc.offset or 0)
        raise ParseError(f"invalid Python: {exc.msg}", where) from None
    except KeyboardInterrupt as exc:
        if hasattr(exc, "signum"):  # Ctrl-C or SIGTERM, as launcher's handlers raise them
            raise
        raise _user_error(exc, path, f"the {noun} raised KeyboardInterrupt itself (no Ctrl-C "
                                     f"was pressed){_INSTEAD.get(noun, '')}") from None
    except SystemExit as exc:  # sys.exit() in the file: an error, not the launcher's end
        raise _user_error(exc, path, f"the {noun} called sys.exit({exc.code!r})"
                                     f"{_INSTEAD.get(noun, '')}") from None
    except RecursionError as exc:
        raise _user_error(exc, path, f"the {noun} recursed too deeply") from None
    except Exception as exc:  # the user's code failed: show where, in their file
        raise _user_error(exc, path, noun=noun) from None


def _definition(function: object, path: Path) -> Location:
    """Where generate_launch_description is defined (the file, when unknown)."""
    code = getattr(function, "__code__", None)
    return Location(str(path), code.co_firstlineno) if code is not None else Location(str(path))


def _check_entities(description: LaunchDescription, where: Location) -> None:
    """Everything in the description must be a launch action (ROS 2 fails later, deep inside
    its launch service, on `LaunchDescription([42])`)."""
    todo = [description]
    while todo:
        for number, entity in enumerate(todo.pop().actions, 1):
            if isinstance(entity, LaunchDescription):
                todo.append(entity)
            elif not isinstance(entity, LaunchDescriptionEntity):
                raise ParseError(f"the LaunchDescription holds {entity!r:.60} "
                                 f"({type(entity).__name__}) as entry {number}; expected launch "
                                 f"actions (launch.actions…, launch_ros.actions…)", where)


def _nearest_import(exc: BaseException) -> str:
    """' (did you mean …?)' for `from module import Name` of a name the module lacks: the
    module's names and, for launch's and rclpy's modules, the real package's."""
    if not isinstance(exc, ImportError) or exc.name not in sys.modules:
        return ""
    wanted = re.match(r"cannot import name '(\w+)'", str(exc))
    if wanted is None:
        return ""
    from launcher.compat.finder import layout
    from launcher.errors import did_you_mean

    names = [n for n in dir(sys.modules[exc.name]) if not n.startswith("_")]
    return did_you_mean(wanted[1], [*names, *layout().get(exc.name, ())])


def _user_error(exc: BaseException, path: Path, message: str | None = None,
                noun: str = "launch file") -> ParseError:
    import traceback  # (for a failure alone: start-up time)

    frames = traceback.extract_tb(exc.__traceback__)
    mine = [f for f in frames if Path(f.filename) == path]
    last = mine[-1] if mine else None
    where = Location(str(path), last.lineno or 0) if last else Location(str(path))
    if message is not None:
        return ParseError(message, where)
    trace = "".join(traceback.format_list(mine)).rstrip()
    text = f"{type(exc).__name__}: {exc}{_nearest_import(exc)}"
    return ParseError(f"the {noun} raised {text}" + (f"\n{trace}" if trace else ""), where)


