#!/usr/bin/env bash
# Writes scenes/assets/bunny.obj from the npm package `bunny` (the Stanford bunny); a no-op when up to date.
# Needs node and npm (Node 20) and the npm registry; nothing else is downloaded.
set -euo pipefail
assets="$(cd "$(dirname "$0")/../scenes/assets" && pwd)"
out="$assets/bunny.obj"

if [ -f "$out" ] && [ "$out" -nt "$assets/make_bunny.mjs" ] && [ "$out" -nt "$0" ]; then
  exit 0
fi
for tool in node npm; do
  if ! command -v "$tool" >/dev/null; then
    echo "make_bunny: '$tool' not found; install Node.js 20 (node + npm) to build $out" >&2
    exit 1
  fi
done

# A throw-away prefix keeps node_modules and any package.json out of the source tree.
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
npm install --no-save --no-package-lock --no-audit --no-fund --loglevel=error --prefix "$tmp" bunny@1.0.1 >&2
node "$assets/make_bunny.mjs" "$tmp/node_modules/bunny" "$out"
