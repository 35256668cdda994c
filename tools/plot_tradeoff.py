#!/usr/bin/python3
"""Plots `wavetrace tradeoff`'s CSVs: RMSE against render time, log-log, one line per
configuration, the Pareto front marked, and the fitted floor + v/t curve of every configuration
that can be biased, drawn past the measurements to show where it flattens.

Usage: tools/plot_tradeoff.py POINTS.csv FITS.csv OUT.png [--title TEXT]
Debian's python3-matplotlib (tools/install-deps.sh); /usr/bin/python3, where apt installs it.
"""
import argparse
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")  # no display: write the file only
import matplotlib.pyplot as plt  # noqa: E402


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("points")
    parser.add_argument("fits")
    parser.add_argument("out")
    parser.add_argument("--title", default="")
    args = parser.parse_args()
    try:
        points, fits = read_rows(args.points), read_rows(args.fits)
    except (OSError, csv.Error) as e:
        print(f"plot_tradeoff: {e}", file=sys.stderr)
        return 1

    configurations = list(dict.fromkeys(p["configuration"] for p in points))
    colours = plt.get_cmap("tab20")
    fig, ax = plt.subplots(figsize=(10, 6.5))
    t_max = max(float(p["seconds"]) for p in points)
    for i, name in enumerate(configurations):
        own = sorted((p for p in points if p["configuration"] == name), key=lambda p: int(p["spp"]))
        t = [float(p["seconds"]) for p in own]
        rmse = [float(p["rmse"]) for p in own]
        base = name == "base"
        colour = "black" if base else colours(i % 20)
        ax.plot(t, rmse, marker="o", markersize=3.5, linewidth=2.2 if base else 1.0, color=colour, label=name)
        fit = next((f for f in fits if f["configuration"] == name), None)
        if fit and fit["can_bias"] == "1" and float(fit["floor_mse"]) > 0.0:
            # MSE = floor + variance / spp, and spp = t / seconds_per_spp
            floor, v = float(fit["floor_mse"]), float(fit["variance"]) * float(fit["seconds_per_spp"])
            ts = [t[0] * (10 * t_max / t[0]) ** (k / 40) for k in range(41)]
            ax.plot(ts, [math.sqrt(floor + v / x) for x in ts], linestyle=":", linewidth=1.0, color=colour)

    front = sorted((p for p in points if p["pareto"] == "1"), key=lambda p: float(p["seconds"]))
    ax.step([float(p["seconds"]) for p in front], [float(p["rmse"]) for p in front], where="post",
            color="grey", linewidth=5, alpha=0.35, zorder=0, label="Pareto front")
    ax.scatter([float(p["seconds"]) for p in front], [float(p["rmse"]) for p in front], s=70,
               facecolors="none", edgecolors="red", linewidths=1.2, zorder=5, label="on the front")
    target = float(fits[0]["target_rmse"]) if fits else None
    if target:
        ax.axhline(target, color="red", linestyle="--", linewidth=0.8)
        ax.annotate(f"target RMSE {target:g}", (ax.get_xlim()[0], target), xytext=(4, 3),
                    textcoords="offset points", fontsize=8, color="red")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("render time (s, median of repeats)")
    ax.set_ylabel("RMSE against the reference")
    ax.set_title(args.title)
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
