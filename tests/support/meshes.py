"""Small mesh files made at test time: a box as binary STL, a tetrahedron as OBJ text."""

from __future__ import annotations

import struct


def box_stl(size: float = 0.1) -> bytes:
    """A closed box as binary STL: 12 triangles."""
    s = size
    corners = [(x, y, z) for x in (-s, s) for y in (-s, s) for z in (-s, s)]
    faces = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
             (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    data = b"\0" * 80 + struct.pack("<I", len(faces))
    for face in faces:
        data += struct.pack("<3f", 0, 0, 0)
        for i in face:
            data += struct.pack("<3f", *corners[i])
        data += b"\0\0"
    return data


def tetra_obj(x: float, y: float, z: float) -> bytes:
    """A tetrahedron as OBJ text."""
    return (f"v 0 0 0\nv {x} 0 0\nv 0 {y} 0\nv 0 0 {z}\n"
            "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n").encode()
