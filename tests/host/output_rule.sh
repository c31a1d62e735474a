#!/bin/sh
# SPDX-License-Identifier: MIT
# The output rule of every host tool (port/host/zl_output.h; issues 16, 26),
# checked on each tool through its command line:
#   1. an output is never an input or another output: by device and inode,
#      through ./ and absolute spellings, hard and symbolic links, and for a
#      path that does not exist yet (a dangling link to the other output);
#   2. an existing FIFO, device or folder is refused and stays what it is;
#   3. a symbolic link as an output is written through (the link stays);
#   4. a read-only output is an error (also for root) and stays as it was;
#   5. a failure part-way leaves the previous files intact and no temporary
#      file behind (a write error made with `ulimit -f 0`); a replaced file
#      keeps its permission bits.
#   output_rule.sh ZLINE_RENDER ZLINE_IMG2C ZLINE_OBJ2C ZLINE_BSP WORK_DIR
# Each case prints "ok" or "FAIL"; the exit status is the number of failures.
set -u
render=$1 img2c=$2 obj2c=$3 bsp=$4 dir=$5
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n' > m.obj
printf 'P6\n2 2\n255\n\001\002\003\004\005\006\007\010\011\012\013\014' > t.ppm
printf 'P5\n2 2\n255\n\100\200\300\377' > a.pgm
for f in m.obj t.ppm a.pgm; do cp "$f" "$f.orig"; done
fails=0
ok() { echo "ok   $1"; }
bad() { echo "FAIL $1"; fails=$((fails + 1)); }
inputs_intact() {
    for f in m.obj t.ppm a.pgm; do cmp -s "$f" "$f.orig" || { cp "$f.orig" "$f"; return 1; }; done
}
no_temporaries() { ! ls | grep -q '\.tmp[0-9]'; }

# refused CASE EXPECTED-MESSAGE COMMAND...: exit 2, the message on stderr,
# the inputs unchanged, no temporary file left
refused() {
    name=$1 msg=$2; shift 2
    "$@" > out.txt 2> err.txt
    rc=$?
    if [ "$rc" -ne 2 ]; then bad "$name: exit $rc, expected 2 ($(cat err.txt))"; return; fi
    if ! grep -q "$msg" err.txt; then bad "$name: stderr lacks '$msg': $(cat err.txt)"; return; fi
    if ! inputs_intact; then bad "$name: an input was changed"; return; fi
    if ! no_temporaries; then bad "$name: a temporary file was left"; return; fi
    ok "$name"
}
R() { "$render" --size 16x12 "$@"; }
RT() { "$render" --size 16x12 --texture "$@"; }

# --- 1. outputs against inputs and each other ---------------------------------
over="refusing to write over the input"
one="are one file"
refused "render: model as output, ./ spelling" "$over" R m.obj ./m.obj
refused "render: model as output, absolute path" "$over" R m.obj "$PWD/m.obj"
refused "render: model as depth output" "$over" R --depth "$PWD/./m.obj" m.obj img.ppm
ln m.obj hard.obj && refused "render: model through a hard link" "$over" R m.obj hard.obj
ln -s m.obj soft.obj && refused "render: model through a symbolic link" "$over" R m.obj soft.obj
mkdir -p sub && refused "render: model through .." "$over" R m.obj sub/../m.obj
refused "render: texture as image output" "$over" RT t.ppm m.obj t.ppm
refused "render: texture as depth output" "$over" RT a.pgm --depth a.pgm m.obj img.ppm
refused "render: depth = image, new file, two spellings" "$one" R --depth ./new.ppm m.obj new.ppm
: > old.ppm
refused "render: depth = image, existing file" "$one" R --depth "$PWD/old.ppm" m.obj old.ppm
ln -s new2.ppm dangling.pgm
refused "render: depth is a dangling link to the image" "$one" R --depth dangling.pgm m.obj new2.ppm
[ ! -e new.ppm ] && [ ! -e new2.ppm ] && ok "render: nothing written when refused" || bad "render: written although refused"
refused "img2c: image as C output" "$over" "$img2c" t.ppm t.ppm o.h
refused "img2c: image as header" "$over" "$img2c" t.ppm o.c ./t.ppm
refused "img2c: alpha mask as output" "$over" "$img2c" --alpha a.pgm t.ppm a.pgm o.h
refused "img2c: C output = header" "$one" "$img2c" t.ppm same.c same.c
ln -s x.c lx.h
refused "img2c: header a dangling link to the C output" "$one" "$img2c" t.ppm x.c lx.h
refused "obj2c: model as C output" "$over" "$obj2c" m.obj m.obj o.h
refused "obj2c: C output = header through a path" "$one" "$obj2c" m.obj o.c sub/../o.c
refused "bsp: model as output" "$over" "$bsp" m.obj hard.obj tree
[ ! -e same.c ] && [ ! -e o.h ] && [ ! -e x.c ] && ok "converters: nothing written when refused" ||
    bad "converters: written although refused"

# --- 2. FIFOs, devices and folders stay what they are -------------------------
nonreg="not a regular file"
if mkfifo fifo 2>/dev/null; then
    refused "render: FIFO output" "$nonreg" R m.obj fifo
    refused "render: FIFO depth output" "$nonreg" R --depth fifo m.obj img.ppm
    refused "img2c: FIFO header" "$nonreg" "$img2c" t.ppm o.c fifo
    refused "obj2c: FIFO C output" "$nonreg" "$obj2c" m.obj fifo o.h
    refused "bsp: FIFO output" "$nonreg" "$bsp" m.obj fifo tree
    [ -p fifo ] && ok "the FIFO is still a FIFO" || bad "the FIFO was replaced"
fi
if [ -c /dev/null ] && [ -w /dev/null ]; then
    refused "render: device output" "$nonreg" R m.obj /dev/null
    refused "img2c: device C output" "$nonreg" "$img2c" t.ppm /dev/null o.h
    [ -c /dev/null ] && ok "/dev/null is still a device" || bad "/dev/null was replaced"
fi
echo keep > keep.h
refused "img2c: folder as C output, existing header kept" "$nonreg" "$img2c" t.ppm sub keep.h
[ "$(cat keep.h)" = keep ] && ok "img2c: keep.h intact" || bad "img2c: keep.h changed or deleted"
refused "render: folder output" "$nonreg" R m.obj sub

# --- 3. symbolic links are written through ------------------------------------
through() { # through CASE LINK TARGET COMMAND...
    name=$1 link=$2 target=$3; shift 3
    if "$@" 2> err.txt && [ -L "$link" ] && [ -s "$target" ]; then ok "$name"; else bad "$name: $(cat err.txt)"; fi
}
: > real.ppm && ln -s real.ppm l.ppm
through "render: symlinked image written through" l.ppm real.ppm R m.obj l.ppm
ln -s sub/real.h l.h
through "img2c: symlinked header written through to a new file" l.h sub/real.h "$img2c" t.ppm o.c l.h
ln -s real.c l.c
through "obj2c: symlinked C output written through" l.c real.c "$obj2c" m.obj l.c o.h

# --- 4. read-only outputs ------------------------------------------------------
ro="read-only"
echo old > ro.ppm && chmod 0444 ro.ppm
refused "render: read-only output" "$ro" R m.obj ro.ppm
echo old > ro.h && chmod 0444 ro.h
refused "img2c: read-only header" "$ro" "$img2c" t.ppm o.c ro.h
refused "obj2c: read-only header" "$ro" "$obj2c" m.obj o.c ro.h
refused "bsp: read-only output" "$ro" "$bsp" m.obj ro.h tree
[ "$(cat ro.ppm)" = old ] && [ "$(cat ro.h)" = old ] && ok "read-only files unchanged" || bad "a read-only file changed"

# --- 5. a failure part-way, permission bits ------------------------------------
# `ulimit -f 0` makes every write to a file fail (EFBIG; SIGXFSZ ignored).
write_fails() { # write_fails CASE FILE... -- COMMAND...
    name=$1; shift
    files=""
    while [ "$1" != "--" ]; do files="$files $1"; echo "previous $1" > "$1"; shift; done
    shift
    (trap '' XFSZ; ulimit -f "${limit:-0}"; "$@") > out.txt 2> err.txt
    rc=$?
    for f in $files; do
        [ "$(cat "$f")" = "previous $f" ] || { bad "$name: $f changed or deleted"; return; }
    done
    if [ "$rc" -ne 1 ]; then bad "$name: exit $rc, expected 1 ($(cat err.txt))"; return; fi
    if ! no_temporaries; then bad "$name: a temporary file was left: $(ls | grep '\.tmp')"; return; fi
    ok "$name"
}
write_fails "render: write error keeps the previous image and depth" p.ppm p.pgm -- R --depth p.pgm m.obj p.ppm
write_fails "img2c: write error keeps both previous files" p.c p.h -- "$img2c" t.ppm p.c p.h
write_fails "obj2c: write error keeps both previous files" q.c q.h -- "$obj2c" m.obj q.c q.h
write_fails "bsp: write error keeps the previous file" b.c -- "$bsp" m.obj b.c tree
# 512 bytes allowed: the 16x16 texture's header (about 440 bytes) is written
# whole, its source (about 1,500) is not; neither may take its name.
{ printf 'P6\n16 16\n255\n'; head -c 768 /dev/zero; } > t16.ppm
limit=1 write_fails "img2c: header complete, source not: neither renamed" h.c h.h -- "$img2c" t16.ppm h.c h.h
echo old > mode.h && chmod 0640 mode.h
if "$img2c" t.ppm mode.c mode.h 2> err.txt && [ "$(stat -c %a mode.h)" = 640 ] && grep -q texels mode.c; then
    ok "img2c: a replaced file keeps its permission bits"
else
    bad "img2c: permission bits: $(stat -c %a mode.h) $(cat err.txt)"
fi
if R --depth d.pgm m.obj old.ppm 2> err.txt && [ -s old.ppm ] && [ -s d.pgm ]; then
    ok "render: distinct outputs render"
else
    bad "render: distinct outputs: $(cat err.txt)"
fi
echo "output_rule: $fails failed"
exit "$fails"
