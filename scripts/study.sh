#!/usr/bin/env bash
# Accuracy against time, in one command (docs/accuracy-vs-time.md): builds glint (release),
# runs `glint study` and `glint study --scaling` into one folder, then computes FLIP, the
# Pareto fronts, the plots and the tables with scripts/study.py in a venv (build/venv).
#
#   scripts/study.sh [--out DIR] [--size WxH] [--frame-count N] [--spp N] [--runs N]
#                    [--effect reflections|shadows|all] [--budget-us B] [--quick] [--glint PATH]
#                    [--python PATH] [--no-plots | --plots-only]
#
# --glint PATH uses an existing glint binary instead of building one; --python PATH uses an
# interpreter that already has flip_evaluator, matplotlib and numpy instead of the venv.
# Without network (the GPU machine): measure with --no-plots, bring DIR back, and run
# `scripts/study.sh --plots-only --out DIR` where pip can install the packages (or carry the
# flip-evaluator wheel there and use --python; docs/accuracy-vs-time.md).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=out/study
glint=""
python=""
measure=1
plots=1
args=()
while (($#)); do
  case "$1" in
    --out) out=$2; shift 2 ;;
    --size | --frame-count | --spp | --runs | --effect | --budget-us) args+=("$1" "$2"); shift 2 ;;
    --quick) args+=(--quick); shift ;;
    --glint) glint=$2; shift 2 ;;
    --python) python=$2; shift 2 ;;
    --no-plots) plots=0; shift ;;
    --plots-only) measure=0; shift ;;
    *) echo "study.sh: unknown option '$1' (see the comment at the top of scripts/study.sh)" >&2; exit 2 ;;
  esac
done
cd "$root"

if ((measure)); then
  if [ -z "$glint" ]; then
    scripts/setup.sh release glint
    glint=build/release/harness/cli/glint
  fi
  "$glint" study --out "$out" "${args[@]}"
  # The scaling runs take --quick, --runs, --effect and --size (where the fractions are
  # measured); the resolutions they sweep are fixed (720p to 4K).
  scaling=()
  for ((i = 0; i < ${#args[@]}; i++)); do
    case "${args[i]}" in
      --quick) scaling+=(--quick) ;;
      --size | --runs | --effect) scaling+=("${args[i]}" "${args[i + 1]}") ;;
    esac
  done
  "$glint" study --scaling --out "$out" "${scaling[@]}"
fi

if ((plots)); then
  if [ -z "$python" ]; then
    scripts/python_env.sh
    python=build/venv/bin/python
  fi
  "$python" scripts/study.py "$out"
fi
