"""The world in a browser: MuJoCo Studio's web viewer, served by the sim process.

`WebView.start()` starts Studio's web viewer (MuJoCo 4's `mujoco.studio`) on 127.0.0.1 only:
Studio binds every interface and has no authentication, so another address is used only when
asked for (`--gui-host`). `follow()` is called by the sim's loop after its steps; while a
browser watches, it sends the world's state at most `rate` times a second (a recompiled model,
after a spawn or a removal, goes as a new model, which the page reloads, with the view framed
as `launcher sim snapshot` frames it); while none does, it sends nothing but a new model. The
page's Pause/Run, Step and Reset buttons come back from `follow()` as actions for the sim's
control path (`on_action`); nothing else done in the page reaches the simulation: the viewer
has a copy of the world's data, and a state dragged, a model dropped onto the page or physics
options changed there are dropped (viewer_page.py). When Studio cannot start (an older MuJoCo,
the port taken), `start()` raises ViewerError with the reason and the sim runs on headless.
Studio itself is reached through its adapter alone (studio.py: the one place that knows its
internals).
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Callable
from typing import Any

from launcher.errors import LaunchError

DEFAULT_PORT = 8080
DEFAULT_RATE = 30.0
MAX_RATE = 60.0


class ViewerError(LaunchError):
    pass


class WebView:
    def __init__(self, port: int, host: str, rate: float, camera: str = "",
                 track: str = "", token: str | None = None) -> None:
        self.port, self.host = port, host
        self.token = token  # the graph's, asked of every request (viewer_gate.py); None: off
        self.camera_name, self.track = camera, track  # the view asked for, if any
        self._period = 1.0 / min(max(rate, 1.0), MAX_RATE)
        self._next = 0.0
        self._studio: Any = None  # Studio's viewer thread (studio.py), the sim's side of it
        self._camera: Any = None  # the viewer's camera, framed on a new model
        self._model: Any = None  # the world's model the viewer shows
        self._data: Any = None  # the viewer's copy of the world's data
        self._paused: bool | None = None  # as the page was last told
        self._actions: list[str] = []  # the page's buttons pressed, for on_action
        self.on_action: Callable[[str], None] = lambda action: None

    @property
    def url(self) -> str:
        from launcher.bus import listen_token

        host = f"[{self.host}]" if ":" in self.host else self.host
        return listen_token.url(f"http://{host}:{self.port}/", self.token)

    @classmethod
    def start(cls, port: int | None, host: str = "127.0.0.1", rate: float = DEFAULT_RATE,
              log: Any = None, camera: str = "", track: str = "",
              token: str | None = None) -> WebView:
        """Serve the viewer on `port`, or (None) on the first free one from 8080; `log` (the
        sim's logger) hears of browsers coming and going. The view is the world's `camera`,
        or follows the entity `track`, or frames every entity. Every request must present
        `token` (None: no check)."""
        try:
            import mujoco

            from launcher.sim import studio
        except ImportError as exc:
            version = _mujoco_version()
            raise ViewerError(f"the web viewer needs MuJoCo Studio (mujoco>=4); this is "
                              f"mujoco {version} ({exc})") from None
        listener, port = _listen(host, port)
        view = cls(port, host, rate, camera, track, token)
        view._camera = mujoco.MjvCamera()
        try:
            with studio.Studio.starting(listener, port, token, view._camera,
                                        view._actions.append, log) as view._studio:
                _wait_until_serving(view._studio, view.url)
        except BaseException:
            listener.close()
            raise
        return view

    def follow(self, world: Any, paused: bool, now: float | None = None) -> None:
        """Send the world's state if its turn has come (at most `rate` times a second) and a
        browser watches; then hand the page's pressed buttons to `on_action`."""
        now = time.monotonic() if now is None else now
        if now < self._next:
            return
        self._next = now + self._period
        import mujoco

        if world.model is not self._model:  # a new world (a spawn recompiles): a new model
            self._model = world.model
            self._data = mujoco.MjData(world.model)
            mujoco.mj_copyData(self._data, world.model, world.data)
            self._frame(world)
            self._studio.set_model(world.model, self._data)  # (the viewer copies it)
        elif not self._studio.watched():
            return  # no browser: nothing to send (the next one gets the state at once)
        else:
            mujoco.mj_copyData(self._data, world.model, world.data)
        if paused != self._paused:
            self._paused = paused
            self._studio.say_paused(paused)
        self._studio.sync(world.model, self._data)  # (the page's events come in here)
        actions, self._actions[:] = list(self._actions), []
        for action in actions:  # after sync: an action may call follow() again
            self.on_action(action)

    def say_what_is_missing(self, world: Any, log: Any) -> None:
        """A camera or an entity asked for that the world does not have (yet: a robot spawned
        later may bring it): the free view until then."""
        from launcher.errors import did_you_mean

        model = world.model
        if self.camera_name:
            names = [model.camera(i).name for i in range(model.ncam)]
            if self.camera_name not in names:
                log.warning(f"--camera: no camera '{self.camera_name}' in world "
                            f"'{world.world_name}'{did_you_mean(self.camera_name, names)}; the "
                            f"web viewer shows the free view until one comes")
        if self.track and self.track not in world.entities:
            log.info(f"--track: no entity '{self.track}' in world '{world.world_name}' yet"
                     f"{did_you_mean(self.track, list(world.entities))}; the web viewer "
                     f"follows it once it is spawned")

    def _frame(self, world: Any) -> None:
        """The view on a new model: the world's camera asked for (`--camera`), or one that
        follows the entity asked for (`--track`) once it is there, or the free view `launcher
        sim snapshot` takes: from the side and above, framing every entity but the ground
        (Studio's own default sits at the origin, often in the floor)."""
        import mujoco

        from launcher.sim.snapshot import AZIMUTH, ELEVATION, framing

        camera, model = self._camera, world.model
        if self.camera_name:
            index = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_CAMERA, self.camera_name)
            if index >= 0:
                camera.type, camera.fixedcamid = mujoco.mjtCamera.mjCAMERA_FIXED, index
                return
        tracked = world.entities.get(self.track) if self.track else None
        framed = framing(world, [self.track] if tracked is not None else None)
        if framed is not None:
            camera.lookat[:], camera.distance = framed
        else:  # nothing to frame: the world's own extent
            camera.lookat[:] = model.stat.center
            camera.distance = 1.5 * float(model.stat.extent)
        camera.azimuth, camera.elevation = AZIMUTH, ELEVATION
        if tracked is not None:
            camera.type, camera.trackbodyid = mujoco.mjtCamera.mjCAMERA_TRACKING, tracked.body
        else:
            camera.type = mujoco.mjtCamera.mjCAMERA_FREE

    def close(self) -> None:
        with contextlib.suppress(Exception):  # the viewer's own failure is no reason to
            self._studio.close()  # fail the sim's ending


def _listen(host: str, port: int | None) -> tuple[Any, int]:
    """A socket listening on `host` at `port`, or (None) at the first free port from 8080
    (more than one sim may run); ViewerError if there is none."""
    import socket

    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    candidates = [port] if port is not None else range(DEFAULT_PORT, DEFAULT_PORT + 20)
    for candidate in candidates:
        listener = socket.socket(family, socket.SOCK_STREAM)
        listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)  # (past TIME_WAITs)
        try:
            listener.bind((host, candidate))
            listener.listen(100)
            return listener, candidate
        except OSError as exc:
            listener.close()
            error = exc.strerror or str(exc)
    if port is not None:
        raise ViewerError(f"the web viewer cannot listen on {host} port {port}: {error} "
                          f"(another program has it; choose another with --gui=PORT)")
    raise ViewerError(f"the web viewer found no free port on {host} from {DEFAULT_PORT} to "
                      f"{DEFAULT_PORT + 19}: {error} (choose one with --gui=PORT)")


def _wait_until_serving(studio: Any, url: str, timeout: float = 10.0) -> None:
    """Studio binds and serves from its own thread: wait until its page answers, or its
    error comes."""
    import urllib.request

    deadline = time.monotonic() + timeout
    while True:
        try:
            running = studio.is_running()  # re-raises the viewer thread's error
        except Exception as exc:  # noqa: BLE001 - Studio's (a RuntimeError for a taken port)
            raise ViewerError(f"the web viewer did not start: {exc}") from None
        if not running:
            raise ViewerError("the web viewer stopped as it started")
        with contextlib.suppress(OSError), urllib.request.urlopen(url, timeout=0.5) as page:
            if page.status == 200:
                return
        if time.monotonic() > deadline:
            studio.close()
            raise ViewerError(f"the web viewer did not answer at {url} within {timeout:g} s")
        time.sleep(0.05)


def _mujoco_version() -> str:
    try:
        import mujoco

        return str(mujoco.__version__)
    except ImportError:
        return "(not installed)"
