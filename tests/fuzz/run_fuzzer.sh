#!/bin/sh
# Runs one libFuzzer harness for a bounded time.
#   run_fuzzer.sh FUZZER SEED_CORPUS WORK_DIR SECONDS
# New inputs go to WORK_DIR/corpus (the committed seeds stay untouched), a
# crashing input to WORK_DIR/crash-*; commit such a file to
# tests/fuzz/regressions/<harness>/ so that `make test` replays it. An input
# may take 120 s: the sanitizers make the remesher 5 to 10 times slower, and
# a loaded machine slower still; a hang still ends the run.
set -eu
fuzzer=$1 seeds=$2 work=$3 seconds=$4
mkdir -p "$work/corpus"
"$fuzzer" -max_total_time="$seconds" -timeout=120 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$work/" "$work/corpus" "$seeds" >"$work/log" 2>&1 || {
  tail -n 60 "$work/log"
  echo "$(basename "$fuzzer"): failed; the input is in $work/crash-* (see $work/log)"
  exit 1
}
runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log")
echo "$(basename "$fuzzer"): $runs executions in $seconds s, corpus $(ls "$work/corpus" | wc -l) inputs"
