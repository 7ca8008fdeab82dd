#!/usr/bin/env bash
# Runs one libFuzzer target for ctest (tests/fuzz/CMakeLists.txt).
#
#   run_fuzz.sh replay FUZZER SEEDS REGRESSIONS        every seed and regression input, once
#   run_fuzz.sh run    FUZZER SEEDS REGRESSIONS WORK [DICT]
#                      fuzz $FLUIDVIZ_FUZZ_RUNS inputs (default 60000) from seed $FLUIDVIZ_FUZZ_SEED
#                      (default 1), at most $FLUIDVIZ_FUZZ_SECONDS (default 30), with dictionary DICT
#
# Exits non-zero on any finding (crash, sanitizer report, unexpected exception, leak, timeout,
# allocation over the limit). `run` prints libFuzzer's execution count and, on a finding, where
# the input was saved; a fixed finding's input belongs in REGRESSIONS (tests/fuzz/regressions/).
set -euo pipefail
mode=$1 fuzzer=$2 seeds=$3 regressions=$4
name=$(basename "$fuzzer")

# scripts/sanitize.sh exports the sanitizer options; these defaults make the test work alone too.
root=$(cd "$(dirname "$0")/../.." && pwd)
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:halt_on_error=1:print_stacktrace=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tests/sanitizers/lsan.supp}

# -timeout: an input that takes this long (s) is a finding (a hang); -rss_limit_mb and
# -malloc_limit_mb: a file may not make the reader allocate more than this (MB).
limits=(-timeout=30 -rss_limit_mb=2560 -malloc_limit_mb=1024)

case $mode in
  replay)
    inputs=()
    for dir in "$seeds" "$regressions"; do
      [[ -d "$dir" ]] || continue
      while IFS= read -r -d '' f; do inputs+=("$f"); done < <(find "$dir" -type f ! -name '*.md' -print0 | sort -z)
    done
    [[ ${#inputs[@]} -gt 0 ]] || { echo "$name: no inputs in $seeds or $regressions" >&2; exit 1; }
    echo "$name: replaying ${#inputs[@]} inputs"
    # Each input as a corpus of its own (-runs=0: run it once, mutate nothing), not as a file named
    # on the command line: libFuzzer checks an input for leaks only when it is run from a corpus and
    # adds coverage, which an input among others may not. Named as files, or in one corpus with the
    # rest, vtp_reader/misspelt_points_components_leaks_in_vtk.vtp replayed clean while it leaked.
    corpus=$(mktemp -d)
    trap 'rm -rf "$corpus"' EXIT
    for f in "${inputs[@]}"; do
      rm -rf "${corpus:?}"/*
      cp "$f" "$corpus/"
      "$fuzzer" "${limits[@]}" -runs=0 -artifact_prefix="$corpus/" "$corpus" 2>"$corpus.log" ||
        { cat "$corpus.log" >&2; echo "$name: finding on replay of $f" >&2; rm -f "$corpus.log"; exit 1; }
    done
    rm -f "$corpus.log"
    echo "$name: ${#inputs[@]} inputs replayed clean (each alone, leaks checked)"
    ;;
  run)
    work=$5
    dict=()
    [[ $# -ge 6 ]] && dict=(-dict="$6")
    seconds=${FLUIDVIZ_FUZZ_SECONDS:-30}
    # New corpus entries go to WORK (first directory); seeds and regressions are only read.
    rm -rf "$work"
    mkdir -p "$work/corpus" "$work/findings"
    dirs=("$work/corpus" "$seeds")
    [[ -d "$regressions" ]] && dirs+=("$regressions")
    log="$work/fuzz.log"
    status=0
    # A fixed seed and run count make the CI run the same sequence of inputs every time (a red CI
    # is then a real regression, not a new random finding); the time limit only cuts it short,
    # and a prefix of a clean sequence is clean. Explore further by hand with another
    # FLUIDVIZ_FUZZ_SEED and larger FLUIDVIZ_FUZZ_RUNS.
    "$fuzzer" "${limits[@]}" "${dict[@]}" -seed="${FLUIDVIZ_FUZZ_SEED:-1}" \
      -runs="${FLUIDVIZ_FUZZ_RUNS:-60000}" -max_total_time="$seconds" -print_final_stats=1 \
      -artifact_prefix="$work/findings/" "${dirs[@]}" >"$log" 2>&1 || status=$?
    grep -E '^(#[0-9]+[[:space:]]+DONE|stat::number_of_executed_units|stat::peak_rss_mb)' "$log" || true
    if [[ $status -ne 0 ]]; then
      tail -n 80 "$log"
      echo "$name: FINDING (exit $status) after fuzzing; input(s): $(ls "$work/findings")" >&2
      echo "$name: full log $log; once fixed, copy the input into $regressions/" >&2
      exit 1
    fi
    echo "$name: no finding (seed ${FLUIDVIZ_FUZZ_SEED:-1}, at most ${FLUIDVIZ_FUZZ_RUNS:-60000} runs or ${seconds} s)"
    ;;
  *)
    echo "usage: $0 replay FUZZER SEEDS REGRESSIONS | run FUZZER SEEDS REGRESSIONS WORK [DICT]" >&2
    exit 2
    ;;
esac
