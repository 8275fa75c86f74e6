#!/usr/bin/env bash
# CI, after the sanitizer run: builds the libFuzzer harness test/Qzip/fuzz/fuzz_qzip.cpp with clang
# (installed with apt-get if missing) and fuzzes 60000 inputs from a fixed seed (QZIP_FUZZ_RUNS, QZIP_FUZZ_SEED;
# at most QZIP_FUZZ_SECONDS, default 120: well above the 30-60 s the 60000 inputs take on a CI machine, so that
# every run tries all of them; a cap that cut the run short made its coverage depend on the machine's speed. The
# inputs still vary a little from run to run with the same seed (two runs: 1352 and 1355 new units), so a run may
# find an input an earlier one did not)
# from a seed corpus made of the bad-input corpus and two small test meshes. A crash, a leak, a hang
# (> 10 s on one input) or a sanitizer report fails the run; the input is printed in base64 (and kept
# under the artifact directory) so that it can be added to test/Qzip/data/bad/ (see test/Qzip/fuzz/README.md).
# Usage: bash .ci/fuzz.sh [BUILD_DIR]   (default build-fuzz)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-fuzz}
seconds=${QZIP_FUZZ_SECONDS:-120}
start=$(date +%s)

if ! command -v clang++ >/dev/null 2>&1 || ! dpkg -s libclang-rt-14-dev >/dev/null 2>&1; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq clang libclang-rt-14-dev
fi

cmake -S test/Qzip/fuzz -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=""
cmake --build "$build" -j2
built=$(date +%s)

work=$(mktemp -d)
mkdir -p "$work/corpus" "$work/seeds" "$work/artifacts"
# an input is: one byte for the format (0 OFF, 1 OBJ, 2 PLY), one byte seeding the random choices, the file
for f in test/Qzip/data/bad/* test/Qzip/data/polylap_amo_quad.off test/Qzip/data/noisy_sphere_triquad.obj; do
  [ "$(basename "$f")" = README.md ] && continue
  case "$f" in
    *.obj) format='\001' ;;
    *.ply) format='\002' ;;
    *) format='\000' ;;
  esac
  { printf "$format"; printf '\007'; cat "$f"; } > "$work/seeds/$(basename "$f")"
done

export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:allocator_may_return_null=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$PWD/test/Qzip/fuzz/ubsan_suppressions.txt"
status=0
# a fixed seed and a fixed number of runs keep CI reproducible: the same inputs on every run (the time
# limit only caps a slow machine); a longer, exploring run is documented in test/Qzip/fuzz/README.md
"$build/fuzz_qzip" -seed="${QZIP_FUZZ_SEED:-1}" -runs="${QZIP_FUZZ_RUNS:-60000}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
  -print_final_stats=1 -artifact_prefix="$work/artifacts/" "$work/corpus" "$work/seeds" || status=$?
if [ "$status" -ne 0 ]; then
  for a in "$work"/artifacts/*; do
    [ -e "$a" ] || continue
    echo "fuzz: failing input $a (first byte: format 0 OFF / 1 OBJ / 2 PLY; second: seed), base64:"
    base64 "$a"
  done
  echo "fuzz: FAILED (exit $status)"
  exit "$status"
fi
echo "fuzz: built in $(( built - start )) s, fuzzed $(( $(date +%s) - built )) s (cap $seconds s), $(ls "$work/corpus" | wc -l) new corpus inputs, no failure"
rm -rf "$work"
