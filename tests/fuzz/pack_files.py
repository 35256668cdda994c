#!/usr/bin/env python3
"""Packs a mesh file and the files it names into one fuzz input (tests/fuzz/fuzz_files.h).

Usage: pack_files.py OUTPUT MAIN [SIDE...]

MAIN's bytes come first; each SIDE follows after a line "@file NAME", NAME being its base name,
which is the name MAIN refers to it by (the fuzz target writes it beside the main file). Fails if
a name is not one the target accepts, or if a file's bytes hold the separator, since the target
would then cut the file there.
"""
import os
import re
import sys

SEPARATOR = b"\n@file "
NAME = re.compile(r"[A-Za-z0-9_-][A-Za-z0-9._-]{0,63}\Z")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    output, main_path, sides = sys.argv[1], sys.argv[2], sys.argv[3:]
    if len(sides) > 8:
        sys.exit("pack_files: at most 8 side files")
    with open(main_path, "rb") as f:
        packed = f.read()
    if SEPARATOR in packed:
        sys.exit(f"pack_files: {main_path} holds the separator")
    for side in sides:
        name = os.path.basename(side)
        if not NAME.match(name):
            sys.exit(f"pack_files: {name}: not a side file name the fuzz target accepts")
        with open(side, "rb") as f:
            data = f.read()
        if SEPARATOR in data:
            sys.exit(f"pack_files: {side} holds the separator")
        packed += SEPARATOR + name.encode() + b"\n" + data
    with open(output, "wb") as f:
        f.write(packed)


if __name__ == "__main__":
    main()
