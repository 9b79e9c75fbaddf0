"""Read and write PGM (portable grey map) images without any imaging library.

Reads binary P5 and plain (ASCII) P2 with any maxval up to 65535 (16-bit P5 is
big-endian, as the Netpbm format says); writes 8-bit P5, the format map_saver uses.
"""

import numpy as np

MAGICS = (b"P5", b"P2")


class PgmError(ValueError):
    """The bytes are not a PGM image this module can read."""


def is_pgm(head):
    """True when `head` (the first bytes of a file) starts like a P5 or P2 image."""
    return head[:2] in MAGICS


def _header_tokens(data, count, pos):
    """Read `count` whitespace-separated tokens from `pos`, skipping '#' comments.

    Returns the tokens and the position just after the last token.
    """
    tokens = []
    size = len(data)
    while len(tokens) < count:
        while pos < size and data[pos : pos + 1].isspace():
            pos += 1
        if pos < size and data[pos : pos + 1] == b"#":
            end = data.find(b"\n", pos)
            pos = size if end < 0 else end + 1
            continue
        start = pos
        while pos < size and not data[pos : pos + 1].isspace() and data[pos : pos + 1] != b"#":
            pos += 1
        if start == pos:
            raise PgmError("header ends early (expected width, height and maxval)")
        tokens.append(data[start:pos])
    return tokens, pos


def _positive_int(token, what):
    try:
        value = int(token)
    except ValueError:
        raise PgmError(f"{what} is not a number: {token[:20]!r}") from None
    if value <= 0:
        raise PgmError(f"{what} must be positive, got {value}")
    return value


def parse_pgm(data):
    """Decode PGM bytes; returns (pixels as a (height, width) array, maxval).

    The array is uint8 when maxval < 256, else uint16. Row 0 is the top of the image.
    """
    if not is_pgm(data):
        raise PgmError("not a P5/P2 PGM image (bad magic number)")
    magic = data[:2]
    (w_tok, h_tok, max_tok), pos = _header_tokens(data, 3, 2)
    width = _positive_int(w_tok, "width")
    height = _positive_int(h_tok, "height")
    maxval = _positive_int(max_tok, "maxval")
    if maxval > 65535:
        raise PgmError(f"maxval {maxval} is above 65535")
    dtype = np.uint8 if maxval < 256 else np.uint16
    count = width * height
    if magic == b"P5":
        if pos >= len(data) or not data[pos : pos + 1].isspace():
            raise PgmError("no whitespace between header and pixel data")
        pos += 1  # exactly one whitespace byte separates the header from the raster
        bytes_per = 1 if maxval < 256 else 2
        raster = data[pos : pos + count * bytes_per]
        if len(raster) < count * bytes_per:
            raise PgmError(
                f"truncated pixel data: {len(raster)} bytes for a {width}x{height} image "
                f"(expected {count * bytes_per})"
            )
        pixels = np.frombuffer(raster, dtype=">u2" if bytes_per == 2 else np.uint8)
    else:
        text = b"\n".join(line.split(b"#", 1)[0] for line in data[pos:].splitlines())
        words = text.split()
        if len(words) < count:
            raise PgmError(f"truncated pixel data: {len(words)} values for {width}x{height}")
        try:
            pixels = np.array([int(w) for w in words[:count]], dtype=np.int64)
        except ValueError:
            raise PgmError("plain PGM pixel data holds a non-number") from None
    if pixels.size and int(pixels.max()) > maxval:
        raise PgmError(f"a pixel value exceeds maxval {maxval}")
    return pixels.astype(dtype).reshape(height, width), maxval


def read_pgm(path):
    with open(path, "rb") as handle:
        return parse_pgm(handle.read())


def encode_pgm(pixels, comment=None):
    """Encode a (height, width) uint8 array as binary P5 bytes (row 0 first)."""
    pixels = np.asarray(pixels)
    if pixels.ndim != 2 or pixels.dtype != np.uint8:
        raise ValueError("encode_pgm needs a 2-D uint8 array")
    height, width = pixels.shape
    header = "P5\n"
    if comment:
        header += "# " + comment.replace("\n", " ") + "\n"
    header += f"{width} {height}\n255\n"
    return header.encode("ascii") + np.ascontiguousarray(pixels).tobytes()
