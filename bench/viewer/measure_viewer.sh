#!/usr/bin/env bash
# Measures the viewer under Xvfb (not a test): opens SCENE at W×H, lets it render for SETTLE seconds, then orbits
# with a continuous left drag for DRAG seconds (xdotool, a move every 10 ms), waits, and closes with Ctrl+Q. The
# viewer's closing line gives the time to the first image (a preview) and to the first full-size image, the
# frame rate while input arrived, and the passes per second.
# Usage: bench/viewer/measure_viewer.sh TRAZO [SCENE] [W] [H] [BACKEND] [SETTLE] [DRAG]
set -eu
repo=$(cd "$(dirname "$0")/../.." && pwd)
trazo=$(realpath "$1")
scene=$(realpath "${2:-$repo/scenes/scene1_area.scene}")
width=${3:-1280}
height=${4:-720}
backend=${5:-cpu}
settle=${6:-6}
drag=${7:-3}
if [ -z "${TRAZO_INSIDE_XVFB:-}" ]; then
    TRAZO_INSIDE_XVFB=1 exec xvfb-run -a -s "-screen 0 $((width + 64))x$((height + 64))x24" bash "$0" "$@"
fi
log=$(mktemp)
"$trazo" "$scene" --backend "$backend" --width "$width" --height "$height" 2>"$log" &
pid=$!
wid=$(timeout 30 xdotool search --sync --onlyvisible --name '^trazo' | head -n 1)
xdotool windowfocus --sync "$wid"
sleep "$settle"
x=$((width * 3 / 4)); y=$((height / 2))
# One xdotool process for the whole drag: a move every 10 ms (the viewer's frames, not process start-ups,
# set the pace).
moves=()
for i in $(seq $((drag * 100))); do
    moves+=(mousemove --window "$wid" $((x + (i % 200) - 100)) $((y + (i % 50) - 25)) sleep 0.01)
done
xdotool mousemove --window "$wid" $x $y mousedown 1 "${moves[@]}" mouseup 1
sleep "$settle"
xdotool key --clearmodifiers ctrl+q
wait "$pid"
cat "$log"
rm -f "$log"
