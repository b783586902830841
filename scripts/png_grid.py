#!/usr/bin/env python3
"""Puts same-sized PNGs (RGB or RGBA, 8 bit) in a grid, left to right, top to
bottom (alpha dropped, empty cells white), and writes an RGB PNG; python3's
standard library only.

    scripts/png_grid.py OUT.png COLUMNS IN.png...
"""
import struct, sys, zlib

def read_png(path):
    data = open(path, 'rb').read()
    pos, idat = 8, b''
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            w, h, depth, colour = struct.unpack('>IIBB', chunk[:10])
        elif kind == b'IDAT':
            idat += chunk
        pos += 12 + n
    assert depth == 8 and colour in (2, 6), path
    bpp = 3 if colour == 2 else 4
    raw, stride, rows, prev, k = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp), 0
    for _ in range(h):
        f, line = raw[k], bytearray(raw[k + 1:k + 1 + stride])
        k += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b, c = prev[x], (prev[x - bpp] if x >= bpp else 0)
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line[i] for i in range(stride) if i % bpp < 3))  # drop alpha
        prev = line
    return w, h, rows

out, columns, paths = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
images = [read_png(p) for p in paths]
w, h = images[0][0], images[0][1]
grid_rows = (len(images) + columns - 1) // columns
W, H = w * columns, h * grid_rows
lines = []
for gy in range(grid_rows):
    for y in range(h):
        row = b''
        for gx in range(columns):
            i = gy * columns + gx
            row += images[i][2][y] if i < len(images) else b'\xff' * (3 * w)
        lines.append(b'\x00' + row)
def chunk(kind, body):
    return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body) & 0xffffffff)
png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', W, H, 8, 2, 0, 0, 0))
png += chunk(b'IDAT', zlib.compress(b''.join(lines), 9)) + chunk(b'IEND', b'')
open(out, 'wb').write(png)
