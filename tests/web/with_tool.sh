#!/bin/sh
# Runs the rest of the command line if the tool named first is installed; otherwise says so
# and exits 77, which CTest counts as skipped (SKIP_RETURN_CODE).
tool="$1"
shift
if ! command -v "$tool" >/dev/null 2>&1; then
  echo "skipped: $tool is not installed (scripts/install-deps.sh installs it)"
  exit 77
fi
exec "$@"
