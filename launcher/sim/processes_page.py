"""The viewer's processes page: `/processes` on the viewer's port, behind its token, lists every
process of the launches running on the graph (as `launcher ps`) live, with stop, start and
restart buttons (as `launcher stop|start|restart`). It is a client of the launches' services
(bus/launches.py), like the CLI: one interface.

The page's requests are answered at once from what a thread of its own last heard (the viewer's
server never waits on the graph); that thread asks the launches once a second while the page is
looked at, and does the buttons' work, saying the outcome in the next table.
"""

from __future__ import annotations

import json
import queue
import threading
import time
import urllib.parse
from typing import Any

REFRESH = 1.0  # seconds between asks while the page is looked at
WATCHED = 10.0  # seconds after its last request the page counts as looked at
VERBS = ("stop", "start", "restart")

PAGE = """<!doctype html><html><head><meta charset="utf-8"><title>launcher: processes</title>
<style>body{font:14px sans-serif;margin:1em}table{border-collapse:collapse;margin-bottom:1.5em}
td,th{padding:3px 10px;border-bottom:1px solid #ccc;text-align:left}#said{color:#555}</style>
</head><body><h1>Processes</h1><p id="said"></p><div id="launches">…</div><script>
function cell(row, text) { const td = document.createElement("td"); td.textContent = text;
  row.appendChild(td); }
function act(launch, name, verb) {
  fetch(`/processes/act?launch=${launch}&name=${encodeURIComponent(name)}&verb=${verb}`); }
async function refresh() {
  try {
    const answer = await (await fetch("/processes.json")).json();
    document.getElementById("said").textContent = answer.said;
    const launches = document.getElementById("launches");
    launches.replaceChildren();
    for (const launch of answer.launches) {
      const title = document.createElement("h2");
      title.textContent = `${launch.launch} (pid ${launch.pid})`;
      launches.appendChild(title);
      if (launch.message) {
        const why = document.createElement("p");
        why.textContent = launch.message;
        launches.appendChild(why);
        continue;
      }
      const table = document.createElement("table");
      const head = table.insertRow();
      for (const name of ["name", "pid", "host", "state", "restarts", "uptime", "CPU %",
                          "memory", ""]) cell(head, name);
      for (const p of launch.processes) {
        const row = table.insertRow();
        row.dataset.name = p.name;
        for (const v of [p.name, p.pid || "-", p.host, p.state, p.restarts,
                         p.pid ? `${Math.round(p.uptime)} s` : "-",
                         p.cpu >= 0 ? p.cpu.toFixed(1) : "-",
                         p.memory >= 0 ? `${(p.memory / 1048576).toFixed(1)} MiB` : "-"])
          cell(row, v);
        const buttons = document.createElement("td");
        for (const verb of ["stop", "start", "restart"]) {
          const button = document.createElement("button");
          button.textContent = verb;
          button.className = verb;
          button.onclick = () => act(launch.pid, p.name, verb);
          buttons.appendChild(button);
        }
        row.appendChild(buttons);
      }
      launches.appendChild(table);
    }
  } catch (e) { document.getElementById("said").textContent = String(e); }
}
refresh(); setInterval(refresh, 1000);
</script></body></html>
"""


class ProcessesPage:
    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._listing: list[dict[str, Any]] = []
        self._said = ""
        self._asked = 0.0  # when the page was last requested
        self._work: queue.SimpleQueue[tuple[str, str, str]] = queue.SimpleQueue()
        self._thread: threading.Thread | None = None

    def respond(self, path: str) -> tuple[int, str, bytes] | None:
        """(status, content type, body) for a path of the page's; None for other paths."""
        parsed = urllib.parse.urlsplit(path)
        if parsed.path not in ("/processes", "/processes.json", "/processes/act"):
            return None
        self._asked = time.monotonic()
        self._start()
        if parsed.path == "/processes":
            return 200, "text/html; charset=utf-8", PAGE.encode()
        if parsed.path == "/processes.json":
            with self._lock:
                body = {"launches": self._listing, "said": self._said}
            return 200, "application/json", json.dumps(body).encode()
        query = dict(urllib.parse.parse_qsl(parsed.query))
        verb, name, launch = query.get("verb", ""), query.get("name", ""), query.get("launch", "")
        if verb not in VERBS or not name or not launch.isdigit():
            return 400, "application/json", json.dumps(
                {"error": f"expected verb ({', '.join(VERBS)}), name and launch (a pid)"}
            ).encode()
        self._work.put((launch, name, verb))
        return 202, "application/json", b'{"queued": true}'

    # --- the page's thread ----------------------------------------------------------------------
    def _start(self) -> None:
        with self._lock:
            if self._thread is None:
                self._thread = threading.Thread(target=self._serve, name="processes-page",
                                                daemon=True)
                self._thread.start()

    def _serve(self) -> None:
        from launcher.bus.launches import Launches
        from launcher.errors import LaunchError

        try:
            launches = Launches("_launcher_viewer")
        except LaunchError as exc:  # (no graph: said on the page; the next request tries again)
            with self._lock:
                self._said, self._thread = f"cannot reach the graph: {exc.message}", None
            return
        while True:
            try:
                item = self._work.get(timeout=REFRESH)
            except queue.Empty:
                item = None
            if item is not None:
                self._act(launches, *item)
            if time.monotonic() - self._asked < WATCHED:
                try:
                    listing = [shown(launch) for launch in launches.all()]
                except LaunchError as exc:
                    listing = []
                    with self._lock:
                        self._said = exc.message
                with self._lock:
                    self._listing = listing

    def _act(self, launches: Any, pid: str, name: str, verb: str) -> None:
        from launcher.errors import LaunchError

        try:
            launch = next(each for each in launches.all() if str(each.listing.pid) == pid)
            said = launches.act(launch, name, verb)
        except StopIteration:
            said = f"no running launch has pid {pid}"
        except LaunchError as exc:
            said = exc.message
        with self._lock:
            self._said = said


def shown(launch: Any) -> dict[str, Any]:
    listing = launch.listing
    return {"launch": listing.launch, "pid": listing.pid, "message": listing.message,
            "processes": [
        {"name": p.name, "pid": p.pid, "host": p.host, "state": p.state,
         "restarts": p.restarts, "uptime": p.uptime, "cpu": p.cpu, "memory": p.memory}
        for p in listing.processes]}
