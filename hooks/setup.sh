# Apply the environment hooks of every package launcher can see to this shell, as sourcing a
# colcon workspace's setup.sh does; put ROS's commands (ros2, roslaunch, rostopic, …) last on
# PATH; turn on tab completion (bash, zsh):   . hooks/setup.sh
# Uses the repo's .venv (sh hooks/bootstrap.sh demo|test makes it); LAUNCHER_PACKAGE_PATH
# adds workspaces of your own.
_launcher_repo=${LAUNCHER_REPO:-}
if [ -z "$_launcher_repo" ]; then
    if [ -n "${BASH_SOURCE:-}" ]; then
        _launcher_repo=$(cd "$(dirname "$BASH_SOURCE")/.." && pwd)
    elif [ -n "${ZSH_VERSION:-}" ]; then
        _launcher_repo=$(cd "$(dirname "${(%):-%x}")/.." && pwd)
    elif [ -f hooks/setup.sh ]; then
        _launcher_repo=$(pwd)
    fi
fi
if [ -x "$_launcher_repo/.venv/bin/launcher" ]; then
    eval "$(cd "$_launcher_repo" && .venv/bin/launcher env --shell sh)"
    PATH="$_launcher_repo/.venv/bin:$PATH"; export PATH
    # ROS's commands (ros2, roslaunch, rostopic, …, gz) came LAST on PATH with the env above:
    # a real ROS or Gazebo earlier on PATH wins. roscd and rosls, as ROS 1's setup defines
    # them, unless the shell has its own.
    if ! command -v roscd >/dev/null 2>&1; then
        roscd() {
            if [ $# -eq 0 ]; then cd "${ROS_WORKSPACE:-$HOME}" || return; return; fi
            _launcher_dir=$(rospack find "${1%%/*}") || return
            case $1 in */*) cd "$_launcher_dir/${1#*/}" ;; *) cd "$_launcher_dir" ;; esac
        }
    fi
    if ! command -v rosls >/dev/null 2>&1; then
        rosls() {
            _launcher_dir=$(rospack find "${1%%/*}") || return
            case $1 in */*) ls "$_launcher_dir/${1#*/}" ;; *) ls "$_launcher_dir" ;; esac
        }
    fi
    # Tab completion of commands, options, topics, nodes and packages (as ros2cli's setup)
    if [ -n "${BASH_VERSION:-}" ]; then
        eval "$("$_launcher_repo/.venv/bin/register-python-argcomplete" --shell bash launcher)"
    elif [ -n "${ZSH_VERSION:-}" ]; then
        autoload -U compinit && { whence compdef >/dev/null || compinit; }
        eval "$("$_launcher_repo/.venv/bin/register-python-argcomplete" --shell zsh launcher)"
    fi
else
    echo "launcher: no .venv under '${_launcher_repo:-?}'; run: sh hooks/bootstrap.sh test" >&2
fi
unset _launcher_repo
