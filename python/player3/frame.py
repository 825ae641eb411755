"""Camera frames: numpy arrays that a notebook shows as pictures."""

import struct
import zlib

import numpy as np


class Frame(np.ndarray):
    """A camera frame: a height x width x 3 `uint8` RGB array (a plain numpy array in every
    other way) that Jupyter shows as a picture."""

    def _repr_png_(self):
        return rgb_png(np.asarray(self))


def rgb_png(rgb):
    """PNG bytes of a height x width x 3 `uint8` array (8-bit RGB, no filtering)."""
    rgb = np.ascontiguousarray(rgb, dtype=np.uint8)
    height, width, _ = rgb.shape
    rows = np.zeros((height, 1 + width * 3), dtype=np.uint8)  # each row: filter byte 0, pixels
    rows[:, 1:] = rgb.reshape(height, width * 3)

    def chunk(kind, data):
        crc = zlib.crc32(kind + data) & 0xFFFFFFFF
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
            + chunk(b"IDAT", zlib.compress(rows.tobytes())) + chunk(b"IEND", b""))
