#!/usr/bin/env python3
"""Writes the TLM fuzz target's seed corpus (fuzz/corpus/fuzz_tlm/): per wrapper, the accesses the
wrapper tests make (testbenches/tlm), encoded as fuzz_tlm.cpp decodes its input. Rerun after
changing that encoding; the files are committed."""
import os
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "fuzz_tlm")
READ, WRITE, IGNORE = 0, 1, 2
SPECULAR = ["ua60553_lt", "ua22802_lt", "tuned_lt", "squared_lt"]
LINE = ["line5_lt", "line3_lt"]
PIN_SPECULAR = ["ua60553_pa", "ua22802_pa", "tuned_pa", "squared_pa"]
PIN_LINE = ["line5_pa"]
SQMUL = ["sqmul_lt", "sqmul_pa"]  # appended to fuzz_tlm.cpp's list, so the other seeds keep their targets
ORDER = SPECULAR + LINE + PIN_SPECULAR + PIN_LINE + SQMUL


def op(cmd, region, offset, length=None, units=None, debug=False, sw=None, be=False, fix=False, delay=0, seed=1):
    """One access: region 0 registers, 1 the first window, 2 the second; length in bytes (u16) or
    units (granules, 1..256)."""
    sel = (cmd << 3) | (7 if debug else 0)
    am = (region << 3) | 4 | 1
    if units is not None:
        lm, tail = 1, bytes([units - 1])
    elif length is None:
        lm, tail = 0, b""
    else:
        lm, tail = 2, struct.pack("<H", length)
    if sw is not None:
        lm |= 0x10
        tail += struct.pack("<I", sw)
    if be:
        lm |= 0xC0
    if fix:
        lm |= 0x20
    return bytes([sel, am, lm]) + struct.pack("<H", offset) + tail + bytes([delay]) + struct.pack("<H", seed)


def raw(cmd, addr, length):
    return bytes([cmd << 3, 0, 3]) + struct.pack("<Q", addr) + struct.pack("<I", length) + bytes([0]) + b"\1\0"


def write(name, target, ops):
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(bytes([ORDER.index(target)]) + b"".join(ops))


os.makedirs(OUT, exist_ok=True)
for t in SPECULAR + PIN_SPECULAR:
    write(f"{t}_pixel", t, [op(WRITE, 0, 0x000, seed=20), op(WRITE, 0, 0x004, seed=200), op(WRITE, 0, 0x010, seed=3),
                            op(READ, 0, 0x014), op(READ, 0, 0x020), op(READ, 0, 0x024)])
    write(f"{t}_line", t, [op(WRITE, 0, 0x000, seed=120), op(WRITE, 1, 0, length=64, seed=7),
                           op(READ, 2, 0, length=512), op(READ, 2, 0, units=1, debug=True)])
    write(f"{t}_errors", t, [op(READ, 0, 0x014), op(WRITE, 0, 0x014), op(READ, 0, 0x002), op(READ, 1, 0, length=3),
                             op(READ, 0, 0x000, be=True), op(READ, 0, 0x000, sw=2), op(IGNORE, 0, 0x000),
                             raw(READ, 0x8000, 4), raw(READ, 0x17FE, 4), op(WRITE, 0, 0x024, seed=0x8000),
                             op(READ, 0, 0x020)])
for t in LINE + PIN_LINE:
    write(f"{t}_burst", t, [op(WRITE, 1, 0, length=64, fix=True, seed=11), op(READ, 2, 0, length=64),
                            op(READ, 0, 0x000), op(READ, 0, 0x004)])
    write(f"{t}_errors", t, [op(WRITE, 1, 0, length=16, seed=5), op(WRITE, 0, 0x000), op(READ, 2, 0, length=0x4000),
                             op(READ, 1, 8, length=16), op(READ, 0, 0, be=True), raw(READ, 0x20000, 4),
                             op(WRITE, 0, 0x004, seed=0x8000), op(READ, 0, 0, debug=True, length=8)])
print("wrote", len(os.listdir(OUT)), "seeds to", OUT)
