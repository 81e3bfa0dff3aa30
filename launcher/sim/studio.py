"""MuJoCo Studio's web viewer as the sim drives it: the one place that knows Studio's internals.

Studio (MuJoCo 4's `mujoco.studio`) runs its web viewer in a thread of its own; the sim's side
of it is `Studio`, an adapter over Studio's ViewerHandle. Where the sim needs what Studio does
not offer, it reaches past Studio's public surface, here and nowhere else (a new Studio that
moves these breaks this module alone):
- while it starts, its web server's socket binders and websockets' `serve` are swapped
  (`web_server.bind_public_socket`, `bind_loopback_socket`, `serve`): it is handed the socket
  the viewer made on the host asked for, its internal port takes this user's connections
  alone, and its requests pass the token check (viewer_gate.py);
- its WebViewer is subclassed (`PageViewer`): a model dropped onto the page is not kept (its
  `_drop_queue`), a new model prints nothing (its `_on_post_model`), and nothing is drawn
  while no browser watches;
- browsers are counted from its server's log lines (`Browsers`), and its loggers ("WebServer",
  "mujoco.studio") go to the sim's log.
Imported by viewer.py once Studio is known to be there.
"""

from __future__ import annotations

import contextlib
import logging
import threading
import time
from collections.abc import Callable, Iterator
from typing import Any

from mujoco.studio import launch_thread, messages, sim, viewer_protocol, web_viewer
from mujoco.studio.web import web_server

from launcher.sim import viewer_gate, viewer_page
from launcher.sim.processes_page import ProcessesPage

WATCHED_FOR = 0.5  # s after the last frame drawn for a browser


class Studio:
    """Studio's viewer thread, from the sim's side: the model and state to show, the pause to
    say, and whether a browser watches."""

    def __init__(self, handle: Any = None, page: Any = None) -> None:
        self._handle = handle  # Studio's ViewerHandle, the sim's side of the viewer
        self.page = page  # its PageViewer, the viewer thread's side (made in that thread)

    @classmethod
    @contextlib.contextmanager
    def starting(cls, listener: Any, port: int, token: str | None, camera: Any,
                 act: Callable[[str], None], log: Any) -> Iterator[Studio]:
        """Start Studio's viewer on `listener` (listening on `port`), its view `camera`; the
        page's buttons go to `act`, its log to `log`. Studio binds and serves from its own
        threads: its server's parts stay swapped, and its banner silenced, until the caller,
        inside the `with`, has seen its page answer. Every request must present `token`
        (None: no check)."""
        studio = cls()
        config = viewer_protocol.ViewerConfig(gfx="web", http_port=port, open_browser=False,
                                              title="launcher sim")

        def serve(endpoint: Any) -> None:  # Studio's launch_web.launch, with our parts
            studio.page = PageViewer(config, endpoint, camera=camera,
                                     plugins=[viewer_page.Panel()])
            viewer_protocol.run_viewer_loop(studio.page)

        route_log(log)
        bind, loopback, websockets_serve = (web_server.bind_public_socket,
                                            web_server.bind_loopback_socket, web_server.serve)
        # Studio binds "::" (every interface) with no way to say otherwise: it is handed the
        # socket made by the viewer, on its host, listening already (a port another sim has
        # is found taken there, not in Studio's server thread)
        web_server.bind_public_socket = lambda _host, _port: listener
        web_server.bind_loopback_socket = viewer_gate.own_user_listener
        if token is not None:
            web_server.serve = viewer_gate.guarded_serve(websockets_serve, token, port,
                                                         ProcessesPage().respond)
        try:
            with contextlib.redirect_stdout(None):  # its banner names the wrong address
                studio._handle = launch_thread.launch_thread(
                    serve, sim_plugins=[viewer_page.Controls(act)])
                yield studio
        finally:
            web_server.bind_public_socket, web_server.bind_loopback_socket = bind, loopback
            web_server.serve = websockets_serve

    def is_running(self) -> bool:
        """Whether the viewer thread runs; raises its error if it failed."""
        return bool(self._handle.is_running())

    def set_model(self, model: Any, data: Any) -> None:
        """Show a new model (the page reloads; the viewer copies it)."""
        self._handle.set_model(model, data=data)

    def say_paused(self, paused: bool) -> None:
        self._handle.send_to_viewer(messages.StepControlSnapshot(
            pause_state=sim.PauseState.NORMAL_PAUSED if paused else sim.PauseState.UNPAUSED))

    def sync(self, model: Any, data: Any) -> None:
        """Send the state; the page's events come in here (to Controls)."""
        self._handle.sync(model, data)

    def watched(self) -> bool:
        """Whether a browser has been drawn for lately."""
        return self.page is not None and self.page.watched()

    def close(self) -> None:
        self._handle.close()


class Browsers(logging.Filter):
    """How many browsers Studio's server has (its log says each coming and going, with the
    count; the server keeps its list to itself)."""

    def __init__(self) -> None:
        super().__init__()
        self.count = 0
        self.came = threading.Event()  # set while there are some

    def filter(self, record: logging.LogRecord) -> bool:
        if str(record.msg).startswith("[StateWS] Browser") and record.args:
            count = record.args[0] if isinstance(record.args, tuple) else None
            if isinstance(count, int):
                self.count = count
                (self.came.set if count else self.came.clear)()
        return True


class PageViewer(web_viewer.WebViewer):
    """Studio's web viewer, without model drops or prints, that draws only for a browser."""

    last_frame = 0.0  # (monotonic) when a frame was last drawn for a browser

    def __init__(self, *args, **kwargs) -> None:  # noqa: ANN002, ANN003 - Studio's own
        self.browsers = Browsers()
        logging.getLogger("WebServer").addFilter(self.browsers)
        super().__init__(*args, **kwargs)

    def watched(self) -> bool:
        return time.monotonic() - self.last_frame < WATCHED_FOR

    def _start_server(self) -> None:
        self._drop_queue = None  # its server then reads a drop and keeps nothing of it
        super()._start_server()

    def get_drop_file(self) -> str:
        return ""

    def prepare_next_frame(self) -> bool:
        if not self.browsers.count:  # nobody to draw for: wait for one (the loop still
            self.browsers.came.wait(0.1)  # takes the sim's new models, 10 times a second)
            return False
        frame = super().prepare_next_frame()
        if frame:
            self.last_frame = time.monotonic()
        return frame

    def close(self) -> None:
        logging.getLogger("WebServer").removeFilter(self.browsers)
        super().close()

    @messages.handler(priority=messages.Priority.INTERNAL)
    def _on_post_model(self, event: messages.PostModelEvent) -> None:
        del event  # (Studio's own prints that the page reloads)
        self._update_model()


class _StudioLog(logging.Handler):
    """Studio's web server's log (browsers coming and going), said as the sim's info."""

    def __init__(self, log: Any) -> None:
        super().__init__()
        self._log = log

    def emit(self, record: logging.LogRecord) -> None:
        text = record.getMessage()
        if text.startswith("["):  # "[StateWS] Browser connected (1 total)"
            text = text.partition("] ")[2]
        if record.exc_info and record.exc_info[1] is not None:  # (its traceback: --debug)
            text = f"{text} ({type(record.exc_info[1]).__name__}: {record.exc_info[1]})"
        say = self._log.warning if record.levelno >= logging.WARNING else self._log.info
        say(f"web viewer: {text[:1].lower()}{text[1:]}")


def route_log(log: Any) -> None:
    """Studio's server prints its log on stdout in its own format, its viewer thread's errors
    go to Python's last resort with a traceback: both go to the sim's log (`log`; None:
    nowhere)."""
    for name in ("WebServer", "mujoco.studio"):
        studio = logging.getLogger(name)
        for handler in list(studio.handlers):
            studio.removeHandler(handler)
        studio.addHandler(_StudioLog(log) if log is not None else logging.NullHandler())
        studio.propagate = False
