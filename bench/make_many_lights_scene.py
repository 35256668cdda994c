#!/usr/bin/env python3
"""Writes the many-lights scene (issue 17): a room lit by 11,200 small emissive triangles.

    bench/make_many_lights_scene.py OUT.json [--side N] [--length L]

A L x 10 x 4 room (L = 10 by default; a long hall with L = 40): the ceiling holds a grid of
N x N triangles facing down (N = 80 by default, stretched along x) and each wall a band of
triangles facing in; their emission spans three decades, a few bright
and most dim (eight materials, assigned by a fixed pseudo-random draw, so the file is the same
on every run). Under them a diffuse floor, a rough metal sphere and block, and a diffuse
sphere. Selection by area spends most light samples on the dim emitters and on the far ones;
by power, on the bright ones wherever they are; the light tree, on those bright and near.
"""
import argparse
import json
import random

# (emission, share of the triangles): most dim, a few bright
EMISSIONS = [([0.3, 0.3, 0.35], 0.40), ([0.8, 0.7, 0.6], 0.25), ([1.5, 1.5, 1.8], 0.15), ([3.0, 2.5, 2.0], 0.10),
             ([8.0, 8.0, 10.0], 0.05), ([20.0, 16.0, 12.0], 0.03), ([60.0, 60.0, 60.0], 0.015), ([200.0, 150.0, 100.0], 0.005)]


def pick_emission(rng):
    u = rng.random()
    for k, (_, share) in enumerate(EMISSIONS):
        if u < share:
            return k
        u -= share
    return len(EMISSIONS) - 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--side", type=int, default=80, help="ceiling triangles per side (the walls get side x 15 / 20 each)")
    parser.add_argument("--length", type=float, default=10.0, help="the room's extent along x (its width along y is 10)")
    args = parser.parse_args()
    rng = random.Random(17)
    meshes = [{"vertices": [], "triangles": []} for _ in EMISSIONS]

    def triangle(k, a, b, c):
        m = meshes[k]
        base = len(m["vertices"])
        m["vertices"] += [a, b, c]
        m["triangles"].append([base, base + 1, base + 2])

    n = args.side
    hx = 0.5 * args.length  # the room spans [-hx, hx] along x, [-5, 5] along y
    cell_x, cell = (args.length - 1.0) / n, 9.0 / n
    for j in range(n):  # the ceiling, facing down: cross(b - a, c - a) points to -z
        for i in range(n):
            x, y = -(hx - 0.5) + (i + 0.5) * cell_x, -4.5 + (j + 0.5) * cell
            triangle(pick_emission(rng), [x, y, 3.95], [x, y + 0.4 * cell, 3.95], [x + 0.4 * cell_x, y, 3.95])
    columns, rows = n * 3 // 4, n // 4
    for wall in range(4):  # a band on each wall, 1.5 to 3.5 high, facing into the room
        for j in range(rows):
            for i in range(columns):
                z, h = 1.5 + (j + 0.5) * 2.0 / rows, 0.4 * 9.0 / columns
                if wall < 2:  # the walls across x: their bands run along y
                    s = -4.5 + (i + 0.5) * 9.0 / columns
                else:  # along x
                    s, h = -(hx - 0.5) + (i + 0.5) * (args.length - 1.0) / columns, 0.4 * (args.length - 1.0) / columns
                if wall == 0:
                    a, b, c = [-(hx - 0.05), s, z], [-(hx - 0.05), s + h, z], [-(hx - 0.05), s, z + h]
                elif wall == 1:
                    a, b, c = [hx - 0.05, s, z], [hx - 0.05, s, z + h], [hx - 0.05, s + h, z]
                elif wall == 2:
                    a, b, c = [s, -4.95, z], [s, -4.95, z + h], [s + h, -4.95, z]
                else:
                    a, b, c = [s, 4.95, z], [s + h, 4.95, z], [s, 4.95, z + h]
                triangle(pick_emission(rng), a, b, c)

    materials = {
        "wall": {"type": "lambertian", "albedo": [0.7, 0.7, 0.7]},
        "floor": {"type": "lambertian", "albedo": [0.6, 0.5, 0.4]},
        "metal": {"type": "conductor", "roughness": 0.3, "f0": [0.95, 0.8, 0.55]},
        "blue": {"type": "lambertian", "albedo": [0.2, 0.3, 0.7]},
    }
    for k, (emission, _) in enumerate(EMISSIONS):
        materials["lamp%d" % k] = {"type": "lambertian", "albedo": [0, 0, 0], "emission": emission}

    def quad(material, *v):
        return {"type": "quad", "material": material, "vertices": list(v)}

    shapes = [
        quad("floor", [-hx, -5, 0], [hx, -5, 0], [hx, 5, 0], [-hx, 5, 0]),
        quad("wall", [-hx, -5, 4], [-hx, 5, 4], [hx, 5, 4], [hx, -5, 4]),
        quad("wall", [-hx, -5, 0], [-hx, 5, 0], [-hx, 5, 4], [-hx, -5, 4]),
        quad("wall", [hx, -5, 0], [hx, -5, 4], [hx, 5, 4], [hx, 5, 0]),
        quad("wall", [-hx, -5, 0], [-hx, -5, 4], [hx, -5, 4], [hx, -5, 0]),
        quad("wall", [-hx, 5, 0], [hx, 5, 0], [hx, 5, 4], [-hx, 5, 4]),
        quad("metal", [0.5, 0.5, 1.2], [2.5, 0.5, 1.2], [2.5, 2.5, 1.2], [0.5, 2.5, 1.2]),
        quad("metal", [0.5, 0.5, 0], [2.5, 0.5, 0], [2.5, 0.5, 1.2], [0.5, 0.5, 1.2]),
        quad("metal", [0.5, 0.5, 0], [0.5, 0.5, 1.2], [0.5, 2.5, 1.2], [0.5, 2.5, 0]),
        {"type": "sphere", "material": "metal", "center": [-1.5, 1.0, 1.0], "radius": 1.0},
        {"type": "sphere", "material": "blue", "center": [1.0, -1.8, 0.7], "radius": 0.7},
    ]
    for k, m in enumerate(meshes):
        if not m["triangles"]:
            continue  # a small --side may leave an emission unused
        shapes.append({"type": "mesh", "material": "lamp%d" % k, "vertices": m["vertices"], "triangles": m["triangles"]})
    scene = {
        # Looking down at the floor and the objects, below the walls' bands: what the image shows
        # is the light the selection finds, not the emitters' own edges.
        "camera": {"eye": [-3.5, -3.5, 3.0], "look_at": [0.6, 0.6, -1.4], "up": [0, 0, 1], "fov_degrees": 50},
        "render": {"width": 160, "height": 120, "spp": 16, "shadow_rays": 1, "seed": 0, "max_bounces": 8,
                   "rr_start_bounce": 3, "light_sampling": "mis"},
        "materials": materials,
        "shapes": shapes,
    }
    with open(args.out, "w") as f:
        json.dump(scene, f, separators=(",", ":"))
    print("%s: %d emissive triangles" % (args.out, sum(len(m["triangles"]) for m in meshes)))


if __name__ == "__main__":
    main()
