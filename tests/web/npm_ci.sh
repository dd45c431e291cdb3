#!/bin/sh
# Installs tests/web's npm packages (package-lock.json, exactly) unless node_modules already
# holds them; skipped (77) where npm is not installed.
cd "$(dirname "$0")" || exit 1
if ! command -v npm >/dev/null 2>&1; then
  echo "skipped: npm is not installed (scripts/install-deps.sh installs it)"
  exit 77
fi
if [ node_modules/.package-lock.json -nt package-lock.json ]; then
  echo "npm packages present"
  exit 0
fi
exec npm ci --no-audit --no-fund
