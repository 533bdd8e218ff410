# The Xvfb viewer tests' common start (sourced by tests/viewer_*_test.sh): the tools they need (status 77,
# CTest's skip, naming the first one missing), the test run again inside xvfb-run on an 800x600 screen under a
# time limit, then a work folder removed at exit with the viewer ($pid, when set) stopped; fail(), which
# shows the viewer's log ($work/viewer.log), and xvfb_viewer_quit.
# Usage: xvfb_viewer_start SECONDS "INSTALL HINT" TOOL... -- "$0" "$@"

xvfb_viewer_start() {
    local seconds=$1 hint=$2
    shift 2
    local tools=(xvfb-run xauth Xvfb)
    while [ "$1" != -- ]; do
        tools+=("$1")
        shift
    done
    shift
    if [ -z "${TRAZO_INSIDE_XVFB:-}" ]; then
        for tool in "${tools[@]}"; do
            if ! command -v "$tool" >/dev/null 2>&1; then
                echo "SKIP: $tool is not installed ($hint)"
                exit 77
            fi
        done
        TRAZO_INSIDE_XVFB=1 exec timeout "$seconds" xvfb-run -a -s "-screen 0 800x600x24" bash "$@"
    fi
    work=$(mktemp -d)
    pid=
    trap xvfb_viewer_cleanup EXIT
}

xvfb_viewer_cleanup() {
    [ -n "$pid" ] && kill "$pid" 2>/dev/null
    rm -rf "$work"
}

fail() {
    echo "FAIL: $*"
    echo "--- viewer log"; cat "$work/viewer.log" 2>/dev/null
    exit 1
}

# Ctrl+Q to the viewer ($pid): it must exit, with status 0, within 10 s.
xvfb_viewer_quit() {
    xdotool key --clearmodifiers ctrl+q 2>/dev/null
    for _ in $(seq 100); do
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
    done
    kill -0 "$pid" 2>/dev/null && fail "Ctrl+Q did not close the viewer within 10 s"
    wait "$pid"
    local status=$?
    pid=
    [ $status -eq 0 ] || fail "the viewer exited with $status"
}
