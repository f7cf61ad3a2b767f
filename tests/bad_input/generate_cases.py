#!/usr/bin/python3
"""Writes hostile non-mesh inputs and their cases: damaged PNG stamps and
patterns, stroke scripts and label tables that are not regular files or are
too large, checksum-valid projects with bad content or a header stating huge
sizes, and strokes whose results would not be finite.

    generate_cases.py OUTDIR MESHPAINT

writes the files into OUTDIR and OUTDIR/cases.json in the form of
tests/bad_input/cases.json ({dir} stands for OUTDIR). MESHPAINT (the
executable) saves the valid project that the project cases damage."""

import json
import os
import shutil
import struct
import subprocess
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
CUBE = os.path.join(HERE, "..", "support", "cube.obj")


def png_chunk(tag, data):
    return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)


def png(width, height, rows=None, colour=0, depth=8):
    """A PNG file; rows (filtered bytes) default to a grey ramp."""
    if rows is None:
        rows = b"".join(b"\0" + bytes((x * 16 + y) & 255 for x in range(width)) for y in range(height))
    ihdr = struct.pack(">IIBBBBB", width, height, depth, colour, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) + png_chunk(b"IDAT", zlib.compress(rows)) +
            png_chunk(b"IEND", b""))


def write(path, data):
    with open(path, "wb") as f:
        f.write(data)


def make_pngs(out):
    good = png(16, 16)
    write(os.path.join(out, "stamp-good.png"), good)
    write(os.path.join(out, "png-truncated.png"), good[:60])
    idat = good.index(b"IDAT")
    write(os.path.join(out, "png-no-iend.png"), good[:good.index(b"IEND") - 4])
    bad_crc = bytearray(good)
    (length,) = struct.unpack_from(">I", good, idat - 4)
    bad_crc[idat + 4 + length] ^= 0x55  # the first byte of IDAT's CRC
    write(os.path.join(out, "png-bad-crc.png"), bytes(bad_crc))
    # About 100 bytes declaring 100000 x 100000 pixels (9.3 GiB of grey).
    write(os.path.join(out, "png-huge.png"), png(100000, 100000, rows=b"\0" * 64))
    # Within the sample budget, but more than its few bytes could ever hold.
    write(os.path.join(out, "png-overstated.png"), png(4000, 4000, rows=b"\0" * 64))
    write(os.path.join(out, "png-text.png"), b"this is not an image\n")
    write(os.path.join(out, "png-empty.png"), b"")


def stroke(**extra):
    s = {"tool": "paint", "points": [[0.5, 0.5, 1.0]], "radius": 0.5, "channels": {"diffuse": [1, 0, 0]}}
    s.update(extra)
    return s


def script(out, name, *strokes):
    path = os.path.join(out, name)
    with open(path, "w") as f:
        json.dump({"strokes": list(strokes)}, f)
    return path


class Project:
    """A project file taken apart into its header fields and sections."""

    def __init__(self, path):
        data = open(path, "rb").read()
        self.head = data[:12]
        raw = zlib.decompress(data[40:])
        self.sections = []
        at = 0
        while at < len(raw):
            tag = raw[at:at + 4]
            (length,) = struct.unpack_from("<Q", raw, at + 4)
            self.sections.append([tag, bytearray(raw[at + 12:at + 12 + length])])
            at += 12 + length

    def section(self, tag):
        return next(body for t, body in self.sections if t == tag)

    def save(self, path, raw_size=None):
        raw = b"".join(t + struct.pack("<Q", len(b)) + bytes(b) for t, b in self.sections)
        packed = zlib.compress(raw, 1)
        header = self.head + struct.pack("<IQQI", 40, len(packed), raw_size or len(raw),
                                         zlib.crc32(packed) & 0xFFFFFFFF)
        header += struct.pack("<I", zlib.crc32(header) & 0xFFFFFFFF)
        write(path, header + packed)

    def mesh_offsets(self):
        """Offsets in MESH of the points, the face sizes and the corners."""
        m = self.section(b"MESH")
        (name,) = struct.unpack_from("<I", m, 0)
        at = 4 + name
        (v,) = struct.unpack_from("<I", m, at)
        points = at + 4
        at = points + 12 * v
        (f,) = struct.unpack_from("<I", m, at)
        sizes = at + 4
        at = sizes + 4 * f
        corners = at + 4
        return points, sizes, corners

    def labels(self, classes):
        body = bytearray(struct.pack("<I", len(classes)))
        for cid, name, colour in classes:
            body += struct.pack("<iI", cid, len(name)) + name + struct.pack("<3f", *colour)
        self.section(b"LABL")[:] = body


def make_projects(out, meshpaint, cases):
    base = os.path.join(out, "base.meshpaint")
    labels = os.path.join(out, "labels.json")
    with open(labels, "w") as f:
        json.dump([{"id": 1, "name": "bone", "colour": [1, 1, 0.8]}], f)
    paint = script(out, "base-strokes.json", stroke(channels={"diffuse": [1, 0, 0], "label": 1}))
    r = subprocess.run([meshpaint, "paint", CUBE, "--strokes", paint, "--level", "2", "--save", base,
                        "--labels", labels], capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        raise SystemExit("cannot make the base project: " + r.stderr)

    def damaged(name, message, change, raw_size=None):
        p = Project(base)
        change(p)
        path = os.path.join(out, name + ".meshpaint")
        p.save(path, raw_size)
        cases.append({"args": ["info", "{dir}/" + os.path.basename(path)], "message": message})

    def put_float(tag, offset, value):
        return lambda p: struct.pack_into("<f", p.section(tag), offset, value)

    atls_texels = 4 + 8  # level, texel count
    damaged("project-nan-control-point", r"corrupt project \(control point 0 has the value nan",
            put_float(b"ATLS", atls_texels, float("nan")))
    damaged("project-huge-control-point", r"corrupt project \(control point 3 has the value 3e\+38",
            put_float(b"ATLS", atls_texels + 16 * 3 + 4, 3e38))
    damaged("project-nan-diffuse", r"corrupt project \(diffuse at texel 2 is not finite",
            put_float(b"DIFF", 16 * 2, float("nan")))
    damaged("project-diffuse-above-one", r"corrupt project \(diffuse at texel 0 is not from 0 to 1",
            put_float(b"DIFF", 0, 1.5))
    damaged("project-label-fraction", r"corrupt project \(label at texel 1 is not an integer",
            put_float(b"MATL", 16 + 8, 0.5))
    damaged("project-huge-displacement", r"corrupt project \(displacement at texel 0 is beyond 1e15",
            put_float(b"MATL", 4, 3e38))
    damaged("project-nan-mesh-point", r"corrupt project \(base mesh: .*(non-finite|NaN|nan)",
            lambda p: struct.pack_into("<f", p.section(b"MESH"), p.mesh_offsets()[0], float("nan")))

    def repeat_vertex(p):
        corners = p.mesh_offsets()[2]
        (first,) = struct.unpack_from("<I", p.section(b"MESH"), corners)
        struct.pack_into("<I", p.section(b"MESH"), corners + 4, first)
    damaged("project-face-repeats-vertex", r"corrupt project \(.*base mesh needs repairs", repeat_vertex)
    damaged("project-label-id-twice", r"corrupt project \(label 1: id 1 is used twice",
            lambda p: p.labels([(1, b"bone", (1, 1, 1)), (1, b"skin", (1, 0, 0))]))
    damaged("project-label-colour", r"corrupt project \(label 0: \"colour\" must be",
            lambda p: p.labels([(1, b"bone", (2, 1, 1))]))
    damaged("project-label-not-utf8", r"corrupt project \(label 0: \"name\" \"bo\\xffne\" is not valid UTF-8",
            lambda p: p.labels([(1, b"bo\xffne", (1, 1, 1))]))
    damaged("project-label-negative-id", r"corrupt project \(label 0: \"id\" must be",
            lambda p: p.labels([(-4, b"bone", (1, 1, 1))]))
    # Checksums right, a decompressed size of 512 GiB stated: refused before allocating.
    damaged("project-huge-raw-size", r"corrupt project \(payload size out of range\)", lambda p: None,
            raw_size=1 << 39)
    cases.append({"args": ["paint", "{dir}/base.meshpaint", "--strokes", "{dir}/base-strokes.json",
                           "--labels", "{dir}/labels-not-utf8.json", "-o", "{tmp}/out"],
                  "message": r"labels-not-utf8.json: not valid JSON"})
    write(os.path.join(out, "labels-not-utf8.json"), b'[{"id": 1, "name": "bo\xffne", "colour": [1, 1, 1]}]')


def main():
    out, meshpaint = sys.argv[1], sys.argv[2]
    if os.path.isdir(out):
        shutil.rmtree(out)
    os.makedirs(out)
    cases = []
    make_pngs(out)
    paint = ["paint", CUBE, "--level", "2", "-o", "{tmp}/out", "--strokes"]
    for name, message in [("png-truncated", r"damaged PNG"), ("png-no-iend", r"damaged PNG"),
                          ("png-bad-crc", r"damaged PNG \(IDAT: CRC error\)"),
                          ("png-huge", r"100000 x 100000 pixels of 1 channels: more than the 67108864 samples"),
                          ("png-overstated", r"declares 4000 x 4000 pixels, more than its \d+ bytes can hold"),
                          ("png-text", r"not an image VTK knows"), ("png-empty", r"the file is empty")]:
        script(out, "stamp-" + name + ".json", stroke(stamp=name + ".png"))
        cases.append({"args": paint + ["{dir}/stamp-" + name + ".json"],
                      "message": r"stroke 0: cannot read '.*" + name + r"\.png': " + message})
    script(out, "pattern-png-bad-crc.json",
           stroke(pattern={"type": "image", "file": "png-bad-crc.png"}))
    cases.append({"args": paint + ["{dir}/pattern-png-bad-crc.json"],
                  "message": r"stroke 0: cannot read '.*png-bad-crc\.png': damaged PNG"})

    # Stroke scripts and label tables: regular files of bounded size only.
    os.mkfifo(os.path.join(out, "fifo.json"))
    with open(os.path.join(out, "huge.json"), "wb") as f:
        f.truncate(300 << 20)  # sparse: no disk space taken
    for name in ["/dev/zero", "{dir}/fifo.json", "{dir}"]:
        cases.append({"args": paint + [name], "message": r"stroke script '.*' is not a regular file"})
        cases.append({"args": ["paint", CUBE, "--strokes", "{dir}/base-strokes.json", "--labels", name,
                               "-o", "{tmp}/out"], "message": r"label table '.*' is not a regular file"})
    cases.append({"args": paint + ["{dir}/huge.json"],
                  "message": r"stroke script '.*huge.json' has 300.0 MiB, more than the 256.0 MiB accepted"})

    # Results must be finite: strokes inside the documented ranges whose
    # result would not be are refused, naming the stroke.
    quiet = ["paint", CUBE, "--level", "3", "--quiet", "-o", "{tmp}/out", "--strokes"]
    for name, s in [("sculpt-1e30", stroke(tool="sculpt", amount=1e30, channels=None)),
                    ("inflate-1e20", stroke(tool="inflate", amount=1e20, channels=None)),
                    ("displacement-3e38", stroke(channels={"displacement": 3e38}))]:
        if s.get("channels") is None:
            del s["channels"]
        script(out, name + ".json", stroke(), s)
        cases.append({"args": quiet + ["{dir}/" + name + ".json"],
                      "message": r"stroke 1: refused: it would move the surface to .* \(results must be finite"})

    # A scan whose faces lie on a line: the fit would collapse the surface.
    with open(os.path.join(out, "scan-on-a-line.obj"), "w") as f:
        f.write("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 1 3 4\n")
    cases.append({"args": ["fit", "{dir}/scan-on-a-line.obj", "--direct", "--level", "2", "--quiet",
                           "-o", "{tmp}/out.meshpaint"],
                  "message": r"the scan has no area \(its faces lie on a line or at a point\): nothing to fit to"})

    make_projects(out, meshpaint, cases)
    with open(os.path.join(out, "cases.json"), "w") as f:
        json.dump({"about": "generated by tests/bad_input/generate_cases.py", "cases": cases}, f, indent=1)


if __name__ == "__main__":
    main()
