#!/usr/bin/env bash
# boreas tests: lsan_retry.sh reruns a test only when LeakSanitizer's tracer crashed, once,
# and passes every other outcome on (a real leak report, another failure, success).
#   lsan_retry_test.sh PATH/TO/lsan_retry.sh
set -u
retry=$1
dir=$(mktemp -d) && trap 'rm -rf "$dir"' EXIT
failures=0
# A fake test: appends a line to $dir/runs each time it runs, then acts out its script
# line by line, one line per run (the last line repeats).
fake() {  # fake NAME 'run 1 action' ['run 2 action' ...]
  local name=$1
  shift
  printf '%s\n' "$@" >"$dir/$name.script"
  cat >"$dir/$name" <<SCRIPT
#!/usr/bin/env bash
echo x >>"$dir/$name.runs"
n=\$(wc -l <"$dir/$name.runs")
line=\$(sed -n "\${n}p" "$dir/$name.script")
[ -z "\$line" ] && line=\$(tail -n 1 "$dir/$name.script")
eval "\$line"
SCRIPT
  chmod +x "$dir/$name"
}
expect() {  # expect NAME STATUS RUNS
  local name=$1 want_rc=$2 want_runs=$3
  "$retry" "$dir/$name" >"$dir/$name.out" 2>&1
  local rc=$? runs
  runs=$(wc -l <"$dir/$name.runs")
  if [ "$rc" -ne "$want_rc" ] || [ "$runs" -ne "$want_runs" ]; then
    echo "FAIL $name: exit $rc after $runs runs, expected exit $want_rc after $want_runs"
    cat "$dir/$name.out"
    failures=$((failures + 1))
  else
    echo "ok   $name: exit $rc after $runs runs"
  fi
}
crash='echo "Tracer caught signal 11: addr=0x0 pc=0x1 sp=0x2"; echo "==7==LeakSanitizer has encountered a fatal error."; exit 1'
leak='echo "==7==ERROR: LeakSanitizer: detected memory leaks"; echo "Tracer caught signal 11"; echo "==7==LeakSanitizer has encountered a fatal error."; exit 1'
fake passes 'echo "[  PASSED  ] 1 test."; exit 0'
fake crash_then_passes "$crash" 'exit 0'
fake crashes_twice "$crash"
fake leaks "$leak"
fake fails 'echo "[  FAILED  ] 1 test"; exit 3'
expect passes 0 1
expect crash_then_passes 0 2
expect crashes_twice 1 2
expect leaks 1 1
expect fails 3 1
grep -q "running the test once more" "$dir/crash_then_passes.out" ||
  { echo "FAIL crash_then_passes: the rerun is not announced"; failures=$((failures + 1)); }
exit $((failures > 0))
