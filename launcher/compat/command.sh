# Sourced by compat/bin's scripts, with `launcher_command` set to launcher's command for the name:
# runs it with the interpreter named on the first line of the `launcher` found on PATH (pip's
# scripts name theirs there), so that pip's wrapper and its imports (re: a fifth of a
# `ros2 topic list`) are skipped. -P keeps the current folder off the module path, as the
# wrapper does. Where `launcher` is not such a script, the caller runs `launcher` itself.
launcher_path=$(command -v launcher) || return 0
IFS= read -r launcher_first < "$launcher_path" || return 0
case $launcher_first in
    '#!'/*python*)
        # shellcheck disable=SC2086 - the interpreter line may carry words (env python3)
        exec ${launcher_first#??} -P -c \
            'import sys; from launcher.cli.entry import main; sys.exit(main())' \
            "$launcher_command" "$@" ;;
esac
