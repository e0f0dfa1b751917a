#!/bin/sh
# Disk-full regression test (issue 15): the Taylor bar with a SIGUSR1 restart dump at cycle
# 1000, its output folder on a full device, at sizes where the plot file, the restart dump and
# the time histories fail in turn. Each run must end with exit 4 and a message naming a file in
# the output folder and the OS reason, no crash; what is left must be readable: glstat and
# nodout whole lines without NUL bytes, d3plot.xdmf well-formed XML and not empty, d3plot.h5
# (when there) an HDF5 file, no d3plot.xdmf renamed over by a failed write.
# As root: a size-limited tmpfs per size (mount -t tmpfs -o size=...); otherwise (or when the
# mount is refused) a file-size limit (ulimit -f, SIGXFSZ ignored so write(2) fails with
# EFBIG). Prints PASS/FAIL per size; exits 1 on any failure.
#   scripts/diskfull_check.sh [DYNX]
set -u
cd "$(dirname "$0")/.." || exit 2
DYNX=${1:-bin/dynx}
DECK=decks/taylor_bar/deck.k
work=build/diskfull
umount "$work/mnt" 2>/dev/null     # left mounted by an interrupted earlier run
rm -rf "$work"
mkdir -p "$work"
mode=ulimit
force=${DISKFULL_MODE:-}
if [ -z "$force" ] && [ "$(id -u)" = 0 ] && command -v mount >/dev/null 2>&1; then
    mkdir -p "$work/mnt"
    if mount -t tmpfs -o size=64k tmpfs "$work/mnt" 2>/dev/null; then
        umount "$work/mnt"
        mode=tmpfs
    fi
fi
fail=0
for kb in 1200 2000 3000; do
    out=$work/out_$kb
    if [ $mode = tmpfs ]; then
        mount -t tmpfs -o size=${kb}k tmpfs "$work/mnt" || { echo "FAIL mount"; exit 1; }
        out=$work/mnt/out
    fi
    (
        if [ $mode = ulimit ]; then
            trap '' XFSZ
            ulimit -f $((kb / 3 * 2))     # 512-byte blocks: a third of the tmpfs size
        fi
        exec "$DYNX" -i $DECK -o "$out" --raise-at-cycle 1000:USR1
    ) > "$work/stdout_$kb" 2> "$work/stderr_$kb"
    rc=$?
    why=""
    [ $rc -eq 4 ] || why="$why exit $rc (want 4);"
    grep -q -e 'No space left on device' -e 'File too large' "$work/stderr_$kb" ||
        why="$why no OS reason in the message;"
    grep -q "dynx: error: .*$out/" "$work/stderr_$kb" || why="$why the message names no file;"
    for f in glstat nodout; do
        [ -f "$out/$f" ] || continue
        if [ "$(tr -d '\000' < "$out/$f" | wc -c)" -ne "$(wc -c < "$out/$f")" ]; then
            why="$why NUL bytes in $f;"
        fi
        if [ -s "$out/$f" ] && [ "$(tail -c 1 "$out/$f" | od -An -c | tr -d ' ')" != '\n' ]; then
            why="$why $f ends in a partial line;"
        fi
    done
    if [ -f "$out/d3plot.xdmf" ]; then
        python3 -c "import sys, xml.dom.minidom as m; m.parse(sys.argv[1])" \
            "$out/d3plot.xdmf" 2>/dev/null || why="$why d3plot.xdmf is not well-formed XML;"
    fi
    if [ -f "$out/d3plot.h5" ] && command -v h5ls >/dev/null 2>&1; then
        h5ls "$out/d3plot.h5" >/dev/null 2>&1 || why="$why d3plot.h5 unreadable;"
    fi
    if [ -n "$why" ]; then
        echo "FAIL diskfull $kb KiB ($mode):$why"
        sed 's/^/    /' "$work/stderr_$kb" | grep -v '^ *[0-9]' | head -8
        fail=1
    else
        echo "PASS diskfull $kb KiB ($mode): $(grep 'dynx: error' "$work/stderr_$kb" | cut -c1-90)"
    fi
    if [ $mode = tmpfs ]; then
        rm -rf "$work/keep_$kb"
        cp -a "$out" "$work/keep_$kb" 2>/dev/null
        umount "$work/mnt"
    fi
done
exit $fail
