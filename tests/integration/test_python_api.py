"""The Python API with real processes: event handlers, timers, prefixes, log folder."""

from __future__ import annotations

import sys

PY = sys.executable

HANDLERS = '''
from launcher.api import *


def generate_launch_description():
    talker = ExecuteProcess(cmd=["sh", "-c", "echo line-one; echo line-two >&2; exit 0"],
                            name="talker", output="log")
    heard = []
    return LaunchDescription([
        RegisterEventHandler(OnProcessStart(target_action=talker, on_start=[
            LogInfo(msg="talker is up")])),
        RegisterEventHandler(OnProcessIO(target_action=talker,
                                         on_stdout=lambda event: heard.append(
                                             event.text.decode().strip()),
                                         on_stderr=lambda event: [LogInfo(
                                             msg="stderr said " + event.text.decode().strip())])),
        RegisterEventHandler(OnProcessExit(target_action=talker, on_exit=lambda event, context: [
            LogInfo(msg=f"talker exited with {event.returncode}; heard {heard}"),
            ExecuteProcess(cmd=["sleep", "30"], name="long"),
            TimerAction(period=0.3, actions=[Shutdown(reason="enough")]),
        ])),
        RegisterEventHandler(OnShutdown(on_shutdown=[LogInfo(msg="shutting down now")])),
        talker,
    ])
'''


def test_event_handlers_with_real_processes(ws):
    ws.write("handlers.launch.py", HANDLERS)
    result = ws.run("launch", "handlers.launch.py")
    out = result.stdout
    assert result.returncode == 0, out + result.stderr
    order = ["talker is up", "stderr said line-two",
             "talker exited with 0; heard ['line-one']", "[long-2]: process started",
             "shutting down: enough", "shutting down now", "[long-2]: process stopped"]
    positions = [out.index(text) for text in order]
    assert positions == sorted(positions), out


def test_reset_timer_cancel_prefix_and_log_dir(ws):
    ws.write("misc.launch.yaml", f"""
    launch:
      - let: {{name: a, value: "1"}}
      - let: {{name: b, value: "2"}}
      - reset: {{keep: [{{name: b}}]}}
      - log: {{message: "a=$(var a gone) b=$(var b)"}}
      - timer: {{period: 30, children: [{{log: {{message: never}}}}]}}
      - timer:
          period: 3
          cancel_on_shutdown: false
          children: [{{log: {{message: "kept timer fired"}}}}]
      - executable:
          cmd: {PY} -c "import sys; print('argv', sys.argv[1:])" "$(log_dir)"
          launch-prefix: env FROM_PREFIX=1
          output: screen
          on_exit: shutdown
    """)
    result = ws.run("launch", "misc.launch.yaml", "--launch-prefix", "nice -n 1")
    out = result.stdout
    assert result.returncode == 0, out + result.stderr
    assert "a=gone b=2" in out
    assert "kept timer fired" in out and "never" not in out
    assert out.index("shutting down") < out.index("kept timer fired")  # (it outlived it)
    latest = (ws.root / "log" / "latest").resolve()
    assert f"argv ['{latest}']" in out
