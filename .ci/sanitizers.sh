#!/usr/bin/env bash
# CI, after README's test command: builds the tests and examples with AddressSanitizer (leak checker
# included) and UndefinedBehaviorSanitizer, and runs ctest on them; any sanitizer report fails the run.
# -Og with line tables only (-g1) keeps the build short: on a 2-core CI-class machine it built the 9 programs in
# 10 min 21 s against 21 min 07 s at -O1 (test_optimizer 296 s against 571 s), and ran the tests in 534 s (530 s
# at -O1 on a busier machine; benchmark/Qzip/RESULTS.md, session 19); assertions stay on (no NDEBUG: Debug build type).
# Usage: bash .ci/sanitizers.sh [BUILD_DIR]   (default build-sanitizers)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-sanitizers}
start=$(date +%s)

# the compiler's sanitizer runtimes come with g++ (libasan8, libubsan1); install them if they are missing
if ! dpkg -s libasan8 libubsan1 >/dev/null 2>&1; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq libasan8 libubsan1
fi

# The tests run on the bundled meshes only: the shared corpus (../shared/data/quad), which README's test
# command already runs in Release, would take several minutes more under the sanitizers.
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DBUILD_TESTING=ON -DQZIP_BUILD_BENCHMARKS=OFF \
      -DQZIP_SHARED_DATA_DIR="$PWD/.ci/no-shared-corpus-under-sanitizers" \
      -DCMAKE_CXX_FLAGS_DEBUG="-Og -g1" -DCMAKE_CXX_FLAGS="$flags" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"
cmake --build "$build" -j2

# halt on the first report; new[] of absurd sizes must throw std::bad_alloc rather than abort where possible
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=0:detect_leaks=1:allocator_may_return_null=1:detect_stack_use_after_return=0:strict_string_checks=1:check_initialization_order=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="report_objects=0"
ctest --test-dir "$build" -j2 --output-on-failure
echo "sanitizers: built and ran the tests in $(( $(date +%s) - start )) s"
