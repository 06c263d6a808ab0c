#!/usr/bin/env python3
"""Thousands of specimens, past one machine: a parameter sweep of a preset rendered with Dask.

Each specimen is a seed and an angle of a stochastic preset; each worker renders its PNG
headless (OSMesa) and measures the plant. The results are the PNGs and a CSV of the parameters
and the plant's statistics (modules, segments, leaves, height, spread).

    PYTHONPATH=build/python python3 examples/sweep.py --count 200 --workers 2 --out sweep
    PYTHONPATH=build/python python3 examples/sweep.py --scheduler tcp://10.0.0.5:8786 ...

With no --scheduler it starts a local cluster of --workers processes (one thread each: a
render holds its worker's core); given a scheduler's address, the same script runs unchanged
on that cluster (its workers need Sprout's module on their Python path, and --out a folder
they all see).
"""
import argparse
import csv
import os
import re
import time


def specimen(preset, seed, angle, out_dir, size):
    """Renders one specimen and measures it (runs on a worker)."""
    import numpy as np

    import sprout

    text = sprout.open(preset).text
    text = re.sub(r"(?m)^angle:.*$", "angle: %g" % angle, text)
    plant = sprout.parse(text)
    name = "%s_seed%d_angle%g.png" % (preset, seed, angle)
    plant.render(width=size, height=size, seed=seed, path=os.path.join(out_dir, name))
    g = plant.geometry(seed=seed)
    s = plant.derive(seed=seed)
    lo, hi = np.array(g["bounds"][0]), np.array(g["bounds"][1])
    return {
        "file": name, "preset": preset, "seed": seed, "angle": angle, "n": plant.n,
        "modules": len(s), "segments": len(g["segments"]), "leaves": len(g["leaves"]) + len(g["triangles"]),
        "height": round(float(hi[1] - lo[1]), 4), "spread": round(float(max(hi[0] - lo[0], hi[2] - lo[2])), 4),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--preset", default="stochastic_flower_plant")
    ap.add_argument("--count", type=int, default=100, help="specimens (seeds x angles)")
    ap.add_argument("--angles", default="14,18,22,26", help="angle values, comma-separated")
    ap.add_argument("--size", type=int, default=256, help="picture size in pixels")
    ap.add_argument("--workers", type=int, default=2, help="local cluster's worker processes")
    ap.add_argument("--scheduler", help="a Dask scheduler's address (default: a local cluster)")
    ap.add_argument("--out", default="sweep")
    a = ap.parse_args()

    from dask.distributed import Client, LocalCluster

    os.makedirs(a.out, exist_ok=True)
    angles = [float(x) for x in a.angles.split(",")]
    jobs = [(seed, angles[seed % len(angles)]) for seed in range(1, a.count + 1)]
    if a.scheduler:
        client = Client(a.scheduler)
    else:
        client = Client(LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True, dashboard_address=None))
    with client:
        # One warm-up task a worker (Python, the module and OSMesa load once), then the clock.
        client.gather(client.map(specimen, [a.preset] * a.workers, range(a.workers), [angles[0]] * a.workers,
                                 [a.out] * a.workers, [16] * a.workers, pure=False))
        t0 = time.perf_counter()
        futures = client.map(specimen, [a.preset] * len(jobs), [s for s, _ in jobs], [x for _, x in jobs],
                             [a.out] * len(jobs), [a.size] * len(jobs), pure=False)
        rows = client.gather(futures)
        seconds = time.perf_counter() - t0
    rows.sort(key=lambda r: r["seed"])
    with open(os.path.join(a.out, "specimens.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    where = a.scheduler or "a local cluster of %d worker%s" % (a.workers, "s" if a.workers > 1 else "")
    print("%d specimens of %s in %.1f s on %s: %.2f specimens/s" % (len(rows), a.preset, seconds, where, len(rows) / seconds))


if __name__ == "__main__":
    main()
