#!/usr/bin/python3
"""Writes the materials scene: the hexroom with a glTF file of rough metals, plastics and a
textured panel, to compare wavetrace's materials with another renderer's through its glTF
importer (README, "Multiple scattering in rough metals").

Usage: tools/make_materials_scene.py OUTDIR
Writes OUTDIR/materials.glb (five spheres of 96 x 48 quads with vertex normals on the hexroom's
floor: gold roughness 0.3, copper 0.7 and a white-ish metal 1.0, a red plastic 0.4 and a white
plastic 0.8, glTF metallic-roughness materials; a ceiling panel with a checkerboard
baseColorTexture) and OUTDIR/hexroom_materials.json (scenes/hexroom.json with that file added,
its Y-up turned to the hexroom's Z-up as Blender's importer turns it). Python's standard library
only. Node and mesh names are the objects' names (gold, copper, silver, red_plastic,
white_plastic, panel), which an importer keeps.
"""
import json
import math
import os
import struct
import sys
import zlib

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def png(width, height, pixel):
    """An 8-bit RGB PNG, uncompressed rows deflated, from pixel(x, y) -> (r, g, b)."""
    rows = b"".join(b"\x00" + b"".join(bytes(pixel(x, y)) for x in range(width)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")


def y_up(p):
    """Hexroom coordinates (Z up) as glTF writes them (Y up): (X, Y, Z) -> (X, Z, -Y), a rotation."""
    return (p[0], p[2], -p[1])


def sphere(center, radius, segments=96, rings=48):
    """Positions, normals, no texture coordinates, and triangles wound outwards."""
    positions, normals, triangles = [], [], []
    for j in range(rings + 1):
        theta = math.pi * j / rings
        for i in range(segments + 1):
            phi = 2 * math.pi * i / segments
            n = (math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta))
            positions.append(y_up(tuple(center[k] + radius * n[k] for k in range(3))))
            normals.append(y_up(n))
    for j in range(rings):
        for i in range(segments):
            a = j * (segments + 1) + i
            b, c = a + 1, a + segments + 1
            if j > 0:
                triangles += [a, c, b]
            if j < rings - 1:
                triangles += [b, c, c + 1]
    return positions, normals, None, triangles


def ceiling_panel(x0, x1, y0, y1, z):
    """A horizontal quad facing down, the texture's (0, 0) at (x0, y0)."""
    corners = [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)]
    return [y_up(p) for p in corners], [y_up((0, 0, -1))] * 4, [(0, 0), (1, 0), (1, 1), (0, 1)], [0, 2, 1, 0, 3, 2]


def metal(color, roughness):
    return {"baseColorFactor": list(color) + [1.0], "metallicFactor": 1.0, "roughnessFactor": roughness}


def plastic(color, roughness):
    return {"baseColorFactor": list(color) + [1.0], "metallicFactor": 0.0, "roughnessFactor": roughness}


OBJECTS = [
    ("gold", sphere((4.3, -3.0, -4.4), 0.6), metal((1.0, 0.766, 0.336), 0.3)),
    ("copper", sphere((4.3, -1.5, -4.4), 0.6), metal((0.955, 0.637, 0.538), 0.7)),
    ("silver", sphere((4.3, 0.0, -4.4), 0.6), metal((0.97, 0.96, 0.91), 1.0)),
    ("red_plastic", sphere((4.3, 1.5, -4.4), 0.6), plastic((0.8, 0.1, 0.1), 0.4)),
    ("white_plastic", sphere((4.3, 3.0, -4.4), 0.6), plastic((0.8, 0.8, 0.8), 0.8)),
    ("panel", ceiling_panel(7.0, 9.5, -2.5, 2.5, 4.98),
     {"baseColorTexture": {"index": 0}, "metallicFactor": 0.0, "roughnessFactor": 1.0}),
]


class Buffer:
    """The .glb's one binary buffer and the views and accessors into it."""

    def __init__(self):
        self.data, self.views, self.accessors = bytearray(), [], []

    def view(self, data, target=None):
        while len(self.data) % 4:
            self.data.append(0)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.data.extend(data)
        self.views.append(view)
        return len(self.views) - 1

    def accessor(self, values, kind, fmt, component, target, bounds=False):
        view = self.view(b"".join(struct.pack("<" + fmt, *(v if isinstance(v, tuple) else (v,))) for v in values), target)
        accessor = {"bufferView": view, "componentType": component, "count": len(values), "type": kind}
        if bounds:
            accessor["min"] = [min(v[k] for v in values) for k in range(3)]
            accessor["max"] = [max(v[k] for v in values) for k in range(3)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1


def glb():
    buffer = Buffer()
    meshes, nodes, materials = [], [], []
    for name, (positions, normals, uvs, triangles), material in OBJECTS:
        attributes = {"POSITION": buffer.accessor(positions, "VEC3", "3f", 5126, 34962, bounds=True),
                      "NORMAL": buffer.accessor(normals, "VEC3", "3f", 5126, 34962)}
        if uvs:
            attributes["TEXCOORD_0"] = buffer.accessor(uvs, "VEC2", "2f", 5126, 34962)
        indices = buffer.accessor(triangles, "SCALAR", "I", 5125, 34963)
        materials.append({"name": name, "pbrMetallicRoughness": material})
        meshes.append({"name": name, "primitives": [{"attributes": attributes, "indices": indices, "material": len(materials) - 1}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})
    checker = png(64, 64, lambda x, y: (230, 230, 230) if (x // 8 + y // 8) % 2 else (40, 90, 200))
    image_view = buffer.view(checker)
    while len(buffer.data) % 4:
        buffer.data.append(0)
    document = {
        "asset": {"version": "2.0", "generator": "wavetrace tools/make_materials_scene.py"},
        "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes, "meshes": meshes,
        "materials": materials, "accessors": buffer.accessors, "bufferViews": buffer.views,
        "buffers": [{"byteLength": len(buffer.data)}],
        "images": [{"bufferView": image_view, "mimeType": "image/png"}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "textures": [{"source": 0, "sampler": 0}],
    }
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    total = 12 + 8 + len(text) + 8 + len(buffer.data)
    return (struct.pack("<III", 0x46546C67, 2, total) + struct.pack("<II", len(text), 0x4E4F534A) + text +
            struct.pack("<II", len(buffer.data), 0x004E4942) + bytes(buffer.data))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[3])
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "materials.glb"), "wb") as f:
        f.write(glb())
    with open(os.path.join(REPO, "scenes", "hexroom.json")) as f:
        scene = json.load(f)
    scene["shapes"].append({"type": "mesh_file", "file": "materials.glb", "material": "from_file",
                            "transform": {"rotate": {"axis": [1, 0, 0], "degrees": 90}}})
    with open(os.path.join(out, "hexroom_materials.json"), "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")
    print("wrote", os.path.join(out, "materials.glb"), "and", os.path.join(out, "hexroom_materials.json"))


if __name__ == "__main__":
    main()
