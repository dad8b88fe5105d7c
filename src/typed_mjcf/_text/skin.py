"""MuJoCo's binary skin files (``.skn``) name the bodies their bones follow: in an attached
model those names take the model's scope, so its skin file is rewritten to match."""

from __future__ import annotations

import struct

from typed_mjcf._core.errors import ExportError

NAME_BYTES = 40  # a bone's body name, NUL-padded (MuJoCo's skin file format)


def scope_bone_names(contents: bytes, prefix: str, where: str) -> bytes:
    """``contents`` with every bone's body name prefixed by ``prefix`` (``arm/``)."""
    try:
        nvertex, ntexcoord, nface, nbone = struct.unpack_from("<iiii", contents, 0)
        offset = 16 + 4 * (3 * nvertex + 2 * ntexcoord + 3 * nface)
        out = bytearray(contents[:offset])
        for _ in range(nbone):
            name = contents[offset:offset + NAME_BYTES].split(b"\0", 1)[0]
            scoped = prefix.encode("utf-8") + name
            if len(scoped) > NAME_BYTES:
                raise ExportError(f"{where}: the bone body name {scoped.decode()!r} is longer "
                                  f"than the {NAME_BYTES} bytes a skin file allows")
            out += scoped.ljust(NAME_BYTES, b"\0")
            offset += NAME_BYTES
            (count,) = struct.unpack_from("<i", contents, offset + 28)
            end = offset + 28 + 4 + 8 * count  # bind pos, bind quat, count, ids, weights
            out += contents[offset:end]
            offset = end
        if offset != len(contents):
            raise ValueError("trailing bytes")
        return bytes(out)
    except (struct.error, ValueError) as error:
        raise ExportError(f"{where}: cannot read the skin file to scope its bone names "
                          f"({error})") from None
