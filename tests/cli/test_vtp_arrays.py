"""The arrays of .vtp files checked before VTK's XML reader reads them.

Every layout VTK's writer produces (ascii, inline binary, appended raw and
base64; no compression, zlib, LZ4, LZMA; 32- and 64-bit headers; either byte
order) must read as the same mesh, and damaged sizes in any of them must be
one line naming the array, exit 2, before VTK allocates what they state.
"""
import base64
import os
import re
import struct
import subprocess

import numpy as np
import pytest
import vtk
from vtkmodules.util import numpy_support

BIN = os.environ["MESHPAINT_BIN"]
SOURCE = os.environ["MESHPAINT_SOURCE_DIR"]
FINDING = os.path.join(SOURCE, "tests", "fuzz", "regressions", "fuzz_polydata_vtp", "binary-array-huge-allocation.vtp")

MODES = {"ascii": 0, "binary": 1, "appended": 2, "raw": 2}
COMPRESSORS = ["none", "zlib", "lz4", "lzma"]


def run(*args):
    return subprocess.run([BIN, *args], capture_output=True, text=True, timeout=600)


def sphere():
    """A sphere with colours (diffuse) and labels, so that every kind of point array is read."""
    s = vtk.vtkSphereSource()
    s.SetThetaResolution(24)
    s.SetPhiResolution(18)
    s.Update()
    poly = s.GetOutput()
    pts = numpy_support.vtk_to_numpy(poly.GetPoints().GetData())
    diffuse = numpy_support.numpy_to_vtk(np.ascontiguousarray(pts + 0.5, dtype=np.float32), deep=True)
    diffuse.SetName("diffuse")
    labels = numpy_support.numpy_to_vtk(np.where(pts[:, 2] > 0, 1, 2).astype(np.int32), deep=True)
    labels.SetName("labels")
    poly.GetPointData().AddArray(diffuse)
    poly.GetPointData().AddArray(labels)
    # Strings have no fixed size per value: a point array and a field array of them.
    names = vtk.vtkStringArray()
    names.SetName("names")
    for k in range(poly.GetNumberOfPoints()):
        names.InsertNextValue("p%d" % k if k % 3 else "")
    poly.GetPointData().AddArray(names)
    note = vtk.vtkStringArray()
    note.SetName("note")
    note.InsertNextValue("scanned")
    poly.GetFieldData().AddArray(note)
    return poly


def write_vtp(path, mode="binary", compressor="none", header=32, big_endian=False, block_size=None):
    w = vtk.vtkXMLPolyDataWriter()
    w.SetInputData(sphere())
    w.SetFileName(str(path))
    w.SetDataMode(MODES[mode])
    if mode == "raw":
        w.EncodeAppendedDataOff()
    {"none": w.SetCompressorTypeToNone, "zlib": w.SetCompressorTypeToZLib, "lz4": w.SetCompressorTypeToLZ4,
     "lzma": w.SetCompressorTypeToLZMA}[compressor]()
    w.SetHeaderTypeToUInt64() if header == 64 else w.SetHeaderTypeToUInt32()
    w.SetByteOrderToBigEndian() if big_endian else w.SetByteOrderToLittleEndian()
    if block_size:
        w.SetBlockSize(block_size)
    assert w.Write() == 1
    return str(path)


def painted_arrays(tmp_path, mesh):
    """The surface `paint` writes for the mesh with no strokes: its points and point arrays."""
    strokes = tmp_path / "none.json"
    strokes.write_text('{"strokes": []}')
    out = tmp_path / "out"
    r = run("paint", mesh, "--strokes", str(strokes), "--level", "1", "-o", str(out), "--quiet")
    assert r.returncode == 0, r.stderr
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(str(out / "surface.vtp"))
    reader.Update()
    poly = reader.GetOutput()
    arrays = {"points": numpy_support.vtk_to_numpy(poly.GetPoints().GetData())}
    pd = poly.GetPointData()
    for k in range(pd.GetNumberOfArrays()):
        if pd.GetArray(k):  # numeric arrays
            arrays[pd.GetArrayName(k)] = numpy_support.vtk_to_numpy(pd.GetArray(k))
    return arrays


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    d = tmp_path_factory.mktemp("reference")
    return painted_arrays(d, write_vtp(d / "sphere.vtp", mode="ascii"))


LAYOUTS = [(mode, compressor, header, False) for mode in ["ascii", "binary", "appended", "raw"]
           for compressor in COMPRESSORS for header in (32, 64)]
LAYOUTS += [("binary", "zlib", 32, True), ("raw", "lz4", 64, True), ("appended", "none", 32, True)]


@pytest.mark.parametrize("mode, compressor, header, big_endian", LAYOUTS, ids=lambda v: str(v))
def test_vtk_written_layouts_read_as_the_same_mesh(tmp_path, reference, mode, compressor, header, big_endian):
    # Small blocks: many compressed blocks, the last one partial.
    path = write_vtp(tmp_path / "sphere.vtp", mode, compressor, header, big_endian, block_size=96)
    arrays = painted_arrays(tmp_path, path)
    assert arrays.keys() == reference.keys()
    for name, values in reference.items():
        assert np.array_equal(arrays[name], values), name


@pytest.mark.parametrize("compressor", ["zlib", "lz4", "lzma"])
def test_highly_compressed_arrays_are_accepted(tmp_path, compressor):
    # One label everywhere in 32 KiB blocks: about as tight as each compressor packs.
    s = vtk.vtkSphereSource()
    s.SetThetaResolution(300)
    s.SetPhiResolution(300)
    s.Update()
    poly = s.GetOutput()
    labels = numpy_support.numpy_to_vtk(np.full(poly.GetNumberOfPoints(), 3, dtype=np.int64), deep=True)
    labels.SetName("labels")
    poly.GetPointData().AddArray(labels)
    w = vtk.vtkXMLPolyDataWriter()
    w.SetInputData(poly)
    w.SetFileName(str(tmp_path / "big.vtp"))
    w.SetDataModeToBinary()
    {"zlib": w.SetCompressorTypeToZLib, "lz4": w.SetCompressorTypeToLZ4, "lzma": w.SetCompressorTypeToLZMA}[compressor]()
    assert w.Write() == 1
    r = run("info", str(tmp_path / "big.vtp"))
    assert r.returncode == 0, r.stderr


def refused(path, array):
    r = run("info", str(path))
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2, r.stdout + r.stderr
    assert len(lines) == 1 and lines[0].startswith("meshpaint info: "), r.stderr
    assert array in lines[0], lines[0]
    return lines[0]


def inline_array(text, section, name):
    """The span of the base64 text of array `name` inside `section` (Points, Polys, PointData, ...)."""
    start = text.index("<" + section)
    m = re.compile(r'<DataArray[^>]*Name="%s"[^>]*>\s*([A-Za-z0-9+/=]+)' % name).search(text, start)
    return m.span(1)


def edit_inline(path, section, name, edit):
    """Decodes an uncompressed inline array (header and data, one base64 stream), edits and re-encodes it."""
    text = open(path).read()
    a, b = inline_array(text, section, name)
    raw = bytearray(base64.b64decode(text[a:b]))
    edit(raw)
    open(path, "w").write(text[:a] + base64.b64encode(bytes(raw)).decode() + text[b:])


def test_the_fuzz_finding_is_bad_input():
    # Its damaged base64 made VTK ask for about 10^19 bytes (exit 3, out of host memory).
    refused(FINDING, "array")


def test_a_huge_last_offset_is_refused_before_vtk_allocates_it(tmp_path):
    # The finding's mechanism: VTK allocates the connectivity the last offset states.
    path = write_vtp(tmp_path / "s.vtp", "binary")
    edit_inline(path, "Polys", "offsets", lambda raw: raw.__setitem__(slice(len(raw) - 8, len(raw)),
                                                                       struct.pack("<q", 10 ** 18)))
    line = refused(path, "'offsets'")
    assert "Polys" in line


def test_a_last_offset_beyond_the_connectivity_is_refused(tmp_path):
    path = write_vtp(tmp_path / "s.vtp", "binary")
    edit_inline(path, "Polys", "offsets", lambda raw: raw.__setitem__(slice(len(raw) - 8, len(raw)),
                                                                       struct.pack("<q", struct.unpack("<q", raw[-8:])[0] + 3)))
    refused(path, "'connectivity'")


def test_a_binary_header_stating_more_than_the_file_holds_is_refused(tmp_path):
    path = write_vtp(tmp_path / "s.vtp", "binary", header=64)
    edit_inline(path, "PointData", "labels", lambda raw: raw.__setitem__(slice(0, 8), struct.pack("<Q", 2 ** 62)))
    refused(path, "'labels'")


def test_a_header_disagreeing_with_the_piece_is_refused(tmp_path):
    path = write_vtp(tmp_path / "s.vtp", "binary")
    edit_inline(path, "PointData", "diffuse", lambda raw: raw.__setitem__(slice(0, 4), struct.pack("<I", 12)))
    refused(path, "'diffuse'")


def test_a_piece_count_disagreeing_with_the_arrays_is_refused(tmp_path):
    path = write_vtp(tmp_path / "s.vtp", "binary")
    text = open(path).read()
    n = int(re.search(r'NumberOfPoints="(\d+)"', text).group(1))
    open(path, "w").write(text.replace('NumberOfPoints="%d"' % n, 'NumberOfPoints="%d"' % (n + 1), 1))
    assert "%d points x 3 components" % (n + 1) in refused(path, "'Normals'")


def compressed_header(path, section, name, header):
    """The span of the compressed array's header, the words in it, and its word format."""
    text = open(path).read()
    a, _ = inline_array(text, section, name)
    fmt = "<I" if header == 32 else "<Q"
    size = struct.calcsize(fmt)
    first = base64.b64decode(text[a:a + 4 * -(-3 * size // 3)])
    blocks = struct.unpack(fmt, first[:size])[0]
    chars = 4 * -(-(3 + blocks) * size // 3)
    raw = base64.b64decode(text[a:a + chars])
    words = list(struct.unpack("<%d%s" % (3 + blocks, fmt[1]), raw))
    return text, (a, a + chars), words, fmt


def rewrite_header(path, text, span, words, fmt):
    raw = struct.pack("<%d%s" % (len(words), fmt[1]), *words)
    open(path, "w").write(text[:span[0]] + base64.b64encode(raw).decode() + text[span[1]:])


@pytest.mark.parametrize("header", [32, 64])
def test_a_compression_header_listing_too_many_blocks_is_refused(tmp_path, header):
    path = write_vtp(tmp_path / "s.vtp", "binary", "zlib", header)
    text, span, words, fmt = compressed_header(path, "Points", "Points", header)
    words[0] = 2 ** 31
    rewrite_header(path, text, span, words, fmt)
    refused(path, "'Points'")


@pytest.mark.parametrize("compressor", ["zlib", "lz4", "lzma"])
def test_a_block_stating_more_than_its_compressor_can_pack_is_refused(tmp_path, compressor):
    path = write_vtp(tmp_path / "s.vtp", "binary", compressor, 64)
    text, span, words, fmt = compressed_header(path, "PointData", "labels", 64)
    assert words[0] == 1
    words[1] = words[2] = 5 * 10 ** 6  # within the budget of the file's size, beyond any packing
    rewrite_header(path, text, span, words, fmt)
    assert "can pack" in refused(path, "'labels'")


def test_ascii_connectivity_shorter_than_the_last_offset_is_refused(tmp_path):
    path = write_vtp(tmp_path / "s.vtp", "ascii")
    text = open(path).read()
    start = text.index("<Polys")
    m = re.compile(r'(<DataArray[^>]*Name="connectivity"[^>]*>\s*)([^<]*?)(\s*<)').search(text, start)
    values = m.group(2).split()
    open(path, "w").write(text[:m.start(2)] + " ".join(values[:-2]) + text[m.end(2):])
    refused(path, "'connectivity'")


def test_appended_raw_data_cut_short_is_refused(tmp_path):
    path = write_vtp(tmp_path / "s.vtp", "raw")
    data = open(path, "rb").read()
    cut = data.index(b"_", data.index(b"<AppendedData")) + 1 + 200
    open(path, "wb").write(data[:cut])
    refused(path, "array")
