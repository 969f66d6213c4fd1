"""crops.py - side-by-side crops of PNG images, enlarged, for looking at an artefact beside
the truth (issue 44's before/after/truth crops). Pure Python (zlib): 8-bit RGB or RGBA PNGs
as `ssgraph extract` writes them.

  python3 bench/crops.py OUT.png X Y W H SCALE A.png B.png [C.png ...]
"""
import struct
import sys
import zlib


def read_png(path):
    """(width, height, rows of RGB bytes) of an 8-bit, non-interlaced grey/RGB/RGBA PNG."""
    data = open(path, "rb").read()
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
            assert depth == 8, "8-bit PNGs only"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    bpp = {0: 1, 2: 3, 6: 4}[ctype]
    raw, rows, prev = zlib.decompress(idat), [], bytearray(w * bpp)
    for y in range(h):
        f = raw[y * (w * bpp + 1)]
        line = bytearray(raw[y * (w * bpp + 1) + 1:(y + 1) * (w * bpp + 1)])
        for i in range(len(line)):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        prev = line
        rgb = bytearray()
        for x in range(w):
            px = line[x * bpp:(x + 1) * bpp]
            rgb += bytes(px[:1]) * 3 if bpp == 1 else bytes(px[:3])
        rows.append(rgb)
    return w, h, rows


def write_png(path, w, h, rows):
    raw = b"".join(b"\0" + bytes(r) for r in rows)
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(
            ">I", zlib.crc32(kind + body) & 0xffffffff)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    out, x0, y0, cw, ch, s = sys.argv[1], *map(int, sys.argv[2:7])
    images = [read_png(p)[2] for p in sys.argv[7:]]
    gap = 4
    width = len(images) * cw * s + gap * (len(images) - 1)
    rows = []
    for y in range(ch * s):
        row = bytearray()
        for k, img in enumerate(images):
            src = img[y0 + y // s]
            for x in range(cw * s):
                i = 3 * (x0 + x // s)
                row += src[i:i + 3]
            if k + 1 < len(images):
                row += b"\xff\xff\xff" * gap
        rows.append(row)
    write_png(out, width, ch * s, rows)


if __name__ == "__main__":
    main()
