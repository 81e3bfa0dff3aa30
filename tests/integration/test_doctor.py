"""`launcher doctor`: the checks pass on this install and name what to fix when they do not."""

from __future__ import annotations

from tests.support.packages import make_tree, manifest


def test_doctor_on_a_good_install(ws):
    make_tree(ws.root / "src", {"robot_sim/package.xml": manifest("robot_sim")})
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "src")
    done = ws.run("doctor", timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    lines = {line.split()[1]: line.split()[0] for line in done.stdout.splitlines()
             if line[:4].strip() in ("ok", "note", "FAIL")}
    assert lines["Python"] == "ok" and lines["MuJoCo"] == "ok" and lines["EGL"] == "ok"
    assert lines["Zenoh"] == "ok" and lines["package"] == "ok"
    assert "packages under " + str(ws.root / "src") in done.stdout
    assert done.stdout.rstrip().endswith("all good")


def test_doctor_names_what_to_fix(ws):
    make_tree(ws.root / "src", {
        "robot_sim/package.xml": manifest("robot_sim"),
        "robot_sim/hooks/robot_sim.dsv": "prepend-non-duplicate;PATH\n",
    })
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "src")
    ws.env["LAUNCHER_ROUTER"] = "carrier-pigeon/1.2.3.4"
    done = ws.run("doctor", timeout=120)
    assert done.returncode == 1
    fails = [line for line in done.stdout.splitlines() if line.startswith("FAIL")]
    assert any("the graph's router" in line and "LAUNCHER_ROUTER" in line for line in fails), \
        done.stdout
    hooks = [line for line in fails if "environment hooks" in line]
    assert len(hooks) == 1 and hooks[0].count("robot_sim.dsv:1:1") == 1, done.stdout
    assert "2 to fix: the graph's router, environment hooks" in done.stdout
    ws.env.pop("LAUNCHER_ROUTER")
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "nowhere")
    missing = ws.run("doctor", timeout=120)
    assert missing.returncode == 1 and "which is not a folder" in missing.stdout
    assert "Traceback" not in missing.stdout + missing.stderr
