"""The `mocap` module against the `mocap` command line on the same files, in the same run.

    PYTHONPATH=build/python python3 python/bench/module_bench.py build/bin/mocap

1. Reading a 60-marker × 20 000-frame float C3D (~19 MB, the take of bench/c3d_read_bench.cpp's
   shape): mocap.read (and .positions) against `mocap info` of the same file. Target: ≤ 1.5×.
2. Cleaning 60 markers × 10 000 frames with the default pipeline: mocap.read + mocap.clean +
   Take.write against `mocap clean IN -o OUT` (the same work, and the same read and write).
   Target: ≤ 1.2×: no per-sample work happens in Python.
Best of five runs each; prints one line per measure.
"""

import os
import subprocess
import sys
import tempfile
import time

import numpy as np

import mocap


def synthetic_take(markers, frames, seed):
    rng = np.random.default_rng(seed)
    t = np.arange(frames) / 120.0
    xyz = np.empty((frames, markers, 3))
    for m in range(markers):
        xyz[:, m, 0] = 100.0 * np.sin(t + m) + rng.uniform(-0.2, 0.2, frames)
        xyz[:, m, 1] = 5.0 * m
        xyz[:, m, 2] = 1000.0 + 10.0 * np.cos(t)
        occluded = ((np.arange(frames) // 50 + m) % 23) == 0
        xyz[occluded, m, :] = np.nan
    spikes = rng.integers(0, frames, 40)
    xyz[spikes, spikes % markers, 0] += 25.0  # impulsive noise for the spike step
    take = mocap.Take(["face%d" % m for m in range(markers)], frames, 120.0)
    take.positions = xyz
    return take


def best_of(runs, work):
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return min(times)


def main(cli):
    with tempfile.TemporaryDirectory() as folder:
        large = os.path.join(folder, "large.c3d")
        synthetic_take(60, 20000, 7).write(large)
        python = best_of(5, lambda: mocap.read(large).positions)
        command = best_of(5, lambda: subprocess.run([cli, "info", large], check=True, capture_output=True))
        print("read %.1f MB: mocap.read %.3f s, mocap info %.3f s, ratio %.2f (target <= 1.5)"
              % (os.path.getsize(large) / 1e6, python, command, python / command))

        source = os.path.join(folder, "clean_in.c3d")
        synthetic_take(60, 10000, 11).write(source)
        out_python, out_cli = os.path.join(folder, "py.c3d"), os.path.join(folder, "cli.c3d")

        def clean_in_python():
            take = mocap.read(source)
            mocap.clean(take)
            take.write(out_python)

        python = best_of(5, clean_in_python)
        command = best_of(5, lambda: subprocess.run([cli, "clean", source, "-o", out_cli], check=True,
                                                    capture_output=True))
        same = np.array_equal(mocap.read(out_python).states, mocap.read(out_cli).states)
        print("clean 60 x 10000: python %.3f s, mocap clean %.3f s, ratio %.2f (target <= 1.2), same states: %s"
              % (python, command, python / command, same))


main(sys.argv[1])
