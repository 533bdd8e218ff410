#!/usr/bin/env bash
# Renders every shipped scene small and prints one line per scene: the SHA-256 of its raw accumulation
# (--partial, docs/PARTIAL_FORMAT.md), so a refactor can show that it changes no image, bit for bit.
#   scripts/identical_images.sh [TRAZO] > before.txt   (then, after the change)   ... | diff before.txt -
# Size and passes are small on purpose: every kernel variant a scene uses still runs (--spp 3 crosses the halves).
set -euo pipefail
trazo=${1:-build/app/trazo}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for scene in "$root"/scenes/*.scene; do
  name=$(basename "$scene" .scene)
  "$trazo" --render "$scene" --backend cpu --width 64 --height 48 --spp 3 --seed 7 --quiet \
           --partial "$work/$name.part" >/dev/null
  # Only the accumulation is compared: the header holds the render time, and the file's last 8 bytes hash it.
  bytes=$(grep -a -m1 '^data-bytes: ' "$work/$name.part" | cut -d' ' -f2)
  echo "$name $(tail -c $((bytes + 8)) "$work/$name.part" | head -c "$bytes" | sha256sum | cut -c1-16)"
done
