#!/usr/bin/env bash
# The folders of renderer/ include only folders to their left (docs/ARCHITECTURE.md, "Folders and include
# order"): core, io → shading, geometry, accel → lights → objects → scene → flatten → integrator → backends → render;
# image sits on core and io only. Tests (*_test.cpp) aside. And ui/model/ (trazo_ui_model, no window) includes
# nothing from ui/view/, its tests included: trazo_tests builds them without the viewer. Prints each include
# that breaks the order.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
cd "$repo/renderer"
rank() {
    case $1 in
        core | io) echo 0 ;;
        shading | geometry | accel) echo 1 ;;
        lights) echo 2 ;;
        objects) echo 3 ;;
        scene) echo 4 ;;
        flatten) echo 5 ;;
        integrator) echo 6 ;;
        backends) echo 7 ;;
        render) echo 8 ;;
        image) echo 1 ;;  # on core and io only (below); render/ and the app write images
        *) echo 99 ;;
    esac
}
bad=0
while IFS= read -r line; do
    file=${line%%:*}
    from=${file%%/*}
    to=$(sed -E 's/.*#include "([a-z_]+)\/.*/\1/' <<<"${line#*:}")
    [ "$from" = "$to" ] && continue
    [ -d "$to" ] || continue  # a header beside the file, or a generated one
    allowed=1
    if [ "$from" = image ]; then
        case $to in core | io) ;; *) allowed=0 ;; esac
    elif [ "$(rank "$to")" -ge "$(rank "$from")" ]; then
        allowed=0  # to its right, or beside it (core and io, or shading, geometry and accel, stay apart)
    fi
    if [ $allowed = 0 ]; then
        echo "renderer/$file: includes $to/ (to the right of $from/ in the include order)"
        bad=1
    fi
done < <(grep -rn --include='*.h' --include='*.cpp' --include='*.cuh' --include='*.cu' -E '^#include "[a-z_]+/' . \
             | sed 's|^\./||' | grep -v '_test\.cpp:' | sed -E 's/^([^:]+):[0-9]+:/\1:/')
while IFS= read -r file; do
    echo "ui/$file: includes view/ (the model must not depend on the view)"
    bad=1
done < <(cd "$repo/ui" && grep -rl --include='*.h' --include='*.cpp' -E '^#include "view/' model || true)
if [ $bad = 0 ]; then
    echo "include order: every renderer/ folder includes only folders to its left; ui/model/ includes nothing from ui/view/"
fi
exit $bad
