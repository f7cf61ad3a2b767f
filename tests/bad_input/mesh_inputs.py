"""Damaged and valid mesh files, generated: the mesh classes of the bad-input corpus.

`damaged()` gives (name, bytes, message) for files every command that reads a
mesh must refuse with one line and exit 2 (`message` is a regular expression
for that line); `valid()` gives (name, bytes) for files written the ways other
tools write them, which must read without a repair report. Run as a script to
write them all into a folder (for looking at them, or as a fuzzing corpus):
    python3 tests/bad_input/mesh_inputs.py OUTDIR
"""
import os
import struct
import sys

CUBE_POINTS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
# Outward (counter-clockwise seen from outside).
CUBE_QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
CUBE_TRIANGLES = [t for q in CUBE_QUADS for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def ply_ascii(points=CUBE_POINTS, faces=CUBE_QUADS, list_type="uchar int", face_first=False, vertex_count=None,
              colours=None):
    head = ["ply", "format ascii 1.0"]
    vert = [f"element vertex {len(points) if vertex_count is None else vertex_count}",
            "property float x", "property float y", "property float z"]
    if colours:
        vert += ["property uchar red", "property uchar green", "property uchar blue"]
    face = [f"element face {len(faces)}", f"property list {list_type} vertex_indices"]
    head += (face + vert) if face_first else (vert + face)
    head.append("end_header")
    vlines = [" ".join(str(c) for c in p) + ("" if not colours else " " + " ".join(str(c) for c in colours[i]))
              for i, p in enumerate(points)]
    flines = [f"{len(f)} " + " ".join(str(i) for i in f) for f in faces]
    body = (flines + vlines) if face_first else (vlines + flines)
    return ("\n".join(head + body) + "\n").encode()


def ply_binary(points=CUBE_POINTS, faces=CUBE_TRIANGLES, list_count=None):
    head = ("ply\nformat binary_little_endian 1.0\n"
            f"element vertex {len(points)}\nproperty float x\nproperty float y\nproperty float z\n"
            f"element face {len(faces)}\nproperty list int int vertex_indices\nend_header\n").encode()
    body = b"".join(struct.pack("<3f", *p) for p in points)
    for f in faces:
        body += struct.pack("<i", len(f) if list_count is None else list_count) + struct.pack(f"<{len(f)}i", *f)
    return head + body


def stl_binary(triangles=CUBE_TRIANGLES, points=CUBE_POINTS, header=b"binary STL".ljust(80, b" ")):
    body = b""
    for t in triangles:
        body += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *points[i]) for i in t) + b"\0\0"
    return header + struct.pack("<I", len(triangles)) + body


def stl_ascii(triangles=CUBE_TRIANGLES, points=CUBE_POINTS, solid="solid cube", end=True):
    lines = [solid]
    for t in triangles:
        lines += ["  facet normal 0 0 0", "    outer loop"]
        lines += [f"      vertex {points[i][0]} {points[i][1]} {points[i][2]}" for i in t]
        lines += ["    endloop", "  endfacet"]
    if end:
        lines.append("endsolid cube")
    return ("\n".join(lines) + "\n").encode()


def obj(points=CUBE_POINTS, faces=CUBE_QUADS, colours=None):
    lines = ["mtllib cube.mtl", "usemtl red"]
    for i, p in enumerate(points):
        lines.append("v " + " ".join(str(c) for c in p) + ("" if not colours else " " + " ".join(str(c) for c in colours[i])))
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return ("\n".join(lines) + "\n").encode()


def off(points=CUBE_POINTS, faces=CUBE_QUADS, keyword="OFF", face_extra=None, vertex_extra=None, counts=None):
    lines = [keyword] + ([] if counts == "" else [counts or f"{len(points)} {len(faces)} 0"])
    for i, p in enumerate(points):
        lines.append(" ".join(str(c) for c in p) + ("" if not vertex_extra else " " + vertex_extra(i)))
    for k, f in enumerate(faces):
        lines.append(f"{len(f)} " + " ".join(str(i) for i in f) + ("" if not face_extra else " " + face_extra(k)))
    return ("\n".join(lines) + "\n").encode()


def off_binary(points=CUBE_POINTS, faces=CUBE_TRIANGLES, byte_order=">", face_colour=lambda k: []):
    """'OFF BINARY': Geomview's layout ('>', a colour count and that many floats
    after each face's indices), or OpenMesh's (face_colour=None, little-endian)."""
    body = struct.pack(f"{byte_order}3i", len(points), len(faces), 0)
    body += b"".join(struct.pack(f"{byte_order}3f", *p) for p in points)
    for k, f in enumerate(faces):
        body += struct.pack(f"{byte_order}{len(f) + 1}i", len(f), *f)
        if face_colour is not None:
            c = face_colour(k)
            body += struct.pack(f"{byte_order}i{len(c)}f", len(c), *c)
    return b"OFF BINARY\n" + body


def soup_of(points, faces):
    """Every face with its own copies of its vertices, as many exporters write."""
    pts, fs = [], []
    for f in faces:
        fs.append(tuple(range(len(pts), len(pts) + len(f))))
        pts += [points[i] for i in f]
    return pts, fs


def damaged():
    nan_points = list(CUBE_POINTS)
    nan_points[3] = (0, float("nan"), 0)
    stl = stl_binary()
    cases = [
        ("truncated-ascii.ply", ply_ascii()[:-20], r"truncated|line [0-9]+"),
        ("face-element-first.ply", ply_ascii(face_first=True), r"face element comes before the vertex element"),
        ("nan.ply", ply_ascii().replace(b"\n1 1 0\n", b"\n1 nan 0\n", 1), r"line [0-9]+: non-finite coordinate 'nan'"),
        ("nan-binary.ply", ply_binary(points=nan_points), r"vertex 3 has a non-finite coordinate y"),
        ("index-out-of-range.ply", ply_ascii(faces=CUBE_QUADS[:-1] + [(3, 0, 4, 70)]), r"names vertex 70|not a vertex index|list of"),
        ("index-out-of-range-binary.ply", ply_binary(faces=CUBE_TRIANGLES[:-1] + [(3, 0, 70)]), r"names vertex 70"),
        ("list-count-minus-one.ply", ply_binary(list_count=-1), r"list of -1 items"),
        ("lying-vertex-count.ply", ply_ascii(vertex_count=12), r"truncated|line [0-9]+"),
        ("body-longer-than-header.ply", ply_ascii() + b"3 0 1 2\n", r"after the elements the PLY header declares"),
        ("truncated-binary.ply", ply_binary()[:-7], r"ends inside|truncated"),
        ("float-list-count.ply", ply_ascii(list_type="float int"), r"a list count of type float"),
        ("truncated-binary.stl", stl[:-30], r"a binary STL of 12 triangles has 684 bytes, this file 654"),
        ("nan-binary.stl", stl_binary(points=nan_points), r"binary STL triangle [0-9]+ has a non-finite coordinate"),
        ("truncated-ascii.stl", stl_ascii()[:-60], r"ends without endsolid|line [0-9]+"),
        ("control-byte.stl", stl_ascii().replace(b"vertex 1 0 0", b"vertex 1 0\x01 0", 1), r"line [0-9]+: .* is not a number that fits"),
        ("nan.stl", stl_ascii().replace(b"vertex 1 0 0", b"vertex 1 nan 0", 1), r"line [0-9]+: non-finite coordinate 'nan'"),
        ("quad-facet.stl", stl_ascii().replace(b"    endloop", b"      vertex 0 0 0\n    endloop", 1), r"a facet of 4 vertices"),
        ("malformed-v-line.obj", obj().replace(b"v 1 1 0", b"v 1 1x 0", 1), r"line [0-9]+: '1x' is not a number that fits"),
        ("short-v-line.obj", obj().replace(b"v 1 1 0", b"v 1 1", 1), r"line [0-9]+: a vertex of 2 numbers"),
        ("nan.obj", obj().replace(b"v 1 1 0", b"v 1 nan 0", 1), r"line [0-9]+: non-finite coordinate 'nan'"),
        ("index-out-of-range.obj", obj(faces=CUBE_QUADS[:-1] + [(3, 0, 4, 70)]), r"names vertex 70"),
        ("face-keyword-alone.obj", obj() + b"f", r"line [0-9]+: a face without vertices"),
        ("truncated.obj", obj()[:-4], r"line [0-9]+: a face of [0-2] corners \(truncated\?\)"),
        ("nan.off", off().replace(b"\n1 1 0\n", b"\n1 nan 0\n", 1), r"line [0-9]+: non-finite coordinate 'nan'"),
        ("index-out-of-range.off", off(faces=CUBE_QUADS[:-1] + [(3, 0, 4, 70)]), r"line [0-9]+: face 5 names vertex 70"),
        ("face-count-too-small.off", off(counts="8 5 0"), r"line [0-9]+: more content after the 5 faces"),
        ("truncated.off", off()[:-12], r"declares 6 faces, but the file ends after 5|line [0-9]+"),
        ("malformed-number.off", off().replace(b"\n1 1 0\n", b"\n1 1,0 0\n", 1), r"line 5: '1,0' is not a number"),
        ("two-colour-numbers.off", off(face_extra=lambda k: "1 1"), r"line 11: a face of 4 corners with 2 more numbers"),
        ("colour-out-of-range.off", off(face_extra=lambda k: "300 0 0"), r"colour component '300' is outside 0-255"),
        ("huge-nOFF-dimension.off", off(keyword="nOFF\n4"), r"nOFF of dimension 4"),
        ("beyond-float.off", off().replace(b"\n1 1 0\n", b"\n1 1e39 0\n", 1), r"line 5: '1e39' is not a number that fits"),
        ("binary-colour-count-2.off", off_binary(face_colour=lambda k: [1, 0]), r"binary OFF face 0 has a colour count of 2"),
        ("binary-colour-beyond-one.off", off_binary(face_colour=lambda k: [2, 0, 0]), r"face 0 has colour component 2, outside 0-1"),
        ("binary-colour-map-index-fraction.off", off_binary(face_colour=lambda k: [1.5]), r"face 0 has colour-map index 1.5"),
        ("binary-truncated.off", off_binary()[:-6], r"binary OFF face 11 runs past the end of the file"),
        ("binary-index-out-of-range.off", off_binary(faces=CUBE_TRIANGLES[:-1] + [(3, 0, 70)]),
         r"binary OFF face 11 names vertex 70"),
        ("colour-beyond-one.obj", obj(colours=[(2, 0, 0)] * 8), r"line [0-9]+: colour '2' is outside 0-1"),
        ("float-colour-beyond-one.ply", ply_ascii(colours=[(2.5, 0, 0)] * 8).replace(b"uchar", b"float").replace(
            b"property list float int", b"property list uchar int"), r"line [0-9]+: colour red '2.5' is outside 0-1"),
    ]
    return cases


def valid():
    soup_pts, soup_faces = soup_of(CUBE_POINTS, CUBE_QUADS)
    colours = [(255 * (i & 1), 255 * ((i >> 1) & 1), 255 * ((i >> 2) & 1)) for i in range(8)]
    unit = [tuple(c / 255 for c in col) for col in colours]
    return [
        ("plain.off", off()),
        ("comments-and-blanks.off", b"# written by hand\n\n" + off().replace(b"\n", b"\n\n# a comment\n", 3)),
        ("keyword-with-counts.off", off(keyword="OFF 8 6 0", counts="")),
        ("no-edge-count.off", off(counts="8 6")),
        ("keyword-run-into-counts.off", off(keyword="OFF8 6 0", counts="")),
        ("coff-keyword-run-into-counts.off", off(keyword="COFF8 6 0", counts="", vertex_extra=lambda i: " ".join(f"{c:g}" for c in unit[i]))),
        ("coff.off", off(keyword="COFF", vertex_extra=lambda i: " ".join(f"{c:g}" for c in unit[i]) + " 1")),
        ("noff.off", off(keyword="NOFF", vertex_extra=lambda i: "0 0 1")),
        ("stoff.off", off(keyword="STOFF", vertex_extra=lambda i: "0.5 0.5")),
        ("cnoff.off", off(keyword="CNOFF", vertex_extra=lambda i: "0 0 1 1 0 0")),
        ("4off.off", off(keyword="4OFF", vertex_extra=lambda i: "2")),
        ("noff-dimension-3.off", off(keyword="nOFF\n3")),
        ("face-colour-index.off", off(face_extra=lambda k: str(k))),
        ("face-colour-rgb-int.off", off(face_extra=lambda k: "255 0 0")),
        ("face-colour-rgba-float.off", off(face_extra=lambda k: "0.1 0.8 0.2 0.75")),
        ("geomview-binary.off", off_binary()),
        ("geomview-binary-little-endian.off", off_binary(byte_order="<")),
        ("geomview-binary-face-colours.off", off_binary(face_colour=lambda k: [[k % 149], [], [1, 0, 0], [0, 1, 0, 1]][k % 4])),
        ("geomview-binary-red-faces.off", off_binary(face_colour=lambda k: [1, 0, 0])),
        ("openmesh-binary.off", off_binary(byte_order="<", face_colour=None)),
        ("bom.obj", b"\xef\xbb\xbf" + obj()),
        ("vertex-colours.obj", obj(colours=unit)),
        ("uint-list.ply", ply_ascii(list_type="uint int")),
        ("uchar-colours.ply", ply_ascii(colours=colours)),
        ("bom.stl", b"\xef\xbb\xbf" + stl_ascii()),
        ("blank-line.stl", b"\n" + stl_ascii()),
        ("SOLID.stl", stl_ascii(solid="SOLID cube")),
        ("binary-says-solid.stl", stl_binary(header=b"solid but binary".ljust(80, b" "))),
        ("soup.off", off(points=soup_pts, faces=soup_faces)),
    ]


if __name__ == "__main__":
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, data, *_ in damaged() + valid():
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)
