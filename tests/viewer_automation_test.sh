#!/usr/bin/env bash
# Viewer automation under Xvfb (CTest): `trazo SCENE --frames N --screenshot FILE` in a real window saves the
# same image as `trazo --render SCENE --spp N` with the same seed (PNG bytes and PFM floats compared), and
# without a display `trazo SCENE` says so in one line, suggests --render and exits 1.
# Usage: viewer_automation_test.sh TRAZO SCENES_DIR. Exit 77 (CTest SKIP_RETURN_CODE) without xvfb-run/xauth.
set -u
trazo=$(realpath "$1")
scenes=$(realpath "$2")
for tool in xvfb-run xauth Xvfb cmp; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        echo "SKIP: $tool is not installed (apt-get install xvfb xauth; scripts/setup.sh does)"
        exit 77
    fi
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# Area light + glossy walls (scene 1) and a refracting sphere (scene 7); 11 passes cross half-block boundaries.
for scene in scene1_area scene7_refract; do
    for ext in png pfm; do
        args=(--backend cpu --width 48 --height 32 --seed 11)
        timeout 120 xvfb-run -a -s "-screen 0 640x480x24" \
            "$trazo" "$scenes/$scene.scene" "${args[@]}" --frames 11 --screenshot "$work/viewer.$ext" \
            >"$work/viewer.log" 2>&1
        status=$?
        [ $status -eq 0 ] || { cat "$work/viewer.log"; fail "$scene: the viewer exited with $status"; }
        "$trazo" --render "$scenes/$scene.scene" "${args[@]}" --spp 11 --blocks 1 -o "$work/headless.$ext" --quiet \
            || fail "$scene: the headless render failed"
        cmp "$work/viewer.$ext" "$work/headless.$ext" || fail "$scene: the viewer's .$ext differs from --render's"
        echo "ok: $scene .$ext: viewer screenshot == headless render"
    done
done

# SPEC §7 Image: scene 1 path-traced at Exposure 1.5 (sRGB, the path integrator's default view): the screenshot
# stores 2^1.5 × the pixel through the view, as --render does.
sed '0,/^{/s//{\n    Integrator path\n    Exposure 1.5/' "$scenes/scene1_area.scene" >"$work/exposed.scene"
for ext in png pfm; do
    args=(--backend cpu --width 48 --height 32 --seed 11)
    timeout 120 xvfb-run -a -s "-screen 0 640x480x24" \
        "$trazo" "$work/exposed.scene" "${args[@]}" --frames 5 --screenshot "$work/viewer.$ext" >"$work/viewer.log" 2>&1 \
        || { cat "$work/viewer.log"; fail "exposed: the viewer failed"; }
    "$trazo" --render "$work/exposed.scene" "${args[@]}" --spp 5 --blocks 1 -o "$work/headless.$ext" --quiet \
        || fail "exposed: the headless render failed"
    cmp "$work/viewer.$ext" "$work/headless.$ext" || fail "exposed: the viewer's .$ext differs from --render's"
    echo "ok: scene1_area path, Exposure 1.5 .$ext: viewer screenshot == headless render"
done

# No display: one line, a hint to --render, status 1, and no crash.
env -u DISPLAY -u WAYLAND_DISPLAY "$trazo" "$scenes/scene1_area.scene" >"$work/out.txt" 2>"$work/err.txt"
status=$?
[ $status -eq 1 ] || fail "without a display the viewer exited with $status, expected 1"
[ "$(wc -l <"$work/err.txt")" -eq 1 ] || { cat "$work/err.txt"; fail "expected exactly one line on stderr"; }
grep -q -- "--render" "$work/err.txt" || fail "the no-display message does not suggest --render"
echo "ok: no display: $(cat "$work/err.txt")"
