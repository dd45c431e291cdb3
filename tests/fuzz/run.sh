#!/usr/bin/env bash
# boreas fuzzing: runs every harness of tests/fuzz (built by `make fuzz` into build-fuzz)
# for FUZZ_SECONDS each (default 60), from seed corpora of the project's own files, and
# prints a table of executions, coverage and findings (also written to
# build-fuzz/fuzz/results.md). A finding's input is kept in build-fuzz/fuzz/findings/NAME/;
# the exit status is 1 when any harness found something.
#   tests/fuzz/run.sh [build folder] [harness ...]
set -uo pipefail
SRC=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
BUILD=$(cd "${1:-$SRC/build-fuzz}" && pwd)
shift || true
SECONDS_EACH=${FUZZ_SECONDS:-60}
ALL=(species_json species_growth arbaro_xml underbrush_species obj gltf scene_json tree_cache
     command_line)
NAMES=("$@")
[ ${#NAMES[@]} -eq 0 ] && NAMES=("${ALL[@]}")

seeds() {  # the seed files of a harness: the project's own files, and tests/fuzz/corpus/NAME
  case $1 in
    species_json | species_growth) ls "$SRC"/host/species/*.json ;;
    arbaro_xml) ls "$SRC"/tests/data/arbaro/*.xml ;;
    underbrush_species) ls "$SRC"/host/species/underbrush/*.json ;;
    scene_json) ls "$SRC"/render/scenes/*.json ;;
  esac
  [ -d "$SRC/tests/fuzz/corpus/$1" ] && ls "$SRC"/tests/fuzz/corpus/"$1"/*
  return 0
}

dict() {  # the dictionary of a harness: dict/NAME.dict, or the one of the format it reads
  case $1 in
    species_growth) echo "$SRC/tests/fuzz/dict/species_json.dict" ;;
    *) echo "$SRC/tests/fuzz/dict/$1.dict" ;;
  esac
}

OUT=$BUILD/fuzz
mkdir -p "$OUT"
mkdir -p "$OUT/rows"
status=0
for name in "${NAMES[@]}"; do
  exe=$BUILD/tests/fuzz/fuzz_$name
  [ -x "$exe" ] || { echo "run.sh: $exe is not built (make fuzz)" >&2; exit 2; }
  corpus=$OUT/corpus/$name findings=$OUT/findings/$name log=$OUT/$name.log
  mkdir -p "$corpus" "$findings"
  seeds "$name" | while read -r f; do cp -n "$f" "$corpus/" 2>/dev/null || true; done
  echo "fuzz_$name: ${SECONDS_EACH} s ..."
  # -timeout: an input that takes over 1 s is a finding; -malloc_limit_mb: so is one that
  # makes boreas ask for more than 1 GiB at once; -rss_limit_mb: or hold over 2 GiB.
  "$exe" -max_total_time="$SECONDS_EACH" -timeout=1 -malloc_limit_mb=1024 -rss_limit_mb=2048 \
    -dict="$(dict "$name")" -artifact_prefix="$findings/" -print_final_stats=1 \
    "$corpus" >"$log" 2>&1
  rc=$?
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  secs=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*')
  units=$(ls "$corpus" | wc -l)
  found=$(ls "$findings" | wc -l)
  if [ $rc -ne 0 ] || [ "$found" -gt 0 ]; then
    status=1
    found="$found (exit $rc; see $log)"
  fi
  echo "| fuzz_$name | $SECONDS_EACH | ${runs:-?} | ${secs:-?} | ${cov:-?} | $units | $found |" \
    >"$OUT/rows/$name"
done
# Every harness run so far (several run.sh may run side by side, each with some harnesses).
{
  echo "| harness | seconds | executions | exec/s | coverage (edges) | corpus | findings |"
  echo "|---|---|---|---|---|---|---|"
  for name in "${ALL[@]}"; do [ -f "$OUT/rows/$name" ] && cat "$OUT/rows/$name"; done
} | tee "$OUT/results.md"
exit $status
