#!/usr/bin/env bash
# Runs every libFuzzer target (tests/fuzz, docs/robustness.md) on its committed corpus for a
# bounded time: installs what is missing (clang, libFuzzer), configures and builds the fuzz
# preset, then runs each target with the limits below on a copy of its corpus, so that a run
# never writes into the repository. Fails on any crash, sanitizer report, leak, timeout
# (> 1 s for one input) or out-of-memory (> 512 MB RSS or one allocation > 512 MB); the
# input that failed is kept under build/fuzz/artifacts/<target>/, each target's libFuzzer
# output in build/fuzz/logs/<target>.log.
#   scripts/fuzz.sh [seconds per target, default 60]
#   scripts/fuzz.sh --smoke   the test suite's bounded, deterministic run (label fuzz): every
#                             target replays its committed corpus; every target but gltf then
#                             runs GLINT_FUZZ_SMOKE_RUNS (default 4000) mutations from seed 1.
#                             gltf replays only: assimp 5.2.5 crashes a few mutations away from
#                             its seeds (docs/robustness.md), which would make the gate a
#                             lottery on assimp's bugs rather than glint's.
# Environment:
#   GLINT_FUZZ_TARGETS="frame scene ..."   run only these targets
#   GLINT_FUZZ_RUNS=N                       also stop each target after N executions
#   GLINT_FUZZ_KEEP_CORPUS=DIR              keep each target's grown corpus in DIR/<target>
#   GLINT_FUZZ_NO_SETUP=1                   use the fuzz build as it is (the test suite's run:
#                                           scripts/test.sh builds it first)
set -euo pipefail
smoke=0
if [ "${1:-}" = --smoke ]; then
  smoke=1
  shift
fi
seconds=${1:-60}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
targets=(${GLINT_FUZZ_TARGETS:-frame manifest scene gltf channel_map mapped_frame camera_file})

bin="$root/build/fuzz/tests/fuzz"
if [ "${GLINT_FUZZ_NO_SETUP:-}" = 1 ]; then
  if [ ! -x "$bin/glint_fuzz_frame" ]; then
    if [ "${CI:-}" = true ] || [ "${GLINT_FORBID_SKIPS:-}" = 1 ]; then
      echo "fuzz: no fuzz build in $bin (scripts/setup.sh fuzz builds it)" >&2
      exit 1
    fi
    echo "GLINT_SKIP: no fuzz build in $bin (scripts/setup.sh fuzz builds it)"
    exit 0
  fi
else
  "$root/scripts/setup.sh" fuzz
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/glint-fuzz-run.XXXXXX")
trap 'rm -rf "$work"' EXIT
# Scratch files of the targets (each writes its input to a file) go to memory when it can.
scratch="$work/tmp"
if [ -d /dev/shm ] && [ -w /dev/shm ]; then scratch=$(mktemp -d /dev/shm/glint-fuzz-tmp.XXXXXX); fi
mkdir -p "$scratch"
trap 'rm -rf "$work" "$scratch"' EXIT

# A smaller ASan quarantine keeps RSS meaningful against -rss_limit_mb (the default 256 MB
# of freed memory held back would count as the target's own).
export ASAN_OPTIONS="detect_leaks=1:quarantine_size_mb=64:symbolize=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Leaks inside third-party libraries that glint cannot fix, each with its upstream issue.
export LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp:print_suppressions=0"
if [ -x /usr/lib/llvm-14/bin/llvm-symbolizer ]; then export ASAN_SYMBOLIZER_PATH=/usr/lib/llvm-14/bin/llvm-symbolizer; fi

failed=()
summary=()
for target in "${targets[@]}"; do
  exe="$bin/glint_fuzz_$target"
  [ -x "$exe" ] || { echo "fuzz: no target $target ($exe)" >&2; exit 2; }
  corpus="$work/corpus/$target"
  mkdir -p "$corpus"
  cp -r "$root/tests/fuzz/corpus/$target/." "$corpus/"
  if [ "$target" = gltf ] && [ "$smoke" = 0 ] && [ -d /usr/share/assimp/models/glTF2 ]; then
    # assimp's test models (package assimp-testmodels) as further seeds, not committed here.
    find /usr/share/assimp/models/glTF2 -type f \( -name '*.gltf' -o -name '*.glb' \) -size -64k \
      -exec sh -c 'for f; do cp "$f" "$0/assimp_$(echo "$f" | md5sum | cut -c1-12)_$(basename "$f")"; done' "$corpus" {} +
  fi
  artifacts="$root/build/fuzz/artifacts/$target"
  mkdir -p "$artifacts"
  mkdir -p "$root/build/fuzz/logs"
  log="$root/build/fuzz/logs/$target.log"
  args=(-max_total_time="$seconds" -rss_limit_mb=512 -malloc_limit_mb=512 -timeout=1
        -print_final_stats=1 -artifact_prefix="$artifacts/")
  [ -n "${GLINT_FUZZ_RUNS:-}" ] && args+=(-runs="$GLINT_FUZZ_RUNS")
  if [ "$smoke" = 1 ]; then
    # A count of executions from a fixed seed, not a time: the same inputs on every machine.
    # The time limit only guards against a machine far slower than expected.
    runs=${GLINT_FUZZ_SMOKE_RUNS:-4000}
    [ "$target" = gltf ] && runs=0
    args=(-seed=1 -runs="$runs" -max_total_time=120 -rss_limit_mb=512 -malloc_limit_mb=512 -timeout=1
          -print_final_stats=1 -artifact_prefix="$artifacts/")
  fi
  echo "fuzz: $target $( [ "$smoke" = 1 ] && echo "for ${runs} mutations" || echo "for ${seconds}s") on $(ls "$corpus" | wc -l) seeds"
  status=0
  start=$SECONDS
  TMPDIR="$scratch" "$exe" "${args[@]}" "$corpus" >"$log" 2>&1 || status=$?
  elapsed=$((SECONDS - start))
  final=$(grep -E '^#[0-9]+[[:space:]]+(DONE|pulse|NEW|REDUCE|INITED)' "$log" | tail -1 || true)
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rss=$(sed -n 's/^stat::peak_rss_mb: *//p' "$log" | tail -1)
  cov=$(sed -n 's/.* cov: \([0-9]*\) ft: \([0-9]*\).*/cov \1 ft \2/p' <<<"$final")
  if [ "$status" -ne 0 ]; then
    failed+=("$target")
    summary+=("$target: FAILED (exit $status) after ${execs:-?} executions in ${elapsed}s; see $log")
    echo "fuzz: $target FAILED (exit $status); artifacts in $artifacts" >&2
    grep -E 'ERROR|SUMMARY|runtime error|Test unit written|libFuzzer:' "$log" | head -20 >&2 || true
    tail -40 "$log" >&2
  else
    summary+=("$target: ${execs:-?} executions in ${elapsed}s, ${cov:-no coverage line}, peak RSS ${rss:-?} MB")
  fi
  if [ -n "${GLINT_FUZZ_KEEP_CORPUS:-}" ]; then
    mkdir -p "$GLINT_FUZZ_KEEP_CORPUS/$target"
    cp -r "$corpus/." "$GLINT_FUZZ_KEEP_CORPUS/$target/"
  fi
done

printf 'fuzz: %s\n' "${summary[@]}"
if ((${#failed[@]})); then
  echo "fuzz: failed: ${failed[*]}" >&2
  exit 1
fi
