# Apply the environment hooks of every package launcher can see to this shell, as sourcing a
# colcon workspace's setup.sh does, and turn on tab completion (bash, zsh):   . hooks/setup.sh
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
