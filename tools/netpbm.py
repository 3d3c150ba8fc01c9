# netpbm.py - reads the binary netpbm images rt writes: P6 (RGB, maxval 255) and P5
# (16-bit object IDs from --ids, maxval 65535). Shared by the tools and the test scripts.
# See LICENSE for copyright and licence.


def parse_netpbm(data, magic, maxval, channels):
    """Returns (width, height, sample bytes) of binary netpbm image bytes of this kind."""
    fields, pos = [], 0
    while len(fields) < 4:
        # Header tokens are separated by whitespace; '#' starts a comment line.
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        start = pos
        while pos < len(data) and not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    pos += 1  # exactly one whitespace byte before the samples
    if fields[0] != magic or int(fields[3]) != maxval:
        raise ValueError("not a %s image with maxval %d" % (magic.decode(), maxval))
    width, height = int(fields[1]), int(fields[2])
    size = channels * width * height * (2 if maxval > 255 else 1)
    samples = data[pos:]
    if len(samples) != size:
        raise ValueError("%d bytes of samples, expected %d" % (len(samples), size))
    return width, height, samples


def read_netpbm(path, magic, maxval, channels):
    """The same for an image file."""
    with open(path, "rb") as f:
        return parse_netpbm(f.read(), magic, maxval, channels)


def read_ppm(path):
    """(width, height, RGB bytes) of a P6 PPM with maxval 255."""
    return read_netpbm(path, b"P6", 255, 3)


def read_ids(path):
    """(width, height, big-endian 16-bit samples) of an --ids PGM."""
    return read_netpbm(path, b"P5", 65535, 1)
