#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The OLED firmware on QEMU's emulated display, frame by frame, against the host.

    oled_test.py --qemu qemu-system-arm --elf oled_demo.elf \
                 --reference zline-oled-reference --dir WORKDIR [--expect-mismatch]

1. zline-oled-reference renders every frame of the demo on the host and
   writes WORKDIR/reference/frame-NN.pgm: 128x64, one byte per pixel, the
   4-bit grey level (port/display/zl_grey4.h).
2. QEMU runs the firmware on lm3s6965evb with -display none, the QMP monitor
   on a unix socket and semihosting on this script's pipes. When the firmware
   prints "frame N shown" it is blocked reading the semihosting console; the
   script takes a QMP screendump of the OLED (a 512x256 PPM: QEMU draws each
   panel pixel as a 4x4 block of grey level * 17), reduces it to 128x64 grey
   levels (every block must be one uniform grey of the 16), saves it as
   WORKDIR/captures/frame-NN.pgm, compares it byte for byte with the
   reference and sends a newline so the firmware goes on.
3. The firmware must exit 0 after the last frame, QEMU's SSD0323 model must
   report no error, and every frame must be compared.

Exit status: 0 if every frame equals the reference (or, with
--expect-mismatch, if the run was complete and at least one frame differs:
the negative controls); 1 for a mismatch (or none when one was expected);
2 when the test could not run properly (QEMU missing, timeout, crash).
Everything is bounded: each wait has a timeout, the whole run --timeout s.
"""
import argparse
import json
import os
import select
import shutil
import socket
import subprocess
import sys
import tempfile
import time

W, H, MAGNIFY = 128, 64, 4


class Broken(Exception):
    """The run itself failed: exit status 2."""


def read_pnm(path):
    """(magic, width, height, maxval, pixel bytes) of a binary PGM/PPM."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while pos < len(data) and data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            while pos < len(data) and data[pos:pos + 1] != b"\n":
                pos += 1
            continue
        start = pos
        while pos < len(data) and not data[pos:pos + 1].isspace():
            pos += 1
        if start == pos:
            raise Broken("%s: truncated header" % path)
        fields.append(data[start:pos])
    magic = fields[0].decode()
    width, height, maxval = (int(x) for x in fields[1:4])
    return magic, width, height, maxval, data[pos + 1:]


def reduce_capture(path):
    """The 512x256 screendump as 128x64 grey levels 0..15."""
    magic, width, height, maxval, px = read_pnm(path)
    if magic != "P6" or (width, height, maxval) != (W * MAGNIFY, H * MAGNIFY, 255):
        raise Broken("%s: expected a %dx%d P6 PPM, got %s %dx%d" % (path, W * MAGNIFY, H * MAGNIFY,
                                                                     magic, width, height))
    if len(px) < width * height * 3:
        raise Broken("%s: truncated pixels" % path)
    out = bytearray(W * H)
    for y in range(H):
        for x in range(W):
            first = None
            for dy in range(MAGNIFY):
                row = (y * MAGNIFY + dy) * width
                for dx in range(MAGNIFY):
                    i = (row + x * MAGNIFY + dx) * 3
                    rgb = px[i:i + 3]
                    if first is None:
                        first = rgb
                    elif rgb != first:
                        raise Broken("%s: panel pixel (%d, %d) is not a uniform 4x4 block" % (path, x, y))
            r, g, b = first
            if r != g or g != b or r % 17 != 0:
                raise Broken("%s: panel pixel (%d, %d) is not one of the 16 greys: %d %d %d"
                             % (path, x, y, r, g, b))
            out[y * W + x] = r // 17
    return bytes(out)


def write_pgm(path, levels):
    with open(path, "wb") as f:
        f.write(b"P5\n%d %d\n15\n" % (W, H))
        f.write(levels)


def compare(frame, got, want):
    """None if equal, else a one-line description of the difference."""
    if got == want:
        return None
    diffs = [i for i in range(W * H) if got[i] != want[i]]
    i = diffs[0]
    return ("frame %d: %d of %d pixels differ; first at (%d, %d): panel %d, host %d"
            % (frame, len(diffs), W * H, i % W, i // W, got[i], want[i]))


class Qmp:
    def __init__(self, path, deadline, proc):
        self.deadline = deadline
        while True:
            try:
                self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
                self.sock.connect(path)
                break
            except OSError:
                self.sock.close()
                if proc.poll() is not None:
                    # The firmware stopped before the socket was up (a
                    # start-up error it printed): say so now, not at the deadline.
                    out = proc.stdout.read().decode("utf-8", "replace").strip()
                    raise Broken("QEMU exited (status %d) before its QMP socket was up; the firmware said: %s"
                                 % (proc.returncode, out or "nothing"))
                if time.monotonic() > deadline:
                    raise Broken("cannot connect to QEMU's QMP socket %s" % path)
                time.sleep(0.05)
        self.buf = b""
        self.reply()  # greeting
        self.execute("qmp_capabilities")

    def reply(self):
        while True:
            while b"\n" in self.buf:
                line, self.buf = self.buf.split(b"\n", 1)
                msg = json.loads(line)
                if "event" not in msg:
                    return msg
            left = self.deadline - time.monotonic()
            if left <= 0:
                raise Broken("QMP: no reply before the time limit")
            self.sock.settimeout(left)
            chunk = self.sock.recv(65536)
            if not chunk:
                raise Broken("QMP: QEMU closed the monitor")
            self.buf += chunk

    def execute(self, command, **arguments):
        msg = {"execute": command}
        if arguments:
            msg["arguments"] = arguments
        self.sock.sendall(json.dumps(msg).encode() + b"\n")
        reply = self.reply()
        if "error" in reply:
            raise Broken("QMP %s: %s" % (command, reply["error"]))
        return reply


class Lines:
    """Lines of the firmware's semihosting output, with a deadline."""

    def __init__(self, stream, deadline, log):
        self.fd = stream.fileno()
        self.deadline = deadline
        self.buf = b""
        self.log = log

    def next(self):
        while b"\n" not in self.buf:
            left = self.deadline - time.monotonic()
            if left <= 0:
                raise Broken("timed out waiting for the firmware's output")
            ready, _, _ = select.select([self.fd], [], [], left)
            if not ready:
                continue
            chunk = os.read(self.fd, 4096)
            if not chunk:
                return None
            self.buf += chunk
        line, self.buf = self.buf.split(b"\n", 1)
        text = line.decode(errors="replace")
        self.log.append(text)
        return text


def run(args):
    for d in ("reference", "captures"):
        shutil.rmtree(os.path.join(args.dir, d), ignore_errors=True)
        os.makedirs(os.path.join(args.dir, d))
    ref = subprocess.run([args.reference, os.path.join(args.dir, "reference")],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
    if ref.returncode != 0:
        raise Broken("the host reference failed:\n" + ref.stdout.decode(errors="replace"))
    if shutil.which(args.qemu) is None:
        raise Broken("%s not found (apt install qemu-system-arm)" % args.qemu)

    deadline = time.monotonic() + args.timeout
    # A short private directory for the socket: unix socket paths are
    # limited to about 100 bytes, build directories can be deeper.
    sock_dir = tempfile.mkdtemp(prefix="zline-oled-")
    try:
        return run_qemu(args, deadline, os.path.join(sock_dir, "qmp.sock"))
    finally:
        shutil.rmtree(sock_dir, ignore_errors=True)


def run_qemu(args, deadline, sock_path):
    cmd = [args.qemu, "-M", "lm3s6965evb", "-display", "none", "-monitor", "none", "-serial", "none",
           "-qmp", "unix:%s,server=on,wait=off" % sock_path,
           "-chardev", "stdio,id=semi", "-semihosting-config", "enable=on,target=native,chardev=semi",
           "-icount", "shift=5,sleep=off", "-kernel", args.elf]
    stderr_path = os.path.join(args.dir, "qemu.stderr")
    log = []
    mismatches = []
    frames = 0
    with open(stderr_path, "wb") as err:
        proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=err)
        try:
            qmp = Qmp(sock_path, deadline, proc)
            lines = Lines(proc.stdout, deadline, log)
            while True:
                line = lines.next()
                if line is None:
                    break
                print(line)
                if not line.startswith("frame ") or " shown" not in line:
                    continue
                n = int(line.split()[1])
                if n != frames:
                    raise Broken("frame %d announced, expected frame %d" % (n, frames))
                dump = os.path.join(args.dir, "captures", "frame-%02d.ppm" % n)
                qmp.execute("screendump", filename=os.path.abspath(dump))
                got = reduce_capture(dump)
                os.unlink(dump)
                write_pgm(os.path.join(args.dir, "captures", "frame-%02d.pgm" % n), got)
                want_path = os.path.join(args.dir, "reference", "frame-%02d.pgm" % n)
                if not os.path.exists(want_path):
                    raise Broken("the firmware showed frame %d; the reference has no such frame" % n)
                magic, width, height, maxval, want = read_pnm(want_path)
                if (magic, width, height, maxval) != ("P5", W, H, 15):
                    raise Broken("%s: not a 128x64 grey-level PGM" % want_path)
                diff = compare(n, got, want[:W * H])
                if diff:
                    mismatches.append(diff)
                    print("MISMATCH " + diff)
                frames += 1
                try:
                    proc.stdin.write(b"\n")
                    proc.stdin.flush()
                except OSError as e:
                    raise Broken("cannot reach the firmware after frame %d: %s" % (n, e))
            code = proc.wait(timeout=max(1.0, deadline - time.monotonic()))
        except subprocess.TimeoutExpired:
            raise Broken("QEMU did not exit before the time limit")
        finally:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
    with open(stderr_path, "rb") as f:
        qemu_err = f.read().decode(errors="replace")
    if "ssd0323: error" in qemu_err:
        mismatches.append("QEMU's SSD0323 model reported: " + qemu_err.strip())
        print("MISMATCH " + mismatches[-1])
    elif qemu_err.strip():
        print("QEMU stderr: " + qemu_err.strip())
    # the firmware's own lines (RAM map, counts) for readme_figures.py
    with open(os.path.join(args.dir, "firmware.log"), "w") as f:
        f.write("\n".join(log) + "\n")
    if code != 0:
        raise Broken("the firmware exited with %d" % code)
    expected = len([f for f in os.listdir(os.path.join(args.dir, "reference")) if f.endswith(".pgm")])
    if frames != expected:
        raise Broken("%d frames shown, the reference has %d" % (frames, expected))
    return frames, mismatches


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--qemu", default="qemu-system-arm")
    p.add_argument("--elf", required=True)
    p.add_argument("--reference", required=True, help="the zline-oled-reference program")
    p.add_argument("--dir", required=True, help="work directory (captures, reference frames)")
    p.add_argument("--timeout", type=float, default=120.0, help="limit for the whole run, seconds")
    p.add_argument("--expect-mismatch", action="store_true",
                   help="negative control: pass only if some frame differs")
    args = p.parse_args()
    os.makedirs(args.dir, exist_ok=True)
    try:
        frames, mismatches = run(args)
    except (Broken, OSError, ValueError) as e:
        print("oled_test: cannot complete the test: %s" % e)
        return 2
    if args.expect_mismatch:
        if mismatches:
            print("oled_test: negative control PASSED: the faulty firmware was caught (%d differences)"
                  % len(mismatches))
            return 0
        print("oled_test: negative control FAILED: all %d frames equal the host despite the fault" % frames)
        return 1
    if mismatches:
        print("oled_test: FAILED: %d of %d frames differ from the host rendering" % (len(mismatches), frames))
        return 1
    print("oled_test: PASSED: %d frames captured from the emulated OLED equal the host rendering" % frames)
    return 0


if __name__ == "__main__":
    sys.exit(main())
