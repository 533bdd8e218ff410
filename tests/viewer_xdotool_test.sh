#!/usr/bin/env bash
# A scripted viewer session under Xvfb with real X input (xdotool): open a small scene, press P (screenshot),
# drag with the left button over the image (orbit), press P again. Passes when both screenshots were written
# and differ (the orbit moved the camera), Ctrl+S writes the edited scene beside the scene (a copy in the work
# folder) and it reads back, and Ctrl+Q closes the viewer with status 0.
# Usage: viewer_xdotool_test.sh TRAZO SCENES_DIR. Exit 77 (CTest SKIP_RETURN_CODE) without xvfb-run/xdotool.
set -u
trazo=$(realpath "$1")
scenes=$(realpath "$2")
# shellcheck source=support/xvfb_viewer.sh
source "$(dirname "$0")/support/xvfb_viewer.sh"
xvfb_viewer_start 150 "apt-get install xvfb xauth xdotool; scripts/setup.sh does" xdotool cmp -- "$0" "$@"
count_shots() { ls "$work"/trazo-*.png 2>/dev/null | wc -l; }
wait_for_shots() {  # up to 20 s for $1 screenshots
    for _ in $(seq 200); do
        [ "$(count_shots)" -ge "$1" ] && return 0
        sleep 0.1
    done
    return 1
}
press_p_for_shot() {  # presses P until screenshot number $1 exists (a key lost before focus is pressed again)
    for _ in 1 2 3; do
        xdotool key --clearmodifiers p
        wait_for_shots "$1" && return 0
    done
    return 1
}

cd "$work"
cp "$scenes/scene1_area.scene" "$work/scene1_area.scene"  # self-contained: Ctrl+S writes beside it, here
# 160x120 renders fast; the window opens at 640x480 (the image scaled) with the panel on its left third.
"$trazo" "$work/scene1_area.scene" --backend cpu --width 160 --height 120 --blocks 1 >"$work/viewer.log" 2>&1 &
pid=$!
wid=$(timeout 30 xdotool search --sync --onlyvisible --name '^trazo' | head -n 1)
[ -n "$wid" ] || fail "the viewer window did not appear within 30 s"
timeout 10 xdotool windowfocus --sync "$wid" || fail "could not focus the window"
sleep 0.5

press_p_for_shot 1 || fail "the first screenshot (key P) was not written"

# Orbit: left drag across the image, away from the panel (right part of the window), in small steps.
xdotool mousemove --window "$wid" 520 240 sleep 0.2 mousedown 1 sleep 0.1
for step in $(seq 1 10); do
    xdotool mousemove --window "$wid" $((520 + 8 * step)) $((240 + 2 * step)) sleep 0.03
done
xdotool mouseup 1 sleep 0.2
press_p_for_shot 2 || fail "the second screenshot (key P after the drag) was not written"

[ "$(count_shots)" -eq 2 ] || fail "expected 2 screenshots, found $(count_shots)"
# In the order taken, with their pass counts, from the viewer's "saved NAME (N passes)" lines.
mapfile -t shots < <(sed -n 's/^trazo: saved \(trazo-[^ ]*\.png\) ([0-9]* passes)$/\1/p' "$work/viewer.log")
mapfile -t passes < <(sed -n 's/^trazo: saved trazo-[^ ]*\.png (\([0-9]*\) passes)$/\1/p' "$work/viewer.log")
[ "${#shots[@]}" -eq 2 ] && [ "${#passes[@]}" -eq 2 ] || fail "expected 2 'saved' lines in the log"
if cmp -s "${shots[0]}" "${shots[1]}"; then fail "the image did not change after the orbit drag"; fi
echo "ok: two screenshots written and different: ${shots[*]}"
# The screenshots hold different pass counts, so "different" alone proves little: the first must equal the file
# camera's headless render at its pass count, the second must not (the orbit moved the camera).
for i in 0 1; do
    "$trazo" --render "$scenes/scene1_area.scene" --backend cpu --width 160 --height 120 --spp "${passes[$i]}" --blocks 1 \
        -o "$work/headless$i.png" --quiet || fail "headless render failed"
done
cmp -s "${shots[0]}" "$work/headless0.png" || fail "the first screenshot differs from --render --spp ${passes[0]}"
cmp -s "${shots[1]}" "$work/headless1.png" && fail "the second screenshot still shows the file's camera"
echo "ok: screenshot 1 == headless render of the file camera; screenshot 2 (after the orbit) is not"

edited="$work/scene1_area-edited.scene"
for _ in 1 2 3; do  # a key lost before focus is pressed again
    xdotool key --clearmodifiers ctrl+s
    for _ in $(seq 50); do [ -f "$edited" ] && break; sleep 0.1; done
    [ -f "$edited" ] && break
done
[ -f "$edited" ] || fail "Ctrl+S did not write $edited"
grep -q "^trazo: saved scene $edited\$" "$work/viewer.log" || fail "no 'saved scene' line for Ctrl+S"
"$trazo" --render "$edited" --backend cpu --width 16 --height 12 --spp 1 -o "$work/edited.png" --quiet ||
    fail "the scene Ctrl+S wrote does not render"
echo "ok: Ctrl+S wrote the edited scene and it renders"

xvfb_viewer_quit
echo "ok: Ctrl+Q closed the viewer"
cat "$work/viewer.log"
