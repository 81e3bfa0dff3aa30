"""The web viewer served by the sim (launcher/sim/viewer.py): a real sim process, fetched by
a real HTTP client, and looked at and pressed in a real browser (Debian's Chromium, headless,
installed by the set-up)."""

from __future__ import annotations

import io
import os
import re
import shutil
import socket
import subprocess
import time
import urllib.error
import urllib.request

import psutil
import pytest

from tests.support.environment import REPO, shared
from tests.support.waiting import free_port, wait_for

ARTEFACTS = REPO / "test-artefacts" / "viewer"  # a failing browser test's screenshots


@pytest.fixture
def view_ws(ws):
    return ws.own_bus()






def listening(pid: int, port: int) -> list[str]:
    return [c.laddr.ip for c in psutil.Process(pid).net_connections("inet")
            if c.status == psutil.CONN_LISTEN and c.laddr.port == port]


def said(ws) -> str:
    return ws.output("stderr.txt") + ws.output()


def stop(proc) -> None:
    proc.terminate()
    proc.wait(20)


def token_of(ws) -> str:
    """The graph's token, as the printed URL carries it (and its 0600 file holds it)."""
    return re.search(r"in a browser: http://\S+\?token=(\S+)", said(ws)).group(1)


def fetch(url: str, headers: dict[str, str] | None = None) -> tuple[int, bytes, dict]:
    request = urllib.request.Request(url, headers=headers or {})
    try:
        with urllib.request.urlopen(request, timeout=10) as answer:
            return answer.status, answer.read(), dict(answer.headers)
    except urllib.error.HTTPError as refused:
        return refused.code, refused.read(), dict(refused.headers)


def test_the_sim_serves_the_world_on_loopback_only_to_token_holders_and_says_where(view_ws):
    port = free_port()
    proc = view_ws.start("sim", "-r", f"--gui={port}", "empty.sdf")  # (default verbosity)
    try:
        wait_for(lambda: "the world in a browser" in said(view_ws))
        token = token_of(view_ws)
        assert f"the world in a browser: http://127.0.0.1:{port}/?token={token}" in \
            said(view_ws)
        file = view_ws.root / "run" / "domain-0.token"
        assert file.read_text().strip() == token and file.stat().st_mode & 0o777 == 0o600
        assert listening(proc.pid, port) == ["127.0.0.1"]  # never every interface
        # without the token: the refusal page, for the page, its files and its streams
        for path in ("/", "/model", "/index.html"):
            status, body, _ = fetch(f"http://127.0.0.1:{port}{path}")
            assert status == 403 and b"needs the graph's token" in body, path
        status, _, _ = fetch(f"http://127.0.0.1:{port}/state", {
            "Connection": "Upgrade", "Upgrade": "websocket", "Sec-WebSocket-Version": "13",
            "Sec-WebSocket-Key": "dGhlIHNhbXBsZSBub25jZQ=="})
        assert status == 403  # no handshake: no state, no buttons
        status, _, _ = fetch(f"http://127.0.0.1:{port}/?token=wrong{token}")
        assert status == 403
        # with it: the page, and the cookie its own requests carry
        status, page, headers = fetch(f"http://127.0.0.1:{port}/?token={token}")
        assert status == 200 and b"<!doctype html>" in page.lower()[:200]
        assert headers["Set-Cookie"].startswith(f"launcher_token_{port}={token};")
        assert "HttpOnly" in headers["Set-Cookie"]
        status, model, _ = fetch(f"http://127.0.0.1:{port}/model",
                                 {"Cookie": f"launcher_token_{port}={token}"})
        assert status == 200 and len(model) > 1000  # the compiled world, as the page loads it
    finally:
        stop(proc)
    assert proc.returncode == 0


def test_a_taken_port_is_said_and_the_sim_runs_on_headless(view_ws):
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        proc = view_ws.start("sim", "-r", "-v", "3", f"--gui={port}", "empty.sdf")
        try:
            wait_for(lambda: "world 'empty'" in said(view_ws))
            text = said(view_ws)
            assert f"the web viewer cannot listen on 127.0.0.1 port {port}" in text
            assert "runs on without it" in text
            assert proc.poll() is None  # still simulating
            assert "Traceback" not in text
        finally:
            stop(proc)


@pytest.mark.parametrize("args, expected", [
    (["--gui=eighty"], "expected a port number (1-65535), got 'eighty'"),
    (["--gui=70000"], "expected a port number (1-65535), got 70000"),
    (["--gui", "--gui-rate", "500"], "--gui-rate must be between 1 and 60 Hz"),
    (["--gui", "--camera", "overhead", "--track", "bot"], "not allowed with argument"),
])
def test_bad_viewer_options(view_ws, args, expected):
    done = view_ws.run("sim", *args, "empty.sdf", timeout=30)
    assert done.returncode == 2
    assert expected in done.stderr


def test_a_camera_the_world_does_not_have_is_said_and_the_free_view_shown(view_ws):
    proc = view_ws.start("sim", "-r", "-v", "3", f"--gui={free_port()}", "--camera",
                         "overhed", "empty.sdf")
    try:
        wait_for(lambda: "world 'empty'" in said(view_ws))
        text = said(view_ws)
        assert "--camera: no camera 'overhed' in world 'empty'" in text
        assert "the web viewer shows the free view until one comes" in text
        assert "in a browser" in text and proc.poll() is None
    finally:
        stop(proc)


def test_a_mujoco_without_studio_is_said_and_the_sim_runs_on_headless(view_ws):
    """An older MuJoCo has no `mujoco.studio`: here it is hidden from the sim's import."""
    view_ws.write("sitecustomize.py", """
        import sys
        sys.modules["mujoco.studio"] = None  # what an older MuJoCo's import gives: nothing
    """)
    env = {"PYTHONPATH": str(view_ws.root)}
    proc = view_ws.start("sim", "-r", "-v", "3", f"--gui={free_port()}", "empty.sdf", env=env)
    try:
        wait_for(lambda: "world 'empty'" in said(view_ws))
        text = said(view_ws)
        assert "the web viewer needs MuJoCo Studio (mujoco>=4); this is mujoco" in text
        assert "runs on without it" in text and proc.poll() is None
    finally:
        stop(proc)


def served_at(ws) -> int:
    return int(re.search(r"in a browser: http://127\.0\.0\.1:(\d+)/", said(ws)).group(1))


def test_gz_sim_serves_the_viewer_as_gazebo_opens_its_window_and_not_with_s(view_ws):
    """`gz sim WORLD` is Gazebo's server and GUI: the viewer, on 8080 or the next free port
    (another sim may have it); `gz sim -s` is the server alone."""
    with socket.socket() as taken:  # 8080 taken: the next free one
        taken.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            taken.bind(("127.0.0.1", 8080))
            taken.listen()
        except OSError:
            pass  # (taken already)
        proc = view_ws.start("gz", "sim", "-r", "-v", "3", "empty.sdf")
        try:
            wait_for(lambda: "the world in a browser" in said(view_ws))
            port = served_at(view_ws)
            assert port != 8080 and 8080 < port < 8100
            assert listening(proc.pid, port) == ["127.0.0.1"]
        finally:
            stop(proc)
    assert proc.returncode == 0


def test_gz_sim_g_asks_the_running_server_to_serve_its_viewer(view_ws):
    proc = view_ws.start("gz", "sim", "-s", "-r", "-v", "3", "empty.sdf")
    try:
        wait_for(lambda: "world 'empty'" in said(view_ws))
        assert "in a browser" not in said(view_ws)
        assert not [c for c in psutil.Process(proc.pid).net_connections("inet")
                    if c.status == psutil.CONN_LISTEN]  # server only: nothing served
        asked = view_ws.run("gz", "sim", "-g", timeout=60)
        assert asked.returncode == 0, asked.stderr
        url = re.search(r"the world 'empty' in a browser: (http://127\.0\.0\.1:(\d+)/"
                        r"\?token=\S+)", asked.stderr)
        assert url, asked.stderr
        assert listening(proc.pid, int(url.group(2))) == ["127.0.0.1"]
        page = urllib.request.urlopen(url.group(1), timeout=10).read()
        assert b"<!doctype html>" in page.lower()[:200]
        again = view_ws.run("gz", "sim", "-g", "empty", timeout=60)  # served: the same one
        assert again.returncode == 0 and url.group(1) in again.stderr
        other = view_ws.run("gz", "sim", "-g", "warehouse", timeout=60)
        assert other.returncode == 1
        assert "no sim runs a world named 'warehouse'" in other.stderr
    finally:
        stop(proc)
    assert proc.returncode == 0


def test_gz_sim_g_with_no_sim_running_says_so(view_ws):
    done = view_ws.run("gz", "sim", "-g", timeout=60)
    assert done.returncode == 1
    assert "no sim answered" in done.stderr and "gz sim -s WORLD" in done.stderr
    assert "Traceback" not in done.stderr


def test_a_model_dropped_onto_the_page_is_not_kept(tmp_path):
    """Studio's page uploads dropped files for the sim to load: the sim's viewer takes none
    (its server reads the upload and keeps nothing, and no drop is ever loaded)."""
    from launcher.sim.viewer import WebView

    view = WebView.start(free_port())
    try:
        assert view._studio.page._web_server.drop_queue is None
        assert view._studio.page.get_drop_file() == ""
    finally:
        view.close()


# --- in a real browser: Debian's Chromium, headless, software GL --------------------------
DIFF_DRIVE = ("external", "gz-sim", "worlds", "diff_drive.sdf")  # in ../shared
SCENE = (0, 0, 800, 400)  # the 3D view of an 800×600 window, above the page's status bar
BLUE, GREEN, RED = (0.2, 0.2, 0.8), (0.2, 0.8, 0.2), (0.8, 0.2, 0.2)


@pytest.fixture
def browser():
    from selenium import webdriver
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service

    options = Options()
    for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage",
                     "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                     "--window-size=800,600"):
        options.add_argument(argument)
    driver = webdriver.Chrome(options=options,
                              service=Service(shutil.which("chromedriver") or "chromedriver"))
    driver.shots = []
    try:
        yield driver
    finally:
        driver.quit()


def keep_shots(driver, name: str) -> None:
    """A failing run's screenshots, kept as its artefacts."""
    folder = ARTEFACTS / name
    folder.mkdir(parents=True, exist_ok=True)
    for index, shot in enumerate(driver.shots):
        (folder / f"{index:02d}.png").write_bytes(shot)


def picture(driver):
    """The page's 3D view now, as an image (and kept for a failing run)."""
    from PIL import Image

    shot = driver.get_screenshot_as_png()
    driver.shots.append(shot)
    return Image.open(io.BytesIO(shot)).convert("RGB").crop(SCENE)


def press(driver, button: int) -> None:
    """A click on one of the page's sim buttons (viewer_page.py: 0 Pause/Run, 1 Step, 2 Reset)."""
    from selenium.webdriver.common.actions.action_builder import ActionBuilder

    from launcher.sim.viewer_page import button_centre

    x, y = button_centre(button)
    actions = ActionBuilder(driver)
    actions.pointer_action.move_to_location(int(x), int(y))
    actions.pointer_action.click()
    actions.perform()


def share_of(image, colour, tolerance: float = 0.2) -> float:
    """The part of the picture near `colour` (channel fractions, shading allowed for)."""
    data = image.tobytes()
    pixels = list(zip(data[0::3], data[1::3], data[2::3], strict=True))
    near = 0
    for r, g, b in pixels:
        total = r + g + b
        if total < 60:
            continue
        shares = (r / total, g / total, b / total)
        wanted = [c / sum(colour) for c in colour]
        if all(abs(s - w) < tolerance for s, w in zip(shares, wanted, strict=True)):
            near += 1
    return near / len(pixels)


def difference(a, b) -> float:
    from PIL import ImageChops

    histogram = ImageChops.difference(a, b).convert("L").histogram()
    return sum(histogram[25:]) / (a.width * a.height)  # pixels that changed visibly


def settled(driver, within: float = 20.0):
    """The page's view once three pictures a second apart are the same (a loaded machine's
    browser draws the last frames of a pause late, and may draw none for a second before
    them); fails if it never settles."""
    deadline = time.monotonic() + within
    before, quiet = picture(driver), 0
    while time.monotonic() < deadline:
        time.sleep(1)
        now = picture(driver)
        quiet = quiet + 1 if difference(before, now) < 0.002 else 0
        if quiet == 2:
            return now
        before = now
    raise AssertionError(f"the view kept changing for {within:g} s")


def test_in_a_real_browser_the_robots_are_drawn_move_stop_when_paused_and_a_spawn_appears(
        view_ws, browser):
    world = shared(*DIFF_DRIVE)
    view_ws.env["GZ_SIM_RESOURCE_PATH"] = str(world.parent)
    port = free_port()
    proc = view_ws.start("sim", "-r", "-v", "3", f"--gui={port}", str(world))
    try:
        wait_for(lambda: "the world in a browser" in said(view_ws))
        browser.get(f"http://localhost:{port}/")  # another host name: no cookie, no token
        assert "needs the graph's token" in browser.page_source
        browser.get(f"http://127.0.0.1:{port}/?token={token_of(view_ws)}")
        # the scene: both vehicles of gz-sim's diff_drive.sdf, framed as a snapshot frames
        def both_vehicles():
            shown = picture(browser)
            return shown if share_of(shown, BLUE) > 0.01 and share_of(shown, GREEN) > 0.01 \
                else None

        first = wait_for(both_vehicles, 90)
        assert share_of(first, RED) < 0.001
        # driving: the picture changes
        sent = view_ws.run("gz", "topic", "-t", "/model/vehicle_blue/cmd_vel", "-m",
                           "gz.msgs.Twist", "-p", "linear: {x: 2.0}, angular: {z: 1.0}")
        assert sent.returncode == 0, sent.stderr
        time.sleep(2)
        assert difference(first, picture(browser)) > 0.005
        # paused: it stops changing
        paused = view_ws.run("gz", "service", "-s", "/world/diff_drive/control", "--reqtype",
                             "gz.msgs.WorldControl", "--reptype", "gz.msgs.Boolean",
                             "--req", "pause: true")
        assert paused.returncode == 0, paused.stderr
        still = settled(browser)
        time.sleep(2)
        assert difference(still, picture(browser)) < 0.002
        # the page's own buttons: Run (the paused sim's Pause button), Pause, Reset
        press(browser, 0)  # Run
        wait_for(lambda: "the web viewer's page: run" in said(view_ws))
        time.sleep(1)
        assert difference(still, picture(browser)) > 0.005  # driving again
        press(browser, 0)  # Pause
        wait_for(lambda: "the web viewer's page: pause" in said(view_ws))
        still = settled(browser)
        time.sleep(2)
        assert difference(still, picture(browser)) < 0.002
        press(browser, 2)  # Reset: back where the world began
        wait_for(lambda: "the web viewer's page: reset" in said(view_ws))
        time.sleep(1)
        assert difference(first, picture(browser)) < difference(first, still)
        # a spawned robot appears (the model is sent again, the page reloads it)
        box = ('<sdf version="1.6"><model name="red_box"><pose>0 -2 0.5 0 0 0</pose><link '
               'name="l"><visual name="v"><geometry><box><size>1 1 1</size></box></geometry>'
               '<material><diffuse>0.8 0.1 0.1 1</diffuse><ambient>0.8 0.1 0.1 1</ambient>'
               '</material></visual></link></model></sdf>')
        spawned = view_ws.run("gz", "service", "-s", "/world/diff_drive/create", "--reqtype",
                              "gz.msgs.EntityFactory", "--reptype", "gz.msgs.Boolean",
                              "--req", f"sdf: '{box}'", timeout=60)
        assert spawned.returncode == 0, spawned.stdout + spawned.stderr
        wait_for(lambda: share_of(picture(browser), RED) > 0.005, 60)
        # the page left and opened again (a reload is a disconnect and a reconnect)
        browser.get("about:blank")
        time.sleep(1)
        browser.get(f"http://127.0.0.1:{port}/")  # (the cookie the first visit was given)
        wait_for(lambda: share_of(picture(browser), RED) > 0.005, 60)
        # and vanishes when removed
        removed = view_ws.run("gz", "service", "-s", "/world/diff_drive/remove", "--reqtype",
                              "gz.msgs.Entity", "--reptype", "gz.msgs.Boolean",
                              "--req", "name: 'red_box' type: MODEL", timeout=60)
        assert removed.returncode == 0, removed.stdout + removed.stderr
        wait_for(lambda: share_of(picture(browser), RED) < 0.001, 60)
        assert proc.poll() is None
    except BaseException:
        keep_shots(browser, "robots_drawn_move_pause_spawn")
        raise
    finally:
        stop(proc)
    assert proc.returncode == 0


def test_a_world_with_nothing_to_frame_is_served_too(view_ws):
    view_ws.write("void.sdf", """
        <sdf version="1.9"><world name="void"></world></sdf>
    """)
    port = free_port()
    proc = view_ws.start("sim", "-r", "-v", "3", f"--gui={port}", "void.sdf")
    try:
        wait_for(lambda: "the world in a browser" in said(view_ws))
        time.sleep(0.5)  # a few turns of the viewer on a world with no geometry
        page = urllib.request.urlopen(f"http://127.0.0.1:{port}/model?token="
                                      f"{token_of(view_ws)}", timeout=10).read()
        assert page and proc.poll() is None
    finally:
        stop(proc)
    assert proc.returncode == 0


def centre_of(image, colour) -> tuple[float, float]:
    """Where the part of the picture near `colour` is (its centre, in pixels)."""
    data = image.tobytes()
    wanted = [c / sum(colour) for c in colour]
    xs, ys = [], []
    for index in range(0, len(data), 3 * 3):  # every third pixel
        r, g, b = data[index], data[index + 1], data[index + 2]
        total = r + g + b
        if total >= 60 and all(abs(s / total - w) < 0.2
                               for s, w in zip((r, g, b), wanted, strict=True)):
            xs.append((index // 3) % image.width)
            ys.append((index // 3) // image.width)
    assert xs, "the colour is not in the picture"
    return sum(xs) / len(xs), sum(ys) / len(ys)


def test_in_a_real_browser_track_keeps_the_driving_robot_in_view(view_ws, browser):
    world = shared(*DIFF_DRIVE)
    view_ws.env["GZ_SIM_RESOURCE_PATH"] = str(world.parent)
    port = free_port()
    proc = view_ws.start("sim", "-r", "-v", "3", f"--gui={port}", "--track", "vehicle_blue",
                         str(world))
    try:
        wait_for(lambda: "the world in a browser" in said(view_ws))
        browser.get(f"http://127.0.0.1:{port}/?token={token_of(view_ws)}")
        first = wait_for(lambda: (shown := picture(browser)) and share_of(shown, BLUE) > 0.02
                         and shown, 90)
        where = view_ws.run("gz", "model", "-m", "vehicle_blue", "-p").stdout
        sent = view_ws.run("gz", "topic", "-t", "/model/vehicle_blue/cmd_vel", "-m",
                           "gz.msgs.Twist", "-p", "linear: {x: 2.0}")
        assert sent.returncode == 0, sent.stderr
        time.sleep(3)
        moved = view_ws.run("gz", "model", "-m", "vehicle_blue", "-p").stdout
        assert moved != where  # it drove (metres, at 2 m/s)
        x0, y0 = centre_of(first, BLUE)
        now = picture(browser)
        x1, y1 = centre_of(now, BLUE)
        # the view went with it: 6 m of driving, and the robot is where it was on the page
        # (an untracked view loses it: tens of pixels per metre at this distance)
        assert share_of(now, BLUE) > 0.02
        assert abs(x1 - x0) < 40 and abs(y1 - y0) < 40
    except BaseException:
        keep_shots(browser, "track")
        raise
    finally:
        stop(proc)
    assert proc.returncode == 0


AS_ANOTHER_USER = """
import socket, sys, urllib.error, urllib.request
port, internal, token = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
def status(url):
    try:
        return urllib.request.urlopen(url, timeout=10).status
    except urllib.error.HTTPError as refused:
        return refused.code
print("PLAIN", status(f"http://127.0.0.1:{port}/"))
print("TOKEN", status(f"http://127.0.0.1:{port}/model?token={token}"))
with socket.create_connection(("127.0.0.1", internal), timeout=5) as sock:
    try:
        sock.sendall(b"\\x00" * 64)
        print("INTERNAL", "closed" if sock.recv(100) == b"" else "answered")
    except ConnectionResetError:
        print("INTERNAL closed")
    except TimeoutError:
        print("INTERNAL open")  # the UI bridge took it and waits for more
"""


@pytest.mark.skipif(os.geteuid() != 0, reason="needs root to act as another user")
def test_another_user_reaches_the_viewer_only_with_the_token_and_never_its_internal_port(
        view_ws):
    """As the user nobody: the page's port refuses a request without the token and serves
    one with it; Studio's internal port (its UI client's, which carries the buttons) closes
    the connection unread, token or not."""
    port = free_port()
    proc = view_ws.start("sim", "-r", f"--gui={port}", "empty.sdf")
    try:
        wait_for(lambda: "the world in a browser" in said(view_ws))
        ports = {c.laddr.port for c in psutil.Process(proc.pid).net_connections("inet")
                 if c.status == psutil.CONN_LISTEN}
        (internal,) = ports - {port}
        done = subprocess.run(["setpriv", "--reuid=nobody", "--regid=nogroup",
                               "--clear-groups", "/usr/bin/python3", "-c", AS_ANOTHER_USER,
                               str(port), str(internal), token_of(view_ws)],
                              capture_output=True, text=True, timeout=60, cwd="/")
        assert done.returncode == 0, done.stderr
        assert done.stdout.split("\n")[:3] == ["PLAIN 403", "TOKEN 200", "INTERNAL closed"], \
            done.stdout
        assert proc.poll() is None
    finally:
        stop(proc)
    assert proc.returncode == 0


def test_no_token_serves_anyone_and_says_so(view_ws):
    port = free_port()
    proc = view_ws.start("sim", "-r", f"--gui={port}", "--no-token", "empty.sdf")
    try:
        wait_for(lambda: "the world in a browser" in said(view_ws))
        assert f"in a browser: http://127.0.0.1:{port}/\n" in said(view_ws)
        assert "the token check is off" in said(view_ws)
        status, page, _ = fetch(f"http://127.0.0.1:{port}/")
        assert status == 200 and b"<!doctype html>" in page.lower()[:200]
    finally:
        stop(proc)
    assert proc.returncode == 0


TICKER = "import time\nwhile True:\n    print('tick', flush=True)\n    time.sleep(0.2)\n"


def test_in_a_real_browser_the_processes_page_lists_the_launch_and_restarts_one(view_ws,
                                                                                browser):
    """The viewer's processes page, behind its token: the launch's processes live (as
    `launcher ps`), and a restart button that restarts one."""
    from selenium.common.exceptions import StaleElementReferenceException
    from selenium.webdriver.common.by import By

    view_ws.write("void.sdf", '<sdf version="1.9"><world name="void"></world></sdf>')
    view_ws.write("ticker.py", TICKER)
    port = free_port()
    view_ws.write("view.launch.yaml", f"""
    launch:
      - executable: {{cmd: "launcher sim -r --gui={port} void.sdf", output: screen}}
      - executable: {{cmd: "python3 ticker.py", name: ticker}}
    """)
    proc = view_ws.start("launch", "-n", "view.launch.yaml")
    try:
        wait_for(lambda: "the world in a browser" in said(view_ws), timeout=60)
        assert fetch(f"http://127.0.0.1:{port}/processes")[0] == 403  # (no token: refused)
        browser.get(f"http://127.0.0.1:{port}/processes?token={token_of(view_ws)}")

        def cells(name: str) -> list[str]:  # (read at once: the table is redrawn each second)
            return browser.execute_script(
                "const row = document.querySelector(`tr[data-name='${arguments[0]}']`);"
                "return row ? [...row.cells].map(cell => cell.textContent) : [];", name)

        def press(name: str, verb: str) -> bool:
            try:
                browser.find_element(By.CSS_SELECTOR,
                                     f"tr[data-name='{name}'] button.{verb}").click()
            except StaleElementReferenceException:  # (redrawn under the click: again)
                return False
            return True

        wait_for(lambda: cells("ticker-2")[3:5] == ["running", "0"], timeout=30)
        assert cells("launcher-1")[3] == "running"  # (the sim)
        first_pid = cells("ticker-2")[1]
        wait_for(lambda: press("ticker-2", "restart"))
        wait_for(lambda: cells("ticker-2")[3:5] == ["running", "1"], timeout=30)
        assert cells("ticker-2")[1] != first_pid
        assert "restarting ticker-2" in browser.find_element(By.ID, "said").text
    finally:
        proc.send_signal(2)
        proc.wait(30)
