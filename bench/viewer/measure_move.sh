#!/usr/bin/env bash
# Time from a G move of an object to the first preview showing it, at 512x512 on the CPU, under Xvfb with real
# input: click a sphere of scene 1, G, 20 mouse steps 0.1 s apart, a click; then Ctrl+Z and Ctrl+Q. Prints the
# viewer's closing line ("object moves shown after A ms on average (worst W ms, N images)").
# Usage: bench/viewer/measure_move.sh TRAZO [SCENE]
set -u
repo=$(cd "$(dirname "$0")/../.." && pwd)
trazo=$(realpath "$1")
scene=$(realpath "${2:-$repo/scenes/scene1_area.scene}")
if [ -z "${TRAZO_INSIDE_XVFB:-}" ]; then
    TRAZO_INSIDE_XVFB=1 exec timeout 120 xvfb-run -a -s "-screen 0 1280x800x24" bash "$0" "$@"
fi
log=$(mktemp)
"$trazo" "$scene" --backend cpu --width 512 --height 512 >"$log" 2>&1 &
pid=$!
wid=$(timeout 30 xdotool search --sync --onlyvisible --name '^trazo' | head -n 1)
xdotool windowfocus --sync "$wid"
sleep 3
xdotool key 1 sleep 0.5  # 1:1: the image's pixel (256, 256) at a known place
geometry=$(xdotool getwindowgeometry "$wid" | sed -n 's/.*Geometry: \([0-9]*\)x\([0-9]*\)/\1 \2/p')
read -r w h <<<"$geometry"
# The image area is right of the 380-wide panel, below the menu bar (19); 1:1 centres the image in it.
cx=$((380 + (w - 380) / 2)); cy=$((19 + (h - 19) / 2))
xdotool mousemove --window "$wid" "$cx" $((cy + 40)) sleep 0.3 click 1 sleep 1
xdotool key g
for step in $(seq 1 20); do
    xdotool mousemove --window "$wid" $((cx + 3 * step)) $((cy + 40 - step)) sleep 0.1
done
xdotool click 1 sleep 0.5 key ctrl+z sleep 0.5 key ctrl+q
wait "$pid"
grep -E "selected|moved|^trazo: viewer [0-9]" "$log"
rm -f "$log"
