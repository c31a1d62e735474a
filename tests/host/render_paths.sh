#!/bin/sh
# SPDX-License-Identifier: MIT
# zline-render's output paths (issue 16): outputs are compared with the model
# and with each other by device and inode, not by spelling, and an existing
# output that is not a regular file (FIFO, device) is refused, never replaced.
#   render_paths.sh ZLINE_RENDER WORK_DIR
# Each case prints "ok" or "FAIL"; the exit status is the number of failures.
set -u
render=$1
dir=$2
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > m.obj
cp m.obj m.orig
fails=0
ok() { echo "ok   $1"; }
bad() { echo "FAIL $1"; fails=$((fails + 1)); }

# refused CASE EXPECTED-MESSAGE ARGS...: exit 2, the message, the model intact
refused() {
    name=$1 msg=$2; shift 2
    "$render" --size 16x12 "$@" > out.txt 2> err.txt
    rc=$?
    if [ "$rc" -ne 2 ]; then bad "$name: exit $rc, expected 2"; return; fi
    if ! grep -q "$msg" err.txt; then bad "$name: stderr lacks '$msg': $(cat err.txt)"; return; fi
    if ! cmp -s m.obj m.orig; then bad "$name: the model was changed"; cp m.orig m.obj; return; fi
    ok "$name"
}

refused "model as output, ./ spelling" "over the model file" m.obj ./m.obj
refused "model as output, absolute path" "over the model file" m.obj "$PWD/m.obj"
refused "model as depth output" "over the model file" --depth "$PWD/./m.obj" m.obj img.ppm
ln m.obj hard.obj && refused "model as output through a hard link" "over the model file" m.obj hard.obj
ln -s m.obj soft.obj && refused "model as output through a symbolic link" "over the model file" m.obj soft.obj
refused "depth equal to the image, new file, two spellings" "different files" --depth ./new.ppm m.obj new.ppm
: > old.ppm
refused "depth equal to the image, existing file" "different files" --depth "$PWD/old.ppm" m.obj old.ppm
[ ! -e new.ppm ] && ok "nothing written when refused" || bad "new.ppm written although refused"

# A FIFO and a device node are refused and stay what they are.
if mkfifo fifo 2>/dev/null; then
    refused "FIFO output" "not a regular file" m.obj fifo
    [ -p fifo ] && ok "the FIFO is still a FIFO" || bad "the FIFO was replaced"
    refused "FIFO depth output" "not a regular file" --depth fifo m.obj img.ppm
fi
if [ -c /dev/null ] && [ -w /dev/null ]; then
    refused "device output" "not a regular file" m.obj /dev/null
    [ -c /dev/null ] && ok "/dev/null is still a device" || bad "/dev/null was replaced"
fi
mkdir sub
refused "directory output" "not a regular file" m.obj sub

# Different files render: an existing regular output is replaced.
if "$render" --size 16x12 --depth d.pgm m.obj old.ppm 2> err.txt && [ -s old.ppm ] && [ -s d.pgm ]; then
    ok "distinct outputs render"
else
    bad "distinct outputs: $(cat err.txt)"
fi
echo "render_paths: $fails failed"
exit "$fails"
