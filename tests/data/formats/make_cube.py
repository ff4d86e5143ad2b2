#!/usr/bin/env python3
# SPDX-License-Identifier: Zlib
"""Writes the same cube (side 2, centred at the origin, 6 outward quads) as ascii, binary
little-endian and binary big-endian PLY, with extra properties and elements that a reader must
skip. cube.obj holds the same cube in OBJ's other face forms. CC0-1.0, part of btFracture's tests."""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
V = [((1 if i & 1 else -1), (1 if i & 2 else -1), (1 if i & 4 else -1)) for i in range(8)]
F = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]


def header(fmt, coord, count, index, extra_vertex):
    lines = ['ply', 'format %s 1.0' % fmt, 'comment cube for btFracture reader tests',
             'element vertex 8', 'property %s x' % coord, 'property %s y' % coord]
    if extra_vertex:
        lines.append('property uchar red')
    lines += ['property %s z' % coord, 'element face 6',
              'property list %s %s vertex_indices' % (count, index), 'property float quality',
              'element edge 1', 'property int vertex1', 'property int vertex2', 'end_header']
    return ('\n'.join(lines) + '\n').encode()


with open(os.path.join(HERE, 'cube_ascii.ply'), 'wb') as f:
    f.write(header('ascii', 'float', 'uchar', 'int', True))
    for x, y, z in V:
        f.write(b'%d %d 200 %d\n' % (x, y, z))
    for face in F:
        f.write(('4 %d %d %d %d 0.5\n' % face).encode())
    f.write(b'0 1\n')

with open(os.path.join(HERE, 'cube_binary_le.ply'), 'wb') as f:
    f.write(header('binary_little_endian', 'float', 'uchar', 'int', False))
    for v in V:
        f.write(struct.pack('<3f', *v))
    for face in F:
        f.write(struct.pack('<B4if', 4, *face, 0.5))
    f.write(struct.pack('<2i', 0, 1))

with open(os.path.join(HERE, 'cube_binary_be.ply'), 'wb') as f:
    f.write(header('binary_big_endian', 'double', 'int', 'uint', True))
    for x, y, z in V:
        f.write(struct.pack('>ddBd', x, y, 200, z))
    for face in F:
        f.write(struct.pack('>i4If', 4, *face, 0.5))
    f.write(struct.pack('>2i', 0, 1))
