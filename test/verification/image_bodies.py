#!/usr/bin/env python3
"""Bodies from images (Shape = image): orientation, gray-level ranges, particles per pixel,
8-bit PNG and 16-bit TIFF, and the refusals (doc/verification/geometry.md).

Writes its own small images with a PNG and a TIFF writer of a few lines each (standard
library only: zlib, struct), so the reader is checked against files it did not write:

- an L-shaped 8-bit PNG, asymmetric: the particles must sit where an image viewer shows
  the L (row 0 at the top), with the volume of the selected pixels;
- a 16-bit TIFF with two gray levels read by two bodies: each particle's body follows its
  pixel's level;
- Particles Per Pixel = 2: 4 particles per pixel whose domains tile it exactly;
- a colour PNG, a truncated PNG, a missing file and a range with no pixel: each a one-line
  `impm: error:` naming the file and the reason, and no output.
"""

import argparse
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

from impmrun import run_deck

# 6 x 5 pixels (columns x rows), row 0 at the top: an L whose foot points right.
L_SHAPE = ["#.....",
           "#.....",
           "#.....",
           "#.....",
           "####.."]


def write_png(path, width, height, raw, bits=8, colour=False):
    """Writes a PNG from its raw scanlines (each a filter byte 0, then the samples)."""
    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data
                + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))

    kind = 2 if colour else 0
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, bits, kind, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw)))
        f.write(chunk(b"IEND", b""))


def png(path, rows, bits=8, colour=False):
    """Writes rows of levels as a grayscale (or RGB) PNG without filtering."""
    raw = b""
    for row in rows:
        raw += b"\0"
        for v in row:
            sample = struct.pack(">H", v) if bits == 16 else bytes([v])
            raw += sample * (3 if colour else 1)
    write_png(path, len(rows[0]), len(rows), raw, bits, colour)


def tiff16(path, rows, sample_format=1):
    """Writes rows of 16-bit levels as a little-endian, uncompressed, one-strip TIFF
    (sample_format: 1 unsigned, 2 signed, 3 floating-point)."""
    tiff16_pages(path, [rows], sample_format)


def tiff16_pages(path, pages, sample_format=1):
    """The same with a page for each image of pages: the images' strips first, then their
    directories one after the other, each naming the next."""
    strips = [b"".join(struct.pack("<%dH" % len(rows[0]), *row) for row in rows) for rows in pages]
    entries = 10
    size = 2 + 12 * entries + 4
    first = 8 + sum(len(s) for s in strips)
    out, at, ifds = b"II*\0" + struct.pack("<I", first), 8, b""
    for k, (rows, data) in enumerate(zip(pages, strips)):
        height, width = len(rows), len(rows[0])
        fields = [(256, 3, 1, width), (257, 3, 1, height), (258, 3, 1, 16), (259, 3, 1, 1),
                  (262, 3, 1, 1), (273, 4, 1, at), (277, 3, 1, 1), (278, 3, 1, height),
                  (279, 4, 1, len(data)), (339, 3, 1, sample_format)]
        ifds += struct.pack("<H", entries)
        for tag, kind, count, value in fields:
            ifds += struct.pack("<HHI", tag, kind, count) + (
                struct.pack("<HH", value, 0) if kind == 3 else struct.pack("<I", value))
        ifds += struct.pack("<I", first + (k + 1) * size if k + 1 < len(pages) else 0)
        out += data
        at += len(data)
    with open(path, "wb") as f:
        f.write(out + ifds)


def deck(path, bodies, cells=(8, 8)):
    """A static deck with no loads on a 4 x 4 (x 4: three cell counts) domain and the given
    image bodies."""
    # One material per body (E = 100, 200, ...): a particle's body is its material.
    materials = "".join(
        '<ParameterList name="%s"><Parameter name="Model" type="string" value="linear-elastic"/>'
        '<Parameter name="E" type="double" value="%d"/><Parameter name="nu" type="double" '
        'value="0.3"/></ParameterList>' % (name, 100 * (k + 1)) for k, name in enumerate(bodies))
    text = ['<ParameterList name="impm">',
            '<ParameterList name="Discretization"><Parameter name="Method" type="string" '
            'value="cpdi"/></ParameterList>',
            '<ParameterList name="Grid"><Parameter name="Cells" type="Array(int)" '
            'value="{%s}"/><Parameter name="Length" type="Array(double)" '
            'value="{%s}"/></ParameterList>' % (", ".join(str(n) for n in cells),
                                                 ", ".join("4.0" for _ in cells)),
            '<ParameterList name="Materials">%s</ParameterList>' % materials,
            '<ParameterList name="Bodies">']
    for name, params in bodies.items():
        text.append('<ParameterList name="%s"><Parameter name="Material" type="string" '
                    'value="%s"/><Parameter name="Shape" type="string" value="image"/>'
                    % (name, name))
        for key, (kind, value) in params.items():
            text.append('<Parameter name="%s" type="%s" value="%s"/>' % (key, kind, value))
        text.append('</ParameterList>')
    text += ['</ParameterList>',
             '<ParameterList name="Time Integration"><Parameter name="Type" type="string" '
             'value="static"/><Parameter name="Load Steps" type="int" value="1"/>'
             '</ParameterList>', '</ParameterList>']
    with open(path, "w") as f:
        f.write("\n".join(text) + "\n")


def image_body(file, lo, hi, per_pixel=1, origin="{1.0, 1.0}", pixel=0.25):
    return {"Image File": ("string", file), "Pixel Size": ("double", pixel),
            "Image Origin": ("Array(double)", origin), "Gray Range": ("Array(int)", "{%d, %d}" % (lo, hi)),
            "Particles Per Pixel": ("int", per_pixel)}


def particles(impm, path):
    out = run_deck(impm, path, [], "impm-image-")
    rows = out.table("_particles.csv")
    out.remove()
    return rows


def expect_error(impm, path, words, failures):
    out = tempfile.mkdtemp(prefix="impm-image-bad-", dir=".")
    r = subprocess.run([impm, "--output-dir", out, path], capture_output=True, text=True)
    written = os.listdir(out)
    shutil.rmtree(out)
    lines = [l for l in (r.stdout + r.stderr).splitlines() if l.startswith("impm: error:")]
    ok = r.returncode != 0 and len(lines) == 1 and all(w in lines[0] for w in words) and not written
    print("%s: %s" % ("ok" if ok else "FAIL", lines[0] if lines else (r.stdout + r.stderr).strip()))
    if not ok:
        failures.append("%s: expected one error with %s and no output (exit %d, files %s)"
                        % (os.path.basename(path), words, r.returncode, written))


def finish(work, failures):
    """Removes the work directory, prints the failures and exits with their verdict."""
    shutil.rmtree(work)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    args = p.parse_args()
    work = tempfile.mkdtemp(prefix="impm-images-", dir=".")
    failures = []
    h = 0.25

    # The L: pixel (row, column) is [1 + c h, 1 + (c + 1) h] x [1 + (4 - r) h, 1 + (5 - r) h].
    png(os.path.join(work, "l.png"), [[200 if ch == "#" else 0 for ch in row] for row in L_SHAPE])
    deck(os.path.join(work, "l.xml"), {"l": image_body("l.png", 100, 255)})
    got = sorted((round(float(q["X"]), 9), round(float(q["Y"]), 9)) for q in particles(args.impm, os.path.join(work, "l.xml")))
    want = sorted((round(1 + (c + 0.5) * h, 9), round(1 + (4 - r + 0.5) * h, 9))
                  for r, row in enumerate(L_SHAPE) for c, ch in enumerate(row) if ch == "#")
    print("L shape: %d particles, %s" % (len(got), "right way up" if got == want else "WRONG"))
    if got != want:
        failures.append("the L's particles are not where the image shows them: %s" % got)

    # Two materials in one 16-bit TIFF: levels 1000 (left half) and 40000 (right half).
    levels = [[1000 if c < 3 else 40000 for c in range(6)] for _ in range(4)]
    tiff16(os.path.join(work, "two.tif"), levels)
    deck(os.path.join(work, "two.xml"), {"soft": image_body("two.tif", 500, 1500),
                                          "hard": image_body("two.tif", 30000, 50000)})
    rows = particles(args.impm, os.path.join(work, "two.xml"))
    # body 0 is "soft" (the deck's first body), body 1 "hard".
    wrong = [q for q in rows if (float(q["X"]) < 1 + 3 * h) != (float(q["body"]) == 0)]
    print("two materials: %d particles, %d in the wrong body" % (len(rows), len(wrong)))
    if len(rows) != 24 or wrong:
        failures.append("two-material TIFF: %d particles, %d in the wrong body" % (len(rows), len(wrong)))

    # Particles Per Pixel = 2: 4 per pixel, domains tiling each pixel.
    deck(os.path.join(work, "ppp.xml"), {"l": image_body("l.png", 100, 255, per_pixel=2)})
    rows = particles(args.impm, os.path.join(work, "ppp.xml"))
    pixels = sum(row.count("#") for row in L_SHAPE)
    volume = sum(float(q["volume"]) for q in rows)
    tiles = all(abs(float(q["r1_x"]) - h / 4) < 1e-14 and abs(float(q["r2_y"]) - h / 4) < 1e-14
                and float(q["r1_y"]) == 0 and float(q["r2_x"]) == 0 for q in rows)
    print("2 per pixel: %d particles for %d pixels, volume %.15g (pixels %.15g), domains %s"
          % (len(rows), pixels, volume, pixels * h * h, "tile the pixels" if tiles else "WRONG"))
    if len(rows) != 4 * pixels or abs(volume - pixels * h * h) > 1e-14 or not tiles:
        failures.append("Particles Per Pixel = 2 does not tile the pixels")

    # Refusals.
    png(os.path.join(work, "rgb.png"), [[50] * 4] * 4, colour=True)
    deck(os.path.join(work, "rgb.xml"), {"b": image_body("rgb.png", 0, 255)})
    expect_error(args.impm, os.path.join(work, "rgb.xml"), ["rgb.png", "colour"], failures)
    with open(os.path.join(work, "l.png"), "rb") as f:
        data = f.read()
    with open(os.path.join(work, "cut.png"), "wb") as f:
        f.write(data[: len(data) // 2])
    deck(os.path.join(work, "cut.xml"), {"b": image_body("cut.png", 100, 255)})
    expect_error(args.impm, os.path.join(work, "cut.xml"), ["cut.png", "PNG"], failures)
    # Signed and floating-point samples were read as unsigned levels.
    for name, sample_format, kind in (("signed", 2, "signed integer"), ("float", 3, "floating-point")):
        tiff16(os.path.join(work, name + ".tif"), levels, sample_format)
        deck(os.path.join(work, name + ".xml"), {"b": image_body(name + ".tif", 500, 1500)})
        expect_error(args.impm, os.path.join(work, name + ".xml"),
                     [name + ".tif", "has %s samples; impm reads unsigned" % kind], failures)
    deck(os.path.join(work, "missing.xml"), {"b": image_body("none.png", 100, 255)})
    expect_error(args.impm, os.path.join(work, "missing.xml"), ["none.png", "the image file does not exist"], failures)
    deck(os.path.join(work, "empty.xml"), {"b": image_body("l.png", 1, 99)})
    expect_error(args.impm, os.path.join(work, "empty.xml"),
                 ["Bodies/b/Gray Range", "no pixel", "l.png"], failures)
    deck(os.path.join(work, "outside.xml"), {"b": image_body("l.png", 100, 255, origin="{3.5, 1.0}")})
    expect_error(args.impm, os.path.join(work, "outside.xml"), ["Bodies/b/Image Origin"], failures)

    finish(work, failures)


if __name__ == "__main__":
    main()
