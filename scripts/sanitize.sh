#!/usr/bin/env bash
# README command 2, second stage (issue 8): the whole test suite under AddressSanitizer +
# UndefinedBehaviorSanitizer, plus short libFuzzer runs of the readers (tests/fuzz).
#
#   scripts/sanitize.sh [ctest args...]
#
# Builds with clang in build-asan/ (FLUIDVIZ_ASAN_BUILD_DIR) with -DFLUIDVIZ_SANITIZE=ON
# -DFLUIDVIZ_FUZZ=ON (top-level CMakeLists.txt) and runs every ctest test there: the unit,
# validation and CLI tests, the ParaView checks, fuzz_<target>_replay (seed corpus and every
# past finding, tests/fuzz/regressions/) and fuzz_<target>_run, which fuzzes each target for
# the same FLUIDVIZ_FUZZ_RUNS (60000) inputs from FLUIDVIZ_FUZZ_SEED (1), at most
# FLUIDVIZ_FUZZ_SECONDS (default 30), and fails on any finding. Benchmarks are not built: they
# measure speed, which sanitizers distort. Any sanitizer report fails the test that caused it.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
build="${FLUIDVIZ_ASAN_BUILD_DIR:-$root/build-asan}"

# halt_on_error: the first report fails the test. detect_leaks with a suppressions file that
# names only third-party libraries (Mesa, VTK, fontconfig keep process-lifetime allocations).
# check_initialization_order/strict_init_order: static initialisers must not use each other.
# UBSan: print the stack, stop at the first report (the build also has -fno-sanitize-recover).
# Exported for the build too: gtest_discover_tests runs the test executables while building.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:check_initialization_order=1:strict_init_order=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export FLUIDVIZ_FUZZ_SECONDS="${FLUIDVIZ_FUZZ_SECONDS:-30}"

# Configured every time, so that an older build-asan/ gets these options too (the compiler is
# fixed at the first configure; clang is needed for libFuzzer). The build type's own "-O2 -g" is
# replaced: the top-level CMakeLists.txt adds -O1 -gline-tables-only. The ParaView modules are shared
# with the Release build's folder (setup_paraview.sh is idempotent; extracted once per clone).
CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$build" -G Ninja \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" -DFLUIDVIZ_SANITIZE=ON -DFLUIDVIZ_FUZZ=ON \
  -DFLUIDVIZ_BUILD_BENCH=OFF \
  -DFLUIDVIZ_PARAVIEW_PYTHON_DIR="${FLUIDVIZ_BUILD_DIR:-$root/build}/paraview-python" >/dev/null
cmake --build "$build" -j "$(nproc)"
cd "$build"
# The fuzz runs are started first (-j 2 then runs the rest of the suite beside them). The long
# convergence studies of tests/sanitizers/release_only_tests.txt run in the Release stage only.
release_only=$(grep -v '^#' "$root/tests/sanitizers/release_only_tests.txt" | grep -v '^$' |
               sed 's/[.]/[.]/g' | paste -sd '|')
ctest --output-on-failure --timeout 900 -j 2 -E "^($release_only)\$" "$@"
