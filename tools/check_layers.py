#!/usr/bin/env python3
"""Checks that no #include between the source folders runs back up the data flow.

Usage: check_layers.py [--root DIR] [--list]

The folders of src/ and tools/ are stacked in LAYERS, bottom first, in the order the data flows
(scene file -> import -> scene -> accel -> stages -> film -> image, with the basics every room
shares at the bottom). A file may include files of its own folder and of folders below it; an
include of a folder above it, of a folder LAYERS does not name, or of a quoted name that is no
file in the tree is reported as FILE:LINE and the exit status is 1. A new folder gets its place
in LAYERS by hand: where it goes is the design decision this check keeps written down.

--list prints every folder-to-folder edge (with how many includes make it) instead of only the
violations. Includes resolve as the build resolves them: beside the including file, then under
src/ (the library's include root), then under the repository root (tools/ includes "tools/...").
"""
import argparse
import collections
import os
import re
import sys

# Bottom first. One line per room: what it holds, so the stack reads as the design.
LAYERS = [
    ("src/simd", "vfloat<N>, masks, per-ISA lanes"),
    ("src/core/base", "rays, float helpers, enum names, aligned vectors"),
    ("src/core/system", "files written atomically, memory, the thread pool, version"),
    ("src/core/image_io", "the image module's interface (OpenImageIO behind a plug-in)"),
    ("src/core/textures", "texture images, mip levels, lookups"),
    ("src/core/description", "the scene description: plain settings structs, scene hash"),
    ("src/core/sampling", "random numbers (Sobol', the counter RNG), warps from the square"),
    ("src/core/geometry", "triangle and sphere SoA, shading normals"),
    ("src/core/materials", "BSDFs"),
    ("src/core/lights", "emitters, the light table, punctual and environment lights"),
    ("src/core/camera", "cameras and pixel filters"),
    ("src/core/instances", "meshes stored once, placed by transforms"),
    ("src/core/scene", "the scene the kernels read: geometry, materials, lights, camera"),
    ("src/core/path", "one path vertex: the estimator every integrator runs"),
    ("src/core/film", "the exact fixed-point film, AOVs, image output"),
    ("src/core/checkpoint", "checkpoints: write, read, merge"),
    ("src/core/image_metrics", "error metrics between images"),
    ("src/core/import", "mesh files: OBJ, PLY, glTF"),
    ("src/core/scene_file", "the JSON scene file"),
    ("src/image_io_module", "the OpenImageIO plug-in"),
    ("src/kernels/work", "tiles, sample ranges, render statistics"),
    ("src/kernels/primitives", "SIMD triangle and sphere tests, SoA views"),
    ("src/kernels/accel", "BVH build and traversal, instance BVH"),
    ("src/kernels/queues", "SoA ray and hit queues"),
    ("src/kernels/shading", "SIMD shade kernels, generic over the width"),
    ("src/kernels/isa", "per-ISA instantiations and dispatch"),
    ("src/kernels/photons", "photon maps"),
    ("src/kernels/wavefront", "the wavefront stages: generate, intersect, shade, shadow"),
    ("src/kernels/caustics", "the light-tracing and photon passes for caustics"),
    ("src/kernels/adaptive", "adaptive sampling"),
    ("src/kernels", "the renderer: sessions, passes, memory estimate, reference integrator"),
    ("tools/cli", "command-line values and error reports"),
    ("tools/compare", "wavetrace compare"),
    ("tools/render", "wavetrace render (and its MPI split)"),
    ("tools/merge", "wavetrace merge"),
    ("tools/tradeoff", "wavetrace tradeoff"),
    ("tools", "the wavetrace executable"),
]

SOURCE_SUFFIXES = (".h", ".cpp", ".inc")
INCLUDE = re.compile(r'\s*#\s*include\s*"([^"]+)"')


def source_files(root):
    files = set()
    for top in ("src", "tools"):
        for folder, _, names in os.walk(os.path.join(root, top)):
            for name in names:
                if name.endswith(SOURCE_SUFFIXES):
                    files.add(os.path.relpath(os.path.join(folder, name), root))
    return files


def resolve(included, including, files):
    for candidate in (os.path.join(os.path.dirname(including), included),
                      os.path.join("src", included), included):
        candidate = os.path.normpath(candidate)
        if candidate in files:
            return candidate
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.join(os.path.dirname(__file__), ".."),
                        help="the repository to check (default: this one)")
    parser.add_argument("--list", action="store_true", help="print every folder-to-folder edge")
    args = parser.parse_args()

    rank = {folder: i for i, (folder, _) in enumerate(LAYERS)}
    files = source_files(args.root)
    if not files:
        print(f"check_layers: no sources under {args.root}/src or {args.root}/tools", file=sys.stderr)
        return 1
    problems = []
    edges = collections.Counter()
    for path in sorted(files):
        folder = os.path.dirname(path)
        if folder not in rank:
            problems.append(f"{path}: its folder {folder} has no place in LAYERS (tools/check_layers.py)")
            continue
        with open(os.path.join(args.root, path), errors="replace") as source:
            for line_number, line in enumerate(source, 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                target = resolve(match.group(1), path, files)
                where = f"{path}:{line_number}"
                if target is None:
                    problems.append(f'{where}: "{match.group(1)}" is no file under src/ or the repository')
                    continue
                to = os.path.dirname(target)
                if to == folder:
                    continue
                edges[(folder, to)] += 1
                if to not in rank:
                    continue  # reported once, as its own files are read
                if rank[to] > rank[folder]:
                    problems.append(f"{where}: includes {target}, but {to} is above {folder} "
                                    "in the layers (tools/check_layers.py LAYERS)")

    if args.list:
        for folder, purpose in LAYERS:
            below = sorted((to for (frm, to) in edges if frm == folder), key=lambda f: rank.get(f, -1))
            if below or any(frm == folder for (frm, _) in edges) or any(to == folder for (_, to) in edges):
                print(f"{folder}  ({purpose})")
                for to in below:
                    print(f"    -> {to}  [{edges[(folder, to)]}]")
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        print(f"check_layers: {len(problems)} include(s) out of order", file=sys.stderr)
        return 1
    print(f"check_layers: {len(files)} files, {len(edges)} folder edges, none runs back up")
    return 0


if __name__ == "__main__":
    sys.exit(main())
