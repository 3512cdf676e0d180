"""A minimal PNG encoder (8-bit RGB, no interlace: signature, IHDR, one IDAT, IEND), for the
textures the scenes embed (Python 3 stdlib only)."""

import struct
import zlib


def png_rgb(width, height, pixel):
    """pixel(x, y) -> (r, g, b) bytes, row 0 at the top."""
    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))

    raw = bytearray()
    for y in range(height):
        raw.append(0)  # filter type 0 (None) for every scanline
        for x in range(width):
            raw.extend(pixel(x, y))
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr)
            + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b""))


def checkerboard_png(n=4, light=255, dark=128):
    """n x n checkerboard; texel (0, 0) (top-left, glTF uv (0, 0)) is the light one.
    sRGB 255 decodes to linear 1.0, sRGB 128 to linear 0.2158605."""
    return png_rgb(n, n, lambda x, y: (light,) * 3 if (x + y) % 2 == 0 else (dark,) * 3)
