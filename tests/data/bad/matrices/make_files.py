#!/usr/bin/env python3
"""Writes the bad RADIANCE matrices of this folder (README.md says what each one tests).
Run from this folder; the files are committed, this script says how they were made."""
import gzip
import os
import struct


def header(rows, cols, fmt="ascii", big_endian=None, comp=3):
    h = "#?RADIANCE\nbad input for tests/cli/run_bad_inputs.sh\n"
    h += f"NROWS={rows}\nNCOLS={cols}\nNCOMP={comp}\n"
    if big_endian is not None:
        h += f"BigEndian={big_endian}\n"
    return h + f"FORMAT={fmt}\n\n"


def ascii_rows(values):
    """values: list of rows, each a list of (r, g, b) strings."""
    return "".join("".join(f"{r} {g} {b}\n" for r, g, b in row) + "\n" for row in values)


def write(name, data):
    with open(name, "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)


ok = ("0.5", "0.6", "0.7")
write("sky_nan.mtx", header(2, 2) + ascii_rows([[ok, ok], [ok, ("0.5", "nan", "0.7")]]))
write("sky_inf.mtx", header(2, 2) + ascii_rows([[ok, ("inf", "0", "0")], [ok, ok]]))
write("sky_beyond_float.mtx", header(2, 2) + ascii_rows([[ok, ok], [("1e39", "1", "1"), ok]]))
write("sky_data_after.mtx", header(2, 2) + ascii_rows([[ok, ok], [ok, ok]]) + "0.5 0.6 0.7\n")
# 7 KB of values under a header claiming 4.9 million rows (8.4 GB as floats).
write("sky_claims_4900000_rows.mtx", header(4900000, 146) + ascii_rows([[ok] * 146] * 4))
# Big-endian floats under a header that says little-endian (BigEndian=0).
values = [0.0, 0.0, 0.0, 1.25, 25.3, 3.14159] * 2
write("sky_byte_swapped.mtx", header(2, 2, "float", 0).encode() + struct.pack(">12f", *values))
# gzip: the NaN file compressed; a plain file named .gz; a truncated gzip; padding that
# decompresses to 1 MB (run with a 100 KB limit).
write("sky_nan.mtx.gz", gzip.compress(open("sky_nan.mtx", "rb").read(), mtime=0))
write("sky_not_gzip.mtx.gz", header(1, 1) + "1 1 1\n")
write("sky_truncated.mtx.gz", gzip.compress((header(2, 2) + ascii_rows([[ok, ok], [ok, ok]])).encode(), mtime=0)[:40])
write("sky_padding_bomb.mtx.gz", gzip.compress((header(1, 1) + " " * 1_000_000 + "1 1 1\n").encode(), 9, mtime=0))

# Coefficient folders (coefficients_sky.mtx + sensors.csv): one sensor, Tregenza columns.
def grid(folder, matrix):
    os.makedirs(folder, exist_ok=True)
    write(os.path.join(folder, "coefficients_sky.mtx"), matrix)
    write(os.path.join(folder, "sensors.csv"), "index,x,y,z,nx,ny,nz\n0,1,1,0.8,0,0,1\n")


row = [("0.001", "0.001", "0.001")] * 146
grid("nan_coefficients", header(1, 146) + ascii_rows([row[:40] + [("0.001", "NaN", "0.001")] + row[41:]]))
grid("negative_coefficients", header(1, 146) + ascii_rows([row[:7] + [("0.001", "0.001", "-0.25")] + row[8:]]))
# A float matrix written big-endian under a header claiming little-endian.
grid("byte_swapped_coefficients", header(1, 146, "float", 0).encode() + struct.pack(">438f", *([0.0045] * 438)))
# The 7 KB matrix claiming 4.9 million rows as the coefficients of a grid (the old reader
# allocated 8.4 GB before it said "truncated").
grid("claims_4900000_rows", open("sky_claims_4900000_rows.mtx", "rb").read())
