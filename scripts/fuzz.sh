#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz) with clang, ASan and UBSan, and
# runs each one in turn for SECONDS (default 60), one process at a time.
#
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
#   SECONDS  fuzzing time per target; 0 only replays the seed corpus and the
#            saved regression inputs once (a quick check for CI)
#   TARGET   nff, json and/or obj (default: all three)
# Environment:
#   BUILD      build directory (default build-fuzz-targets)
#   JOBS       build parallelism (default: nproc)
#   FUZZ_ARGS  extra libFuzzer flags, e.g. "-max_len=16384"
#
# The growing corpus lives in $BUILD/corpus/<target> (seeded from
# tests/fuzz/corpus/<target>), logs in $BUILD/logs, and crashing inputs in
# $BUILD/crashes/<target>/ (each also replayed for its message and printed in
# base64, so a CI log alone reproduces it). Exits 1 when any target found a crash, leak,
# timeout or out-of-memory input; prints execs, exec/s and corpus size.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

seconds=${1:-60}
shift || true
targets=("$@")
[[ ${#targets[@]} -eq 0 ]] && targets=(nff json obj)
if ! [[ "$seconds" =~ ^[0-9]+$ ]]; then
  echo "usage: scripts/fuzz.sh [SECONDS] [nff|json|obj ...]" >&2
  exit 2
fi
for t in "${targets[@]}"; do
  case "$t" in
    nff|json|obj) ;;
    *) echo "fuzz.sh: unknown target '$t' (nff, json, obj)" >&2; exit 2 ;;
  esac
done

build=${BUILD:-build-fuzz-targets}
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}

# clang and its libFuzzer runtime (libclang-rt-14-dev) are optional packages.
runtime=(/usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a)
if ! command -v clang++ >/dev/null || [[ ! -f "${runtime[0]}" ]]; then
  scripts/install-deps.sh --optional
fi

# The main project builds tests/fuzz when tests/CMakeLists.txt hooks it in;
# otherwise tests/fuzz is configured as its own project, which pulls in the
# libraries. A build directory configured the other way is started afresh.
source_dir=tests/fuzz
if grep -q 'add_subdirectory(fuzz)' tests/CMakeLists.txt 2>/dev/null; then source_dir=.; fi
home="$root/$source_dir"
[[ "$source_dir" == "." ]] && home="$root"
if [[ -f "$build/CMakeCache.txt" ]] &&
   ! grep -qx "CMAKE_HOME_DIRECTORY:INTERNAL=$home" "$build/CMakeCache.txt"; then
  rm -rf "$build"
fi
CC=clang CXX=clang++ cmake -S "$source_dir" -B "$build" -DRAYLAB_FUZZ=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j "$jobs" --target fuzz_nff fuzz_json fuzz_obj

mkdir -p "$build/logs"
status=0
summary=()
for t in "${targets[@]}"; do
  exe="$build/bin/fuzz_$t"
  corpus="$build/corpus/$t"
  crashes="$build/crashes/$t"
  log="$build/logs/$t.log"
  mkdir -p "$corpus" "$crashes"
  common=(-close_fd_mask=2 -rss_limit_mb=2048 -timeout=10 -print_final_stats=1
          -artifact_prefix="$crashes/")
  # Saved regression inputs (tests/robustness/inputs/<t>-*) are replayed too.
  regressions=()
  for f in tests/robustness/inputs/"$t"-*; do [[ -f "$f" ]] && regressions+=("$f"); done
  if [[ "$seconds" -eq 0 ]]; then
    echo "== fuzz_$t: replaying tests/fuzz/corpus/$t and ${#regressions[@]} regression inputs"
    ok=1
    if ! "$exe" "${common[@]}" ${FUZZ_ARGS:-} -runs=0 "tests/fuzz/corpus/$t" >"$log" 2>&1; then
      ok=0
    fi
    if [[ ${#regressions[@]} -gt 0 ]] &&
       ! "$exe" "${common[@]}" ${FUZZ_ARGS:-} "${regressions[@]}" >>"$log" 2>&1; then
      ok=0
    fi
    if [[ $ok -eq 1 ]]; then
      summary+=("fuzz_$t: replay ok")
    else
      status=1
      tail -30 "$log"
      summary+=("fuzz_$t: replay FAILED (log: $log)")
    fi
    continue
  fi
  max_len=4096
  [[ "$t" == json ]] && max_len=8192
  echo "== fuzz_$t: ${seconds} s (log: $log)"
  # One process (-jobs=1 semantics): the machine is shared.
  if ! "$exe" "${common[@]}" -max_total_time="$seconds" -max_len="$max_len" \
        -dict="tests/fuzz/dict/$t.dict" ${FUZZ_ARGS:-} "$corpus" "tests/fuzz/corpus/$t" \
        >"$log" 2>&1; then
    status=1
    echo "fuzz_$t: FINDING (input saved under $crashes/):"
    grep -E "ERROR|SUMMARY|finding|deadly|timeout|out-of-memory|uncaught" "$log" | head -10
    # The run closed stderr (-close_fd_mask=2), which hides the harness's own
    # message, and a CI machine is gone with its files: replay each saved
    # input with stderr open for the message, and print the input itself
    # (base64, whole: at most max_len bytes) so the log alone reproduces it.
    for f in "$crashes"/*; do
      [[ -f "$f" ]] || continue
      echo "--- $(basename "$f"): replayed"
      "$exe" -timeout=10 -rss_limit_mb=2048 "$f" 2>&1 |
        grep -E "raylab fuzz finding|ERROR: |SUMMARY: " | head -5 || true
      echo "--- $(basename "$f"): the input, base64 (base64 -d > input; $exe input)"
      base64 -w 100 "$f"
    done
  fi
  fuzzstat() { grep -Eo "stat::$1: +[0-9]+" "$log" | grep -Eo '[0-9]+$' || echo "?"; }
  execs=$(fuzzstat number_of_executed_units)
  rate=$(fuzzstat average_exec_per_sec)
  rss=$(fuzzstat peak_rss_mb)
  size=$(find "$corpus" -type f | wc -l)
  cov=$(grep -Eo 'cov: [0-9]+ ft: [0-9]+' "$log" | tail -1 || true)
  found=$(find "$crashes" -type f | wc -l)
  line="fuzz_$t: ${seconds} s, $execs execs, $rate exec/s, corpus $size files, $cov"
  summary+=("$line, peak RSS ${rss} MB, $found saved findings")
done

echo
printf '%s\n' "${summary[@]}"
exit "$status"
