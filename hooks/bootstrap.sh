#!/bin/sh
# Set up launcher in a virtual environment under the repo (.venv), then run the demo or the
# tests. Needs only Python 3.11+ on the machine; everything else comes from PyPI.
#   sh hooks/bootstrap.sh demo   # set up, then run the demo (headless)
#   sh hooks/bootstrap.sh test   # set up, then run the test suite
set -eu
cd "$(dirname "$0")/.."
say() { echo "[set-up] $*"; }

find_python() {
    for candidate in ${PYTHON:-} python3.13 python3.12 python3.11 python3; do
        if command -v "$candidate" >/dev/null 2>&1 &&
            "$candidate" -c 'import sys; sys.exit(sys.version_info < (3, 11))' 2>/dev/null; then
            echo "$candidate"
            return 0
        fi
    done
    echo "launcher needs Python 3.11 or newer; set PYTHON=/path/to/python3.11" >&2
    return 1
}

# `launcher sim snapshot` renders offscreen with EGL, which Debian's Mesa packages provide.
# (ldconfig lives in /sbin, which a user's PATH may not hold.)
ldconfig=$(command -v ldconfig || echo /sbin/ldconfig)
if ! "$ldconfig" -p 2>/dev/null | grep -q 'libEGL_mesa.so.0'; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        say "installing Mesa's EGL (libegl1 libegl-mesa0 libgl1-mesa-dri): pictures of the" \
            "world render offscreen with it"
        apt-get update -qq >/dev/null && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
            libegl1 libegl-mesa0 libgl1-mesa-dri >/dev/null
    else
        echo "note: pictures (launcher sim snapshot) need EGL:" \
            "apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri" >&2
    fi
fi

# The tests put a graph across two network namespaces (`ip`, iproute2), act as another user
# (`setpriv`, util-linux), try tab completion in zsh and draw view_frames' PDF (graphviz's dot).
if [ "${1:-}" = test ] && ! { command -v ip && command -v setpriv && command -v zsh \
    && command -v dot; } >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        say "installing iproute2, util-linux, zsh and graphviz (ip, setpriv, zsh, dot): the" \
            "tests put a graph across two network namespaces, act as another user, complete" \
            "in zsh and draw the tf tree"
        apt-get update -qq >/dev/null && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
            iproute2 util-linux zsh graphviz >/dev/null
    else
        echo "note: the tests need ip, setpriv, zsh and dot: apt-get install iproute2" \
            "util-linux zsh graphviz" >&2
    fi
fi

# The tests of nodes on other hosts log in over ssh to real OpenSSH servers, each in a network
# namespace of its own (Debian's sshd, and the ssh client with ssh-keygen).
if [ "${1:-}" = test ] && ! { [ -x /usr/sbin/sshd ] && command -v ssh && command -v ssh-keygen; \
    } >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        say "installing openssh-server and openssh-client (sshd, ssh): the tests start nodes" \
            "on other hosts over ssh, each host an sshd in a network namespace of its own"
        apt-get update -qq >/dev/null && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
            openssh-server openssh-client >/dev/null
    else
        echo "note: the tests of nodes on other hosts need sshd and ssh: apt-get install" \
            "openssh-server openssh-client" >&2
    fi
fi

# The viewer's test looks at the page in a real browser: Debian's Chromium, driven headless
# through its chromedriver (selenium comes with the test extras).
if [ "${1:-}" = test ] && ! { command -v chromium && command -v chromedriver; } >/dev/null 2>&1
then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        say "installing chromium and chromium-driver for the web viewer's browser test" \
            "(about a minute, once)"
        apt-get update -qq >/dev/null && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
            chromium chromium-driver >/dev/null
    else
        echo "note: the web viewer's browser test needs: apt-get install chromium" \
            "chromium-driver" >&2
    fi
fi

# The foxglove bridge's tests drive Foxglove's own client (@foxglove/ws-protocol, from npm)
# with Node.js: Debian's nodejs and npm where they are missing.
if [ "${1:-}" = test ] && ! { command -v node && command -v npm; } >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        say "installing nodejs and npm: the foxglove bridge's tests drive Foxglove's own" \
            "client with them"
        apt-get update -qq >/dev/null && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
            nodejs npm >/dev/null
    else
        echo "note: the foxglove bridge's tests need Node.js: apt-get install nodejs npm" >&2
    fi
fi

if [ ! -x .venv/bin/python ]; then
    python=$(find_python)
    say "making the virtual environment .venv with $python ($("$python" --version 2>&1))"
    "$python" -m venv .venv
fi
# Install (again) when pyproject.toml is newer than the last install. `compat` editable mode
# puts the repo on sys.path with a plain .pth entry: no import hook, faster start-up.
if [ ! -f .venv/.installed ] || [ pyproject.toml -nt .venv/.installed ]; then
    say "installing launcher into .venv with its dependencies from PyPI (MuJoCo, Zenoh," \
        "rosbags, xacro, matplotlib for launcher plot, OpenCV for cv_bridge, Ray for" \
        "launcher batch, the tests' pytest, mcap, selenium, and MkDocs for the docs site the" \
        "tests build): a minute or two the first time, seconds after"
    .venv/bin/python -m pip install --quiet --disable-pip-version-check \
        --config-settings editable_mode=compat -e ".[test,docs,plot,vision,cluster]"
    touch .venv/.installed
else
    say ".venv is up to date"
fi
# The build tools of `colcon build` (pyproject's `tools` extra), apart under .venv/tools: their
# colcon and cmake must never shadow a user's own (launcher's `colcon` runs them from there).
if [ ! -f .venv/tools/.installed ] || [ pyproject.toml -nt .venv/tools/.installed ]; then
    say "installing the build tools of colcon build under .venv/tools (colcon with its ROS," \
        "CMake and Python extensions, CMake, Ninja): a few seconds"
    .venv/bin/python -c 'import tomllib; print("\n".join(tomllib.load(open("pyproject.toml",
"rb"))["project"]["optional-dependencies"]["tools"]))' > .venv/tools-requirements.txt
    # (--use-pep517: EmPy, which colcon-ros needs, is an sdist alone; without a wheel in
    # pip's cache a legacy `setup.py install` under --prefix leaves its module out)
    .venv/bin/python -m pip install --quiet --disable-pip-version-check --use-pep517 \
        --prefix .venv/tools -r .venv/tools-requirements.txt
    touch .venv/tools/.installed
fi
# The test clients from npm (tests/js/package-lock.json), in tests/js/node_modules.
if [ "${1:-}" = test ] && command -v npm >/dev/null 2>&1 && { [ ! -d tests/js/node_modules ] ||
    [ tests/js/package-lock.json -nt tests/js/node_modules ]; }; then
    say "installing the tests' Foxglove clients from npm (@foxglove/ws-protocol," \
        "@foxglove/rosmsg2-serialization) into tests/js/node_modules"
    (cd tests/js && npm ci --no-audit --no-fund --silent) && touch tests/js/node_modules
fi
# Byte-compile once: start-up time is benchmarked and some machines set PYTHONDONTWRITEBYTECODE.
.venv/bin/python -m compileall -q launcher >/dev/null
say "ready. In your shell, . hooks/setup.sh puts launcher, your workspace's hooks and tab" \
    "completion there (LAUNCHER_PACKAGE_PATH=/path/to/ws/src adds your packages)"

case "${1:-}" in
    demo) shift
        say "running the demo, headless, for 20 s: launcher launch" \
            "launch_files/robot.launch.yaml"
        exec .venv/bin/launcher launch launch_files/robot.launch.yaml --duration 20 \
        --noninteractive "$@" ;;
    test) shift
        # Side by side with pytest-xdist, each test on a graph of its own: one worker more
        # than the cores, since most tests spend their time waiting on the processes they
        # start (2 cores: 3 workers, about 11 minutes; one at a time, 24).
        workers=$(( $(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1) + 1 ))
        say "running the tests, $workers at a time (about 11 minutes on 2 cores):" \
            "python -m pytest -n $workers --dist loadgroup tests"
        # (--dist loadgroup: the tests of one Ray cluster share one worker, one at a time)
        exec .venv/bin/python -m pytest -n "$workers" --dist loadgroup tests "$@" ;;
    *) echo "usage: sh hooks/bootstrap.sh demo|test" >&2; exit 2 ;;
esac
