#!/usr/bin/python3
"""Writes the tiny pattern and stamp inputs of the same-bits cases into this
folder (they are stored beside the scripts; run this only to remake them).

grey.png  16x16 8-bit grey: a soft disc with a notch (stamp, image pattern)
rgb.png   8x8 8-bit RGB: colour ramps (image pattern: shade by colour,
          matte by luminance)
rgba.png  8x8 8-bit RGBA: ramps with an alpha checker (image pattern, stamp)
volume.vti 4x4x4 unsigned char voxels, ASCII VTK XML image data (volume pattern)
"""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def png(path, width, height, channels, pixel):
    colour_type = {1: 0, 3: 2, 4: 6}[channels]
    rows = b"".join(b"\0" + bytes(v for x in range(width) for v in pixel(x, y)) for y in range(height))

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(rows, 9)))
        f.write(chunk(b"IEND", b""))


def grey(x, y):
    d2 = (x - 7.5) ** 2 + (y - 7.5) ** 2
    v = max(0, 255 - int(d2 * 4)) if not (x > 9 and 6 <= y <= 9) else 0
    return (v,)


def rgb(x, y):
    return (x * 36, y * 36, 255 - (x + y) * 18)


def rgba(x, y):
    return (255 - x * 30, 40 + y * 25, 128, 255 if (x // 2 + y // 2) % 2 == 0 else 96)


def vti(path, n=4):
    values = [(i * 37 + j * 11 + k * 53) % 256 for k in range(n) for j in range(n) for i in range(n)]
    text = " ".join(str(v) for v in values)
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n'
                '<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">\n'
                f'  <ImageData WholeExtent="0 {n-1} 0 {n-1} 0 {n-1}" Origin="0 0 0" Spacing="1 1 1">\n'
                f'    <Piece Extent="0 {n-1} 0 {n-1} 0 {n-1}">\n'
                '      <PointData Scalars="density">\n'
                f'        <DataArray type="UInt8" Name="density" format="ascii">{text}</DataArray>\n'
                '      </PointData>\n'
                '    </Piece>\n'
                '  </ImageData>\n'
                '</VTKFile>\n')


if __name__ == "__main__":
    png(os.path.join(HERE, "grey.png"), 16, 16, 1, grey)
    png(os.path.join(HERE, "rgb.png"), 8, 8, 3, rgb)
    png(os.path.join(HERE, "rgba.png"), 8, 8, 4, rgba)
    vti(os.path.join(HERE, "volume.vti"))
