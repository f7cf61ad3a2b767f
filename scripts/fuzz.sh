#!/bin/sh
# Builds the libFuzzer targets in build-fuzz/ (clang, ASan + UBSan) and runs
# each for the given number of seconds (default 30), one after another.
# Each run first replays the committed seeds (tests/fuzz/corpus/<target>/)
# and fixed crash inputs (tests/fuzz/regressions/<target>/); what it finds
# new is kept in build-fuzz/corpus/<target>/, crashes in build-fuzz/artifacts/,
# logs with the executed-input counts in build-fuzz/logs/.
# MESHPAINT_FUZZ_TARGETS="fuzz_mesh_obj ..." runs only those targets.
# MESHPAINT_FUZZ_SEED=N fixes libFuzzer's random seed, so that a run from the
# same clean tree on the same machine mutates the same inputs in the same
# order (the test command does this; campaigns leave it unset to explore).
set -eu
seconds=${1:-30}
here=$(cd "$(dirname "$0")/.." && pwd)
build=${MESHPAINT_FUZZ_BUILD_DIR:-"$here/build-fuzz"}
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$here" -B "$build" -DMESHPAINT_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ >/dev/null
fi
targets=${MESHPAINT_FUZZ_TARGETS:-$(cat "$build/fuzz_targets.txt" 2>/dev/null || true)}
if [ -z "$targets" ]; then
  cmake --build "$build" -j"$(nproc)"
  targets=$(cat "$build/fuzz_targets.txt")
else
  cmake --build "$build" -j"$(nproc)" --target $targets
fi
mkdir -p "$build/artifacts" "$build/logs"
failed=0
for t in $targets; do
  mkdir -p "$build/corpus/$t"
  dirs="$build/corpus/$t"
  for d in "$here/tests/fuzz/corpus/$t" "$here/tests/fuzz/regressions/$t"; do
    [ -d "$d" ] && dirs="$dirs $d"
  done
  # VTK 9.1's XML reader leaks a few hundred bytes on some malformed arrays:
  # its leaks are not findings of ours; crashes, hangs and memory still are.
  leaks=""
  case $t in fuzz_polydata_*) leaks="-detect_leaks=0" ;; esac
  seed=""
  [ -n "${MESHPAINT_FUZZ_SEED:-}" ] && seed="-seed=$MESHPAINT_FUZZ_SEED"
  echo "fuzzing $t for $seconds s${seed:+ ($seed)}"
  # -timeout: one input taking longer is a hang; -rss_limit_mb: more is a finding.
  if ! "$build/tests/fuzz/$t" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 $leaks $seed \
       -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" $dirs \
       >"$build/logs/$t.log" 2>&1; then
    echo "$t: finding, see $build/logs/$t.log and $build/artifacts/" >&2
    tail -n 40 "$build/logs/$t.log" >&2
    failed=1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/logs/$t.log" | sed "s/^/  /" || true
done
exit $failed
