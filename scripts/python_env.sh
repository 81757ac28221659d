#!/usr/bin/env bash
# The Python environment of scripts/study.py and its tests: build/venv with flip-evaluator,
# matplotlib and numpy (from the network, pinned). Installs python3-venv when it is missing.
# Idempotent: with everything in place it checks and returns in a second. Prints nothing on
# success; the interpreter is build/venv/bin/python.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
venv="$root/build/venv"
# Versions checked to install together on Debian bookworm's Python 3.11.
packages=(flip-evaluator==1.7 matplotlib==3.11.2 numpy==2.4.6)
if [ -x "$venv/bin/python" ] && "$venv/bin/python" -c "import flip_evaluator, matplotlib, numpy" 2>/dev/null; then
  exit 0
fi
if ! python3 -c "import ensurepip, venv" 2>/dev/null; then
  echo "python_env: installing python3-venv"
  sudo=()
  if [ "$(id -u)" -ne 0 ]; then sudo=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" apt-get install -y -q --no-install-recommends python3-venv
fi
if [ ! -x "$venv/bin/python" ]; then
  rm -rf "$venv"
  python3 -m venv "$venv"
fi
"$venv/bin/pip" install -q --disable-pip-version-check "${packages[@]}"
