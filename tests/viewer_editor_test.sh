#!/usr/bin/env bash
# The viewer as a scene editor under Xvfb, with real X input (xdotool) and real screenshots of the window (xwd):
#  (b) at 1:1 the image area of a screenshot equals the headless render of the same passes, pixel for pixel,
#      right of the side panel (nothing drawn over it);
#  (a) a click on a known pixel selects the object the camera ray through it meets (two spheres, left and
#      right, their image positions in closed form), and a click on the background clears the selection;
#  (c) a G move then Ctrl+Z, and an Alt+drag then Ctrl+Z, save (Ctrl+S) a scene byte-identical to the one
#      saved before the move;
#  (d) duplicate (Shift+D, Enter) saves a third sphere at the first's centre, delete (X) brings back the first
#      save byte for byte, add (Shift+A) saves a sphere at the camera's POI; that file reopened (Ctrl+O, typed
#      path) and saved again is byte-identical;
#  (e) a malformed scene opened by its typed path (Ctrl+O: xdotool cannot drag a file between X clients, so the
#      drop callback is not driven here) leaves the viewer running, the file:line message on stderr; Ctrl+Q
#      then quits with status 0;
#  and an unsaved edit marks the title with *, keeps SCENE.recovery, makes Ctrl+Q ask (Escape cancels); its undo
#  removes both.
# Usage: viewer_editor_test.sh TRAZO. Exit 77 (CTest SKIP_RETURN_CODE) without xvfb-run/xdotool/xwd/python3.
set -u
trazo=$(realpath "$1")
# shellcheck source=support/xvfb_viewer.sh
source "$(dirname "$0")/support/xvfb_viewer.sh"
xvfb_viewer_start 170 "apt-get install xvfb xauth xdotool x11-apps python3" xdotool xwd python3 cmp -- "$0" "$@"
log_has() { grep -q -- "$1" "$work/viewer.log"; }
wait_log() {  # up to 20 s (or $3 tenths) for a line matching $1 (grep -E), counted from line $2 of the log on
    for _ in $(seq "${3:-200}"); do
        tail -n +"${2:-1}" "$work/viewer.log" | grep -Eq -- "$1" && return 0
        sleep 0.1
    done
    return 1
}
lines() { wc -l <"$work/viewer.log"; }
key() { xdotool key --clearmodifiers "$@"; sleep 0.3; }
click_at() {  # left click at window coordinates
    xdotool mousemove --window "$wid" "$1" "$2" sleep 0.2 click 1
    sleep 0.3
}
save() {  # Ctrl+S (again if the key was lost), then copies the saved scene to $1
    local from
    from=$(lines)
    for _ in 1 2 3; do
        key ctrl+s
        wait_log "^trazo: saved scene $edited\$" "$((from + 1))" 50 && { cp "$edited" "$1"; return 0; }
    done
    fail "Ctrl+S did not save the scene"
}
hold() {  # a key ImGui reads (not a viewer command), held across frames: ImGui 1.86 misses a press and release
    # that both come between two of its frames, as they do when frames are slow (the sanitized build under load).
    xdotool keydown "$1" sleep "${2:-0.3}" keyup "$1"
    sleep 0.3
}
open_path() {  # $1, expecting a log line matching $2: Ctrl+O focuses the Open panel's path field (all of it
    # selected), the path is typed over it, Enter opens. Keys typed before the field has the focus are lost, and
    # an Enter ImGui did not see leaves the field active: each is tried again, like a user would.
    local from
    from=$(lines)
    for _ in 1 2 3; do
        key ctrl+o
        sleep 0.7
        xdotool type --delay 20 "$1"
        sleep 0.2
        for hold_s in 0.3 0.8 1.5; do
            hold Return "$hold_s"
            wait_log "$2" "$((from + 1))" 60 && return 0
            [ "$(lines)" -gt "$from" ] && break  # Enter was seen (a wrong path's message): type it again
        done
    done
    return 1
}

# Python helpers: an XWD window dump and a 24-bit BMP as rows of RGB triples; the image searched for in the
# screenshot (every position, exact match).
cat >"$work/images.py" <<'EOF'
import struct, sys

def read_xwd(path):
    d = open(path, 'rb').read()
    f = struct.unpack('>25I', d[:100])
    header, ncolors, w, h, order, bpl = f[0], f[19], f[4], f[5], f[7], f[12]
    masks = f[14:17]
    shifts = [(m & -m).bit_length() - 1 for m in masks]
    off = header + 12 * ncolors
    rows = []
    for y in range(h):
        vals = struct.unpack(('<' if order == 0 else '>') + '%dI' % w, d[off + y * bpl: off + y * bpl + 4 * w])
        rows.append([tuple((v & m) >> s for m, s in zip(masks, shifts)) for v in vals])
    return rows

def read_bmp(path):
    d = open(path, 'rb').read()
    off = struct.unpack('<I', d[10:14])[0]
    w, h = struct.unpack('<ii', d[18:26])
    bpp = struct.unpack('<H', d[28:30])[0]
    step = bpp // 8
    stride = (w * step + 3) // 4 * 4
    rows = []
    for y in range(abs(h)):
        r = d[off + y * stride: off + y * stride + w * step]
        rows.append([(r[i * step + 2], r[i * step + 1], r[i * step]) for i in range(w)])
    return rows[::-1] if h > 0 else rows

def find(shot, image):
    H, W, h, w = len(shot), len(shot[0]), len(image), len(image[0])
    for y in range(H - h + 1):
        for x in range(W - w + 1):
            if shot[y][x:x + w] == image[0] and all(shot[y + j][x:x + w] == image[j] for j in range(1, h)):
                return x, y
    return None

if sys.argv[1] == 'find':  # find SHOT.xwd IMAGE.bmp: prints "x y" of the image in the screenshot
    at = find(read_xwd(sys.argv[2]), read_bmp(sys.argv[3]))
    print('%d %d' % at if at else 'none')
elif sys.argv[1] == 'same':  # same A.xwd B.xwd: exit 0 when the two dumps hold the same pixels
    sys.exit(0 if read_xwd(sys.argv[2]) == read_xwd(sys.argv[3]) else 1)
EOF

# Two spheres, left (line 24) and right (line 31), and a point light; 160x120 renders fast.
cat >"$work/two.scene" <<'EOF'
SceneSettings
{
    BackgroundColor 0.2 0.3 0.4
    RenderWidth 160
    RenderHeight 120
    ReflectionQuality 0
    IndirectQuality 0
    Antialiasing 1
}

Camera
{
    POV 0 0 10
    POI 0 0 0
    FOV 40
}

Material
{
    Name red
    DiffuseColor 0.9 0.2 0.1
}

Sphere
{
    Center -2 0 0
    Radius 1.2
    Material red
}

Sphere
{
    Center 2 0 0
    Radius 1.2
    Material red
}

PointLight
{
    Position 0 5 8
    Color 1 1 1
}
EOF
printf 'Sphere\n{\n    Center 0 0 0\n    Radius -1\n}\n' >"$work/bad.scene"
edited="$work/two-edited.scene"

cd "$work"
"$trazo" "$work/two.scene" --backend cpu --blocks 1 >"$work/viewer.log" 2>&1 &
pid=$!
wid=$(timeout 30 xdotool search --sync --onlyvisible --name '^trazo' | head -n 1)
[ -n "$wid" ] || fail "the viewer window did not appear within 30 s"
timeout 10 xdotool windowfocus --sync "$wid" || fail "could not focus the window"
sleep 0.5

# (b) 1:1, then wait until the image stops changing (the Render panel's default stop: 1024 passes).
key 1
xwd -id "$wid" -silent >"$work/a.xwd"
for _ in $(seq 60); do
    sleep 1
    xwd -id "$wid" -silent >"$work/b.xwd"
    python3 "$work/images.py" same "$work/a.xwd" "$work/b.xwd" && break
    mv "$work/b.xwd" "$work/a.xwd"
done
"$trazo" --render "$work/two.scene" --backend cpu --spp 1024 --blocks 1 -o "$work/headless.bmp" --quiet ||
    fail "the headless render failed"
read -r x0 y0 < <(python3 "$work/images.py" find "$work/a.xwd" "$work/headless.bmp")
[ "$x0" != none ] || fail "the headless render (1024 passes) is not in the window's screenshot at 1:1"
[ "$x0" -ge 300 ] || fail "the image is at x=$x0, over the side panel"
echo "ok: (b) at 1:1 the window shows the headless render pixel for pixel, at ($x0, $y0), right of the panel"

# (a) The spheres' centres (±2, 0, 0) seen from (0, 0, 10) with a 40° vertical FOV at 160x120 project to
# x = (1 ± 0.2 / (tan 20° · 4/3)) · 80, y = 60 (integrator/camera_frame.h's rays, solved for the pixel).
read -r left right < <(python3 -c "import math; s = 0.2 / (math.tan(math.radians(20)) * 4 / 3); print(int((1 - s) * 80), int((1 + s) * 80))")
from=$(lines)
click_at $((x0 + right)) $((y0 + 60))
wait_log "^trazo: selected Sphere 1 \(two.scene:31\)$" "$((from + 1))" || fail "a click on the right sphere did not select Sphere 1"
from=$(lines)
click_at $((x0 + 80)) $((y0 + 5))
wait_log "^trazo: selection cleared$" "$((from + 1))" || fail "a click on the background did not clear the selection"
from=$(lines)
click_at $((x0 + left)) $((y0 + 60))
wait_log "^trazo: selected Sphere 0 \(two.scene:24\)$" "$((from + 1))" || fail "a click on the left sphere did not select Sphere 0"
from=$(lines)
key Escape
wait_log "^trazo: selection cleared$" "$((from + 1))" || fail "Escape did not clear the selection"
from=$(lines)
click_at $((x0 + left)) $((y0 + 60))
wait_log "^trazo: selected Sphere 0 \(two.scene:24\)$" "$((from + 1))" || fail "a click on the left sphere did not select Sphere 0"
echo "ok: (a) clicks select the sphere under the cursor (the background and Escape clear the selection)"

# (c) A move by hand (G, the mouse, a left click), then Ctrl+Z: the saved scene is the one saved before.
save "$work/save0.scene"
xdotool mousemove --window "$wid" $((x0 + left)) $((y0 + 60))
sleep 0.2
key g
for step in $(seq 1 8); do
    xdotool mousemove --window "$wid" $((x0 + left + 4 * step)) $((y0 + 60 - 2 * step))
    sleep 0.05
done
from=$(lines)
xdotool click 1
wait_log "^trazo: moved Sphere 0 \(two.scene:24\) by " "$((from + 1))" || fail "the G move did not end with a click"
save "$work/moved.scene"
cmp -s "$work/save0.scene" "$work/moved.scene" && fail "the moved scene saved the same as before the move"
key ctrl+z
save "$work/undone.scene"
cmp "$work/save0.scene" "$work/undone.scene" || fail "move then undo does not save the scene saved before the move"
# The same with Alt+drag, which first selects the object under the cursor (the right sphere).
xdotool mousemove --window "$wid" $((x0 + right)) $((y0 + 60)) sleep 0.2 keydown alt mousedown 1 sleep 0.2
for step in $(seq 1 6); do
    xdotool mousemove --window "$wid" $((x0 + right - 3 * step)) $((y0 + 60 + step))
    sleep 0.05
done
from=$(lines)
xdotool mouseup 1 keyup alt
wait_log "^trazo: moved Sphere 1 \(two.scene:31\) by " "$((from + 1))" || fail "an Alt+drag did not move the right sphere"
key ctrl+z
save "$work/undone2.scene"
cmp "$work/save0.scene" "$work/undone2.scene" || fail "Alt+drag then undo does not save the scene saved before"
echo "ok: (c) move (G, and Alt+drag) → Ctrl+Z saves a byte-identical scene"

# (d) Duplicate in place (the selection: the right sphere, since the Alt+drag), delete, add; each saved and read
# back.
key shift+d
key Return
save "$work/duplicated.scene"
[ "$(grep -c '^Sphere' "$work/duplicated.scene")" -eq 3 ] || fail "Shift+D did not save a third sphere"
[ "$(grep -c 'Center 2 0 0' "$work/duplicated.scene")" -eq 2 ] || fail "the copy is not at the original's centre"
key x
save "$work/deleted.scene"
cmp "$work/save0.scene" "$work/deleted.scene" || fail "deleting the copy does not save the scene as before"
key shift+a
save "$work/added.scene"
[ "$(grep -c '^Sphere' "$work/added.scene")" -eq 3 ] || fail "Shift+A did not save a third sphere"
grep -A3 '^Sphere' "$work/added.scene" | grep -q 'Center 0 0 0' || fail "the added sphere is not at the POI"
cp "$work/added.scene" "$work/reload.scene"
open_path "$work/reload.scene" "^trazo: opened $work/reload.scene\$" ||
    fail "Ctrl+O and a typed path did not open the saved scene"
edited="$work/reload-edited.scene"
save "$work/resaved.scene"
cmp "$work/added.scene" "$work/resaved.scene" || fail "the reopened scene does not save as it was read"
echo "ok: (d) duplicate, delete and add round-trip through save and reload"

# (e) A malformed scene: the messages, the viewer still running with its scene.
from=$(lines)
open_path "$work/bad.scene" "^trazo: cannot open $work/bad.scene; the current scene stays\$" ||
    fail "opening a malformed scene did not say so"
tail -n +"$((from + 1))" "$work/viewer.log" | grep -q "^$work/bad.scene:4:.*error:" || fail "no file:line message"
kill -0 "$pid" 2>/dev/null || fail "the viewer did not survive a malformed scene"
echo "ok: (e) a malformed scene is refused with its file:line message; the viewer runs on"

# Unsaved edits: the title's mark, the recovery file beside the scene, Ctrl+Q asks (Escape: cancel); undone,
# the file goes and Ctrl+Q quits.
recovery="$work/reload.scene.recovery"
key shift+a
for _ in $(seq 50); do [ -f "$recovery" ] && break; sleep 0.1; done
[ -f "$recovery" ] || fail "no recovery file while there are unsaved edits"
case "$(xdotool getwindowname "$wid")" in *" *") ;; *) fail "the title does not mark unsaved edits" ;; esac
key ctrl+q
sleep 1
kill -0 "$pid" 2>/dev/null || fail "Ctrl+Q with unsaved edits quit without asking"
hold Escape
key ctrl+z
for _ in $(seq 50); do [ -f "$recovery" ] || break; sleep 0.1; done
[ -f "$recovery" ] && fail "the recovery file stayed after every edit was undone"
case "$(xdotool getwindowname "$wid")" in *" *") fail "the title still marks unsaved edits after the undo" ;; esac
echo "ok: unsaved edits mark the title, keep a recovery file and make Ctrl+Q ask; undone, neither"

xvfb_viewer_quit
ls "$work"/*.recovery >/dev/null 2>&1 && fail "a recovery file was left after a clean quit"
echo "ok: Ctrl+Q closed the viewer, no recovery file left"
grep "^trazo: viewer " "$work/viewer.log"
