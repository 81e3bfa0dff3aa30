# bash: . hooks/setup.bash   (the same as setup.sh; BASH_SOURCE finds the repo)
LAUNCHER_REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd) . "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
