"""The world in a browser: MuJoCo Studio's web viewer, served by the sim process.

`WebView.start()` starts Studio's web viewer (MuJoCo 4's `mujoco.studio`) on 127.0.0.1 only:
Studio binds every interface and has no authentication, so another address is used only when
asked for (`--gui-host`). `follow()` is called by the sim's loop after its steps; it sends the
world's state at most `rate` times a second (a recompiled model, after a spawn or a removal,
goes as a new model, which the page reloads, with the view framed as `launcher sim snapshot`
frames it). The viewer gets a copy of the world's data, so nothing done in the page (a reset,
a dragged state, a model dropped onto it) reaches the simulation. When Studio cannot start (an
older MuJoCo, the port taken), `start()` raises ViewerError with the reason and the sim runs
on headless.
"""

from __future__ import annotations

import contextlib
import time
from typing import Any

from launcher.errors import LaunchError

DEFAULT_PORT = 8080
DEFAULT_RATE = 30.0
MAX_RATE = 60.0


class ViewerError(LaunchError):
    pass


class WebView:
    def __init__(self, handle: Any, port: int, host: str, rate: float, camera: Any) -> None:
        self._handle, self.port, self.host, self._camera = handle, port, host, camera
        self._period = 1.0 / min(max(rate, 1.0), MAX_RATE)
        self._next = 0.0
        self._model: Any = None  # the world's model the viewer shows
        self._data: Any = None  # the viewer's copy of the world's data

    @property
    def url(self) -> str:
        host = f"[{self.host}]" if ":" in self.host else self.host
        return f"http://{host}:{self.port}/"

    @classmethod
    def start(cls, port: int, host: str = "127.0.0.1", rate: float = DEFAULT_RATE) -> WebView:
        try:
            import mujoco
            from mujoco.studio import launch_thread, viewer_protocol, web_viewer
            from mujoco.studio.web import web_server
        except ImportError as exc:
            version = _mujoco_version()
            raise ViewerError(f"the web viewer needs MuJoCo Studio (mujoco>=4); this is "
                              f"mujoco {version} ({exc})") from None
        camera = mujoco.MjvCamera()  # the viewer's, which follow() frames on a new model
        config = viewer_protocol.ViewerConfig(gfx="web", http_port=port, open_browser=False,
                                              title="launcher sim")

        def serve(endpoint: Any) -> None:  # Studio's launch_web.launch, with our camera
            viewer = web_viewer.WebViewer(config, endpoint, camera=camera)
            viewer_protocol.run_viewer_loop(viewer)

        _check_free(host, port)
        bind = web_server.bind_public_socket
        # Studio binds "::" (every interface) with no way to say otherwise: the address is
        # put in at its bind
        web_server.bind_public_socket = lambda _host, wanted: bind(host, wanted)
        try:
            with contextlib.redirect_stdout(None):  # its banner names the wrong address
                handle = launch_thread.launch_thread(serve, sim_plugins=[])
                view = cls(handle, port, host, rate, camera)
                _wait_until_serving(handle, view.url)
        except OSError as exc:
            raise ViewerError(f"the web viewer cannot listen on {host} port {port}: "
                              f"{exc.strerror or exc}") from None
        finally:
            web_server.bind_public_socket = bind
        return view

    def follow(self, world: Any, now: float | None = None) -> None:
        """Send the world's state if its turn has come (at most `rate` times a second)."""
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
            self._handle.set_model(world.model, data=self._data)  # (the viewer copies it)
        else:
            mujoco.mj_copyData(self._data, world.model, world.data)
        self._handle.sync(world.model, self._data)  # what the page did is not read back

    def _frame(self, world: Any) -> None:
        """The free view `launcher sim snapshot` takes: from the side and above, framing every
        entity but the ground (Studio's own default sits at the origin, often in the floor)."""
        import mujoco

        from launcher.sim.snapshot import AZIMUTH, ELEVATION, framing

        camera = self._camera
        camera.type = mujoco.mjtCamera.mjCAMERA_FREE
        framed = framing(world)
        if framed is not None:
            camera.lookat[:], camera.distance = framed
        else:  # nothing to frame: the world's own extent
            camera.lookat[:] = world.model.stat.center
            camera.distance = 1.5 * float(world.model.stat.extent)
        camera.azimuth, camera.elevation = AZIMUTH, ELEVATION

    def close(self) -> None:
        with contextlib.suppress(Exception):  # the viewer's own failure is no reason to
            self._handle.close()  # fail the sim's ending


def _check_free(host: str, port: int) -> None:
    """The port taken is said before Studio starts (its own check comes from its thread)."""
    import socket

    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    with socket.socket(family, socket.SOCK_STREAM) as probe:
        probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            probe.bind((host, port))
        except OSError as exc:
            raise ViewerError(f"the web viewer cannot listen on {host} port {port}: "
                              f"{exc.strerror or exc} (another program has it; choose "
                              f"another with --gui=PORT)") from None


def _wait_until_serving(handle: Any, url: str, timeout: float = 10.0) -> None:
    """Studio binds and serves from its own thread: wait until its page answers, or its
    error comes."""
    import urllib.request

    deadline = time.monotonic() + timeout
    while True:
        try:
            running = handle.is_running()  # re-raises the viewer thread's error
        except Exception as exc:  # noqa: BLE001 - Studio's (a RuntimeError for a taken port)
            raise ViewerError(f"the web viewer did not start: {exc}") from None
        if not running:
            raise ViewerError("the web viewer stopped as it started")
        with contextlib.suppress(OSError), urllib.request.urlopen(url, timeout=0.5) as page:
            if page.status == 200:
                return
        if time.monotonic() > deadline:
            handle.close()
            raise ViewerError(f"the web viewer did not answer at {url} within {timeout:g} s")
        time.sleep(0.05)


def _mujoco_version() -> str:
    try:
        import mujoco

        return str(mujoco.__version__)
    except ImportError:
        return "(not installed)"
