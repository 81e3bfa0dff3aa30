"""Web viewer benchmarks (issue 18): what `launcher sim --gui` costs the sim, and how soon a
spawned robot shows in the browser.

A real sim process (paced, 1 kHz, gz-sim's diff_drive.sdf with its two vehicles) measured by
the kernel's CPU times and its own clock messages, in three conditions taken in turns (this
machine is shared and noisy): headless; with the viewer and no browser; with the viewer and one
browser (Debian's Chromium, headless, software GL) at 30 Hz. The browser's own CPU is its
own, not the sim's. Spawn to appearance: the create service's call until a screenshot of a
small page (480×360, so that a screenshot is quick) shows the spawned red box.
"""

from __future__ import annotations

import argparse
import io
import os
import shutil
import socket
import struct
import subprocess
import sys
import threading
import time
from pathlib import Path

import psutil
from _harness import start_router, summary, table

PY = sys.executable
WORLD = Path(__file__).resolve().parents[2] / "shared" / "external" / "gz-sim" / "worlds" / \
    "diff_drive.sdf"
BOX = ('<sdf version="1.6"><model name="{name}"><static>true</static>'
       '<pose>{x} -2 0.5 0 0 0</pose><link name="l"><visual name="v"><geometry><box>'
       '<size>1 1 1</size></box></geometry><material><diffuse>0.8 0.1 0.1 1</diffuse>'
       '<ambient>0.8 0.1 0.1 1</ambient></material></visual></link></model></sdf>')


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def browser(size: str = "800,600"):
    from selenium import webdriver
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service

    options = Options()
    for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage",
                     "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                     f"--window-size={size}"):
        options.add_argument(argument)
    return webdriver.Chrome(options=options,
                            service=Service(shutil.which("chromedriver") or "chromedriver"))


def red_share(driver) -> float:
    from PIL import Image

    image = Image.open(io.BytesIO(driver.get_screenshot_as_png())).convert("RGB")
    data = image.tobytes()
    red = 0
    for i in range(0, len(data), 3):  # the box's red, shading allowed for
        r, g, b = data[i], data[i + 1], data[i + 2]
        red += r + g + b > 60 and r > 2 * (g + b) * 0.8
    return red / (image.width * image.height)


class Sim:
    def __init__(self, env: dict[str, str], gui: bool) -> None:
        from launcher.bus import keys
        from launcher.bus.node import Node

        self.port = free_port()
        args = [f"--gui={self.port}"] if gui else []
        self.proc = subprocess.Popen([PY, "-m", "launcher.nodes.sim", "-r", "-v", "3", *args,
                                      str(WORLD)], env=env, stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT, text=True)
        self.said: list[str] = []
        threading.Thread(target=self._drain, daemon=True).start()
        if gui:  # its URL is said once the viewer serves
            self.wait_said("the world in a browser")
        self.node = Node(f"bench_viewer_{self.port}", argv=[], space=keys.SIM)
        self.clocks: list[tuple[float, float]] = []
        clock = struct.Struct("<4xiI")

        def on_clock(payload: bytes) -> None:
            sec, nanosec = clock.unpack_from(payload)
            self.clocks.append((time.monotonic(), sec + nanosec * 1e-9))

        self.node.create_subscription("mujoco_sim/msg/Clock", "/world/diff_drive/clock",
                                      on_clock, raw=True)

    @property
    def url(self) -> str:
        """The address the sim printed (the graph's token in it)."""
        import re

        for line in self.said:
            found = re.search(r"in a browser: (\S+)", line)
            if found:
                return found.group(1)
        raise RuntimeError("the sim said no address")

    def _drain(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            self.said.append(line)

    def wait_said(self, text: str, timeout: float = 90.0) -> None:
        deadline = time.monotonic() + timeout
        while not any(text in line for line in self.said):
            assert self.proc.poll() is None, "the sim ended"
            assert time.monotonic() < deadline, f"the sim never said {text!r}"
            time.sleep(0.05)

    def measure(self, seconds: float) -> tuple[float, float]:
        """(CPU % of one core, RTF) over `seconds`."""
        self.node.spin(2.0)  # settled
        process = psutil.Process(self.proc.pid)
        cpu0, self.clocks[:] = sum(process.cpu_times()[:2]), []
        start = time.monotonic()
        self.node.spin(seconds)
        cpu = (sum(process.cpu_times()[:2]) - cpu0) / (time.monotonic() - start)
        (wall0, sim0), (wall1, sim1) = self.clocks[0], self.clocks[-1]
        return cpu * 100, (sim1 - sim0) / (wall1 - wall0)

    def spawn(self, name: str, x: float) -> float:
        client = self.node.create_client("mujoco_sim/srv/Create", "/world/diff_drive/create")
        request = self.node.message("mujoco_sim/srv/Create_Request", name=name,
                                    sdf=BOX.format(name=name, x=x),
                                    pose={"position": {"x": x, "y": -2.0, "z": 0.5},
                                          "orientation": {"w": 1.0}})
        start = time.perf_counter()
        response = client.call(request, timeout=30)
        assert response.success, response.message
        return start

    def close(self) -> None:
        self.node.destroy_node()
        self.proc.terminate()
        self.proc.wait(20)


def appearance(sim: Sim, driver, runs: int) -> tuple[list[float], list[float]]:
    """Seconds from a spawn's call to the first screenshot with the box in it (an upper
    bound, as a screenshot in software GL takes its own time), and a screenshot's time."""
    seen, shots = [], []
    remover = sim.node.create_client("mujoco_sim/srv/Remove", "/world/diff_drive/remove")
    for run in range(runs):
        while red_share(driver) > 0.002:  # the last one's box gone
            time.sleep(0.2)
        start = sim.spawn(f"box{run}", -1.0 + run * 0.5)
        while True:
            shot = time.perf_counter()
            shown = red_share(driver) > 0.002
            shots.append(time.perf_counter() - shot)
            if shown:
                break
            assert time.perf_counter() - start < 60, "the spawned box never showed"
        seen.append(time.perf_counter() - start)
        remover.call(sim.node.message("mujoco_sim/srv/Remove_Request", name=f"box{run}"),
                     timeout=30)
    return seen, shots


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=15.0, help="length of each measure")
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--runs", type=int, default=5, help="spawns to time")
    parser.add_argument("--only", choices=["cpu", "spawn"], help="one part alone")
    args, _ = parser.parse_known_args()
    if not WORLD.exists():
        print(f"{WORLD} is not here: the viewer benchmark draws gz-sim's diff_drive.sdf; "
              "left out")
        return
    if args.only != "spawn":
        cpu_part(args)
    if args.only != "cpu":
        spawn_part(args)


def cpu_part(args: argparse.Namespace) -> None:
    env, router = start_router()
    env["GZ_SIM_RESOURCE_PATH"] = str(WORLD.parent)
    figures: dict[str, list[tuple[float, float]]] = {"headless": [], "idle": [], "watched": []}
    driver = browser()
    try:
        for _ in range(args.rounds):
            for condition in figures:
                sim = Sim(env, gui=condition != "headless")
                try:
                    if condition == "watched":
                        driver.get(sim.url)
                        sim.wait_said("browser connected")
                    figures[condition].append(sim.measure(args.seconds))
                finally:
                    driver.get("about:blank")
                    sim.close()
    finally:
        driver.quit()
        router.terminate()
        router.wait()

    def cpu(condition: str) -> list[float]:
        return [c for c, _ in figures[condition]]

    def rtf(condition: str) -> list[float]:
        return [r for _, r in figures[condition]]

    added = [w - h for w, h in zip(cpu("watched"), cpu("headless"), strict=True)]
    idle = [i - h for i, h in zip(cpu("idle"), cpu("headless"), strict=True)]
    table(f"web viewer (paced 1 kHz, gz-sim's diff_drive.sdf, {args.seconds:g} s each)", [
        ("sim CPU %, headless", "report", summary(cpu("headless"))),
        ("sim CPU %, viewer, no browser", "report", summary(cpu("idle"))),
        ("sim CPU %, viewer, one browser at 30 Hz", "report", summary(cpu("watched"))),
        ("viewer's cost, no browser (% of a core)", "next to 0", summary(idle)),
        ("viewer's cost, one browser (% of a core)", "<= 8", summary(added)),
        ("RTF, viewer and one browser", "1.00", summary(rtf("watched"))),
        ("RTF, headless", "1.00", summary(rtf("headless"))),
    ])


def spawn_part(args: argparse.Namespace) -> None:
    env, router = start_router()
    env["GZ_SIM_RESOURCE_PATH"] = str(WORLD.parent)
    driver = browser("480,360")
    try:
        sim = Sim(env, gui=True)
        try:
            driver.get(sim.url)
            sim.wait_said("browser connected")
            time.sleep(5)  # the page loaded and drawing
            seen, shots = appearance(sim, driver, args.runs)
        finally:
            sim.close()
    finally:
        driver.quit()
        router.terminate()
        router.wait()
    table("web viewer: a spawn seen in the browser", [
        ("spawn to a screenshot with the box (at most), s", "report", summary(seen)),
        ("  (a screenshot's own time, s)", "report", summary(shots)),
    ])


if __name__ == "__main__":
    os.environ.setdefault("PYTHONDONTWRITEBYTECODE", "1")
    main()
