#!/usr/bin/env python3
"""Checks that each PNG given is whole: signature, every chunk's CRC, IHDR first, IEND last, and
image data that inflates to exactly height x (1 + 3 x width) bytes (8-bit RGB, one filter byte a row)."""
import struct
import sys
import zlib


def check(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        return "no PNG signature"
    pos, chunks, idat = 8, [], b""
    while pos < len(data):
        if pos + 8 > len(data):
            return "truncated chunk header"
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if len(body) != length or pos + 12 + length > len(data):
            return "truncated %s chunk" % kind.decode("latin1")
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])
        if zlib.crc32(kind + body) != crc:
            return "bad CRC in %s" % kind.decode("latin1")
        chunks.append(kind)
        if kind == b"IDAT":
            idat += body
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
        pos += 12 + length
    if not chunks or chunks[0] != b"IHDR" or chunks[-1] != b"IEND":
        return "IHDR not first or IEND not last"
    if depth != 8 or colour != 2:
        return "not 8-bit RGB"
    if len(zlib.decompress(idat)) != height * (1 + 3 * width):
        return "image data of the wrong size"
    return None


bad = [(p, why) for p in sys.argv[1:] for why in [check(p)] if why]
for path, why in bad:
    print("%s: %s" % (path, why))
print("%d PNG files checked, %d broken" % (len(sys.argv) - 1, len(bad)))
sys.exit(1 if bad else 0)
