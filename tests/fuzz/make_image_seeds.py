#!/usr/bin/env python3
"""Writes the seed corpus of the image-reader fuzzer (tests/fuzz/image_seeds/): tiny segmented
images of each format the readers take, made here byte by byte (no real rock, no library): NumPy
.npy files of format 1 to 3 in several dtypes, byte orders and memory orders; raw volumes whose
first bytes describe them as image_reader_target.cpp reads them; TIFF files little- and
big-endian, classic and BigTIFF, several pages, strips and tiles, 1, 8, 16 and 32 bits, BlackIsZero
and WhiteIsZero, uncompressed, PackBits, LZW and Deflate (with the horizontal predictor). Each is a
few hundred bytes. Also the fuzzer's dictionary (tests/fuzz/image.dict). Usage:
make_image_seeds.py [SEED_DIR] (default: image_seeds next to this script)."""
import os
import struct
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def label(x, y, z, values=(0, 1)):
    """A small pattern with pores (label 0) that connect along some axes."""
    k = (x * 3 + y * 5 + z * 7) % 5
    return values[0] if k < 2 else values[1 + (k % (len(values) - 1))]


# --- NumPy ------------------------------------------------------------------------------------

def npy(descr, shape, fortran, values, version=1):
    fmt = {"u1": "B", "b1": "?", "i1": "b", "u2": "H", "i2": "h", "u4": "I", "i4": "i", "f4": "f"}[descr[1:]]
    order = ">" if descr[0] == ">" else "<"
    header = "{'descr': '%s', 'fortran_order': %s, 'shape': (%s), }" % (
        descr, "True" if fortran else "False", ", ".join(str(n) for n in shape) + ("," if len(shape) == 1 else ""))
    prefix = 10 if version == 1 else 12
    pad = (64 - (prefix + len(header) + 1) % 64) % 64
    header = (header + " " * pad + "\n").encode()
    head = b"\x93NUMPY" + bytes([version, 0])
    head += struct.pack("<H", len(header)) if version == 1 else struct.pack("<I", len(header))
    # Index [i][j][k] (x, y, z); C order: the last index fastest; Fortran: the first.
    dims = list(shape) + [1] * (3 - len(shape))
    data = []
    if fortran:
        for k in range(dims[2]):
            for j in range(dims[1]):
                for i in range(dims[0]):
                    data.append(label(i, j, k, values))
    else:
        for i in range(dims[0]):
            for j in range(dims[1]):
                for k in range(dims[2]):
                    data.append(label(i, j, k, values))
    if fmt == "?":
        data = [bool(v) for v in data]
    return head + header + struct.pack(order + fmt * len(data), *data)


# --- raw --------------------------------------------------------------------------------------

def raw_fitted():
    """uint8, xyz, 4 x 4 voxels a slice, no header: the first word is 0x00330000 (the target's
    fitted description), the voxels after it labels 0 and 1."""
    nx, ny, nz = 4, 4, 5
    body = [label(x, y, z) for z in range(nz) for y in range(ny) for x in range(nx)]
    body[0:4] = [0x00, 0x00, 0x33, 0x00]
    return bytes(body)


def raw_stated():
    """uint16 big-endian (as the target's stated description reads the first byte, 16), order
    xyz, 5 x 3 x 2 voxels after a header of 24 bytes that states it."""
    nx, ny, nz, header = 5, 3, 2, 24
    head = bytes([16, 0, 0, 0]) + struct.pack("<IIIH", nx, ny, nz, header)
    head += b"\0" * (header - len(head))
    body = [label(x, y, z, (0, 1, 300)) for z in range(nz) for y in range(ny) for x in range(nx)]
    return head + struct.pack(">" + "h" * len(body), *body)


# --- TIFF -------------------------------------------------------------------------------------

SHORT, LONG, LONG8 = 3, 4, 16
TYPE_FMT = {SHORT: "H", LONG: "I", LONG8: "Q"}
WIDTH, LENGTH, BITS, COMPRESSION, PHOTOMETRIC = 256, 257, 258, 259, 262
STRIP_OFFSETS, SAMPLES, ROWS_PER_STRIP, STRIP_BYTES, PLANAR = 273, 277, 278, 279, 284
PREDICTOR, TILE_WIDTH, TILE_LENGTH, TILE_OFFSETS, TILE_BYTES, SAMPLE_FORMAT = 317, 322, 323, 324, 325, 339


def packbits(row):
    out = bytearray()
    for at in range(0, len(row), 128):
        chunk = row[at:at + 128]
        out += bytes([len(chunk) - 1]) + chunk
    return bytes(out)


def lzw(data):
    """TIFF's LZW: 9 to 12 bit codes, most significant bit first, Clear first, EOI last."""
    bits, nbits, width = 0, 0, 9
    out = bytearray()

    def emit(code):
        nonlocal bits, nbits
        bits = bits << width | code
        nbits += width
        while nbits >= 8:
            nbits -= 8
            out.append(bits >> nbits & 0xff)

    table = {bytes([i]): i for i in range(256)}
    free = 258
    emit(256)
    w = b""
    for c in data:
        wc = w + bytes([c])
        if wc in table:
            w = wc
            continue
        emit(table[w])
        table[wc] = free
        free += 1
        if free > (1 << width) - 1 and width < 12:
            width += 1
        w = bytes([c])
    if w:
        emit(table[w])
    emit(257)
    if nbits:
        out.append(bits << (8 - nbits) & 0xff)
    return bytes(out)


def encode(block, compression, row_bytes):
    if compression == 1:
        return block
    if compression == 32773:
        return b"".join(packbits(block[r:r + row_bytes]) for r in range(0, len(block), row_bytes))
    if compression == 5:
        return lzw(block)
    return zlib.compress(block)  # 8: Adobe Deflate


def pack_samples(values, bits, bo):
    if bits == 1:
        out = bytearray((len(values) + 7) // 8)
        for k, v in enumerate(values):
            out[k // 8] |= (v & 1) << (7 - k % 8)
        return bytes(out)
    return struct.pack(bo + {8: "B", 16: "H", 32: "I"}[bits] * len(values), *values)


def predict(block, row_bytes):
    """Horizontal differencing of 8-bit samples, row by row (Predictor 2)."""
    out = bytearray(block)
    for r in range(0, len(block), row_bytes):
        for k in range(row_bytes - 1, 0, -1):
            out[r + k] = (block[r + k] - block[r + k - 1]) & 0xff
    return bytes(out)


def tiff_page(width, height, z, bits=8, values=(0, 1), bo="<", compression=1, photometric=1, rows_per_strip=None,
              tile=None, predictor=1):
    """One page's tags (without the data offsets) and its data blocks."""
    tags = {WIDTH: (LONG, [width]), LENGTH: (LONG, [height]), BITS: (SHORT, [bits]), COMPRESSION: (SHORT, [compression]),
            PHOTOMETRIC: (SHORT, [photometric]), SAMPLES: (SHORT, [1]), PLANAR: (SHORT, [1]), SAMPLE_FORMAT: (SHORT, [1])}
    if predictor != 1:
        tags[PREDICTOR] = (SHORT, [predictor])
    pixel = lambda x, y: label(x, y, z, values) if x < width and y < height else 0
    blocks = []
    if tile:
        tw, th = tile
        tags[TILE_WIDTH], tags[TILE_LENGTH] = (LONG, [tw]), (LONG, [th])
        row_bytes = (tw * bits + 7) // 8
        for y0 in range(0, height, th):
            for x0 in range(0, width, tw):
                block = b"".join(pack_samples([pixel(x0 + x, y0 + y) for x in range(tw)], bits, bo) for y in range(th))
                blocks.append(encode(block, compression, row_bytes))
        return tags, blocks, TILE_OFFSETS, TILE_BYTES
    rows = rows_per_strip or height
    tags[ROWS_PER_STRIP] = (LONG, [rows])
    row_bytes = (width * bits + 7) // 8
    for y0 in range(0, height, rows):
        block = b"".join(pack_samples([pixel(x, y) for x in range(width)], bits, bo) for y in range(y0, min(y0 + rows, height)))
        if predictor == 2:
            block = predict(block, row_bytes)
        blocks.append(encode(block, compression, row_bytes))
    return tags, blocks, STRIP_OFFSETS, STRIP_BYTES


def tiff(pages, bo="<", big=False):
    """A TIFF (or BigTIFF) of the pages: each page's data, then its directory and the values too
    long for an entry; the directories chained in page order."""
    off_fmt, count_fmt, entry_inline = ("Q", "Q", 8) if big else ("I", "H", 4)
    out = bytearray(b"II" if bo == "<" else b"MM")
    out += struct.pack(bo + "HHHQ", 43, 8, 0, 0) if big else struct.pack(bo + "HI", 42, 0)
    link = 8 if big else 4  # where the first directory's offset goes

    def align():
        if len(out) % 2:
            out.append(0)

    for tags, blocks, offsets_tag, counts_tag in pages:
        tags = dict(tags)
        offsets = []
        for b in blocks:
            align()
            offsets.append(len(out))
            out.extend(b)
        kind = LONG8 if big else LONG
        tags[offsets_tag] = (kind, offsets)
        tags[counts_tag] = (kind, [len(b) for b in blocks])
        entries = []
        for tag in sorted(tags):
            typ, vals = tags[tag]
            data = struct.pack(bo + TYPE_FMT[typ] * len(vals), *vals)
            if len(data) > entry_inline:
                align()
                at = len(out)
                out.extend(data)
                data = struct.pack(bo + off_fmt, at)
            entries.append(struct.pack(bo + "HH" + off_fmt, tag, typ, len(vals)) + data.ljust(entry_inline, b"\0"))
        align()
        struct.pack_into(bo + off_fmt, out, link, len(out))
        out += struct.pack(bo + count_fmt, len(entries)) + b"".join(entries)
        link = len(out)
        out += struct.pack(bo + off_fmt, 0)
    return bytes(out)


def seeds():
    s = {}
    s["c_uint8_4x3x2.npy"] = npy("|u1", (4, 3, 2), False, (0, 1))
    s["fortran_int16_be_3x3x3.npy"] = npy(">i2", (3, 3, 3), True, (0, 1, -2))
    s["v2_float32_5x4_2d.npy"] = npy("<f4", (5, 4), False, (0, 1, 2), version=2)
    s["v3_bool_2x3x2.npy"] = npy("|b1", (2, 3, 2), False, (0, 1), version=3)
    s["c_uint32_be_2x2x3.npy"] = npy(">u4", (2, 2, 3), False, (0, 70000))
    s["fortran_int8_3x2x2.npy"] = npy("|i1", (3, 2, 2), True, (0, -1, 5))
    s["fitted_uint8_4x4x5.raw"] = raw_fitted()
    s["stated_uint16_be_5x3x2.raw"] = raw_stated()
    s["le_3pages_8bit_strips.tif"] = tiff([tiff_page(8, 6, z, rows_per_strip=4) for z in range(3)])
    s["be_2pages_16bit.tif"] = tiff([tiff_page(6, 5, z, bits=16, values=(0, 1, 300), bo=">", rows_per_strip=2)
                                     for z in range(2)], bo=">")
    s["le_tiled_8bit_18x10.tif"] = tiff([tiff_page(18, 10, z, tile=(16, 16)) for z in range(1)])
    s["be_1bit_whiteiszero_2pages.tif"] = tiff([tiff_page(13, 7, z, bits=1, bo=">", photometric=0) for z in range(2)],
                                               bo=">")
    s["le_32bit_2pages.tif"] = tiff([tiff_page(4, 3, z, bits=32, values=(0, 70000)) for z in range(2)])
    s["le_packbits_2pages.tif"] = tiff([tiff_page(9, 4, z, compression=32773, rows_per_strip=2) for z in range(2)])
    s["be_lzw_16bit_2pages.tif"] = tiff([tiff_page(7, 5, z, bits=16, values=(0, 2, 9), bo=">", compression=5)
                                         for z in range(2)], bo=">")
    s["le_deflate_predictor_2pages.tif"] = tiff([tiff_page(10, 6, z, compression=8, predictor=2) for z in range(2)])
    s["bigtiff_le_2pages.tif"] = tiff([tiff_page(5, 4, z) for z in range(2)], big=True)
    s["bigtiff_be_tiled_16bit.tif"] = tiff([tiff_page(16, 16, 0, bits=16, bo=">", tile=(16, 16))], bo=">", big=True)
    return s


def dictionary():
    """libFuzzer's dictionary: NumPy's header words, TIFF's signatures and directory entries."""
    words = [b"\x93NUMPY\x01\x00", b"\x93NUMPY\x02\x00", b"\x93NUMPY\x03\x00", b"{'descr': ", b"'fortran_order': ",
             b"True", b"False", b"'shape': (", b"), }", b", ", b"\n"]
    words += [("'%s%s'" % (o, t)).encode() for o in "<>|=" for t in ("u1", "b1", "i1", "u2", "i2", "u4", "i4", "f4", "f8")]
    words += [b"II*\x00", b"MM\x00*", b"II+\x00\x08\x00\x00\x00", b"MM\x00+\x00\x08\x00\x00"]
    for bo in "<>":
        for tag, typ, value in [(WIDTH, LONG, 16), (LENGTH, LONG, 16), (BITS, SHORT, 8), (BITS, SHORT, 16),
                                (BITS, SHORT, 1), (BITS, SHORT, 32), (COMPRESSION, SHORT, 1), (COMPRESSION, SHORT, 5),
                                (COMPRESSION, SHORT, 8), (COMPRESSION, SHORT, 32773), (PHOTOMETRIC, SHORT, 0),
                                (PHOTOMETRIC, SHORT, 1), (SAMPLES, SHORT, 1), (ROWS_PER_STRIP, LONG, 1),
                                (PLANAR, SHORT, 1), (PREDICTOR, SHORT, 2), (TILE_WIDTH, LONG, 16),
                                (TILE_LENGTH, LONG, 16), (SAMPLE_FORMAT, SHORT, 1)]:
            value_bytes = struct.pack(bo + ("H" if typ == SHORT else "I"), value).ljust(4, b"\0")
            words.append(struct.pack(bo + "HHI", tag, typ, 1) + value_bytes)
        for tag in (STRIP_OFFSETS, STRIP_BYTES, TILE_OFFSETS, TILE_BYTES):
            words.append(struct.pack(bo + "HH", tag, LONG))
    lines = ["# The image-reader fuzzer's dictionary (written by make_image_seeds.py)."]
    for k, w in enumerate(words):
        lines.append('w%d="%s"' % (k, "".join("\\x%02x" % c for c in w)))
    return "\n".join(lines) + "\n"


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "image_seeds")
    os.makedirs(out, exist_ok=True)
    for name, data in sorted(seeds().items()):
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)
        print("%6d %s" % (len(data), name))
    with open(os.path.join(HERE, "image.dict"), "w") as f:
        f.write(dictionary())


if __name__ == "__main__":
    main()
